// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassAssertionAxiom;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDifferentIndividualsAxiom;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLNaryPropertyAxiom;
import org.semanticweb.owlapi.model.OWLNegativeObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLObjectPropertyExpression;
import org.semanticweb.owlapi.model.OWLPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLSameIndividualAxiom;
import org.semanticweb.owlapi.model.OWLSubObjectPropertyOfAxiom;
import org.semanticweb.owlapi.model.OWLSubPropertyChainOfAxiom;

/**
 * Which ABox assertions tie individuals together under a given schema: the basis of reasoning on
 * a part of the ABox only.
 *
 * <p>An object property assertion P(a, b) carries information from one individual to the other
 * only when P (or a property it implies, or one implied by it) appears inside a class expression,
 * in a chain, or with a characteristic that compares several edges (functional, inverse
 * functional, transitive, asymmetric, irreflexive, disjoint properties). Such a property
 * <em>links</em>; its assertions, and sameness, difference and negative property assertions,
 * join their individuals into one module. For any other property, P(a, b) only gives a the
 * domain of P and b its range, which a module keeps exactly by asserting a : ∃P.⊤ and
 * b : ∃P⁻.⊤ (the property's domain, range, symmetry and reflexivity then act on those).
 *
 * <p>With that, the ontology is consistent exactly when its schema and every module are, and
 * an individual has exactly the types it has in its module: a model of the whole is the
 * disjoint union of the modules' models with the split edges added back, and an added edge of a
 * property that no class expression mentions changes the extension of no class.
 *
 * <p>The argument needs the schema to mention no individual (nominals, ObjectHasValue) and no
 * universal property (every individual is then related to every other), and no SWRL rules or
 * keys (they relate individuals outside property assertions). When one of them is present
 * {@link #obstacle()} says which, and the ontology is reasoned on as a whole.
 */
final class AboxLinks {
    private final Set<OWLObjectProperty> linking;
    private final String obstacle;

    private AboxLinks(Set<OWLObjectProperty> linking, String obstacle) {
        this.linking = Set.copyOf(linking);
        this.obstacle = obstacle;
    }

    /** The links of the ontology whose logical axioms (imports included) are {@code axioms}. */
    static AboxLinks of(Stream<OWLAxiom> axioms) {
        Set<OWLObjectProperty> linking = new HashSet<>();
        List<OWLAxiom> hierarchy = new java.util.ArrayList<>();
        String[] obstacle = {null};
        axioms.forEach(axiom -> {
            String found = inspect(axiom, linking, hierarchy);
            if (found != null && obstacle[0] == null) {
                obstacle[0] = found;
            }
        });
        closeUnderHierarchy(linking, hierarchy);
        return new AboxLinks(linking, obstacle[0]);
    }

    /** Why the ABox cannot be split into modules, if it cannot. */
    Optional<String> obstacle() {
        return Optional.ofNullable(obstacle);
    }

    boolean links(OWLObjectPropertyExpression property) {
        return linking.contains(property.getNamedProperty());
    }

    /** Whether an ABox axiom ties its individuals into one module. */
    boolean ties(OWLAxiom axiom) {
        if (axiom instanceof OWLObjectPropertyAssertionAxiom assertion) {
            return links(assertion.getProperty());
        }
        return axiom instanceof OWLSameIndividualAxiom || axiom instanceof OWLDifferentIndividualsAxiom
                || axiom instanceof OWLNegativeObjectPropertyAssertionAxiom;
    }

    /** Whether an ABox axiom can change what links (a class assertion on a class expression, a negative assertion). */
    static boolean shapesLinks(OWLAxiom axiom) {
        return axiom instanceof OWLClassAssertionAxiom assertion && assertion.getClassExpression().isAnonymous()
                || axiom instanceof OWLNegativeObjectPropertyAssertionAxiom;
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof AboxLinks that && linking.equals(that.linking)
                && java.util.Objects.equals(obstacle, that.obstacle);
    }

    @Override
    public int hashCode() {
        return linking.hashCode();
    }

    /** Adds what one axiom makes linking; answers an obstacle to splitting, or null. */
    private static String inspect(OWLAxiom axiom, Set<OWLObjectProperty> linking, List<OWLAxiom> hierarchy) {
        if (axiom.isOfType(AxiomType.ABoxAxiomTypes)) {
            if (axiom instanceof OWLClassAssertionAxiom assertion && assertion.getClassExpression().isAnonymous()) {
                return inspectExpression(assertion.getClassExpression(), linking);
            }
            if (axiom instanceof OWLNegativeObjectPropertyAssertionAxiom negative) {
                linking.add(negative.getProperty().getNamedProperty());
            }
            return null;
        }
        if (axiom.isOfType(AxiomType.SWRL_RULE)) {
            return "SWRL rules";
        }
        if (axiom.isOfType(AxiomType.HAS_KEY)) {
            return "keys (HasKey)";
        }
        if (axiom.individualsInSignature().findAny().isPresent()
                || axiom.anonymousIndividuals().findAny().isPresent()) {
            return "individuals named in the schema (nominals)";
        }
        if (axiom.objectPropertiesInSignature().anyMatch(OWLObjectProperty::isOWLTopObjectProperty)) {
            return "the universal object property";
        }
        axiom.nestedClassExpressions().forEach(expression -> inspectExpression(expression, linking));
        if (axiom instanceof OWLSubObjectPropertyOfAxiom || axiom.isOfType(AxiomType.EQUIVALENT_OBJECT_PROPERTIES,
                AxiomType.INVERSE_OBJECT_PROPERTIES)) {
            hierarchy.add(axiom);
        } else if (axiom instanceof OWLSubPropertyChainOfAxiom
                || axiom.isOfType(AxiomType.FUNCTIONAL_OBJECT_PROPERTY, AxiomType.INVERSE_FUNCTIONAL_OBJECT_PROPERTY,
                AxiomType.TRANSITIVE_OBJECT_PROPERTY, AxiomType.ASYMMETRIC_OBJECT_PROPERTY,
                AxiomType.IRREFLEXIVE_OBJECT_PROPERTY, AxiomType.DISJOINT_OBJECT_PROPERTIES)) {
            axiom.objectPropertiesInSignature().forEach(linking::add);
        }
        // Domain, range, symmetry and reflexivity act on each edge alone: the split edge keeps them.
        return null;
    }

    private static String inspectExpression(OWLClassExpression expression, Set<OWLObjectProperty> linking) {
        if (expression.individualsInSignature().findAny().isPresent()
                || expression.anonymousIndividuals().findAny().isPresent()) {
            return "individuals named in a class expression (nominals)";
        }
        if (expression.objectPropertiesInSignature().anyMatch(OWLObjectProperty::isOWLTopObjectProperty)) {
            return "the universal object property";
        }
        expression.objectPropertiesInSignature().forEach(linking::add);
        return null;
    }

    /**
     * A property that implies a linking one links too (its edges are the linking one's edges);
     * equivalent and inverse properties are each other's sub-properties. Named properties stand
     * for their inverses here, which can only link more than needed, never less.
     */
    private static void closeUnderHierarchy(Set<OWLObjectProperty> linking, List<OWLAxiom> hierarchy) {
        boolean grew = true;
        while (grew) {
            grew = false;
            for (OWLAxiom axiom : hierarchy) {
                if (axiom instanceof OWLSubObjectPropertyOfAxiom sub) {
                    if (linking.contains(sub.getSuperProperty().getNamedProperty())) {
                        grew |= linking.add(sub.getSubProperty().getNamedProperty());
                    }
                } else if (axiom instanceof OWLNaryPropertyAxiom<?>
                        || axiom.isOfType(AxiomType.INVERSE_OBJECT_PROPERTIES)) {
                    List<OWLObjectProperty> members = axiom.objectPropertiesInSignature().toList();
                    if (members.stream().anyMatch(linking::contains)) {
                        for (OWLObjectProperty member : members) {
                            grew |= linking.add(member);
                        }
                    }
                }
            }
        }
    }

    /** The individuals an ABox axiom is about (read directly for the common kinds: this runs per edge). */
    static Stream<OWLIndividual> individualsOf(OWLAxiom axiom) {
        if (axiom instanceof OWLPropertyAssertionAxiom<?, ?> assertion) {
            return assertion.getObject() instanceof OWLIndividual object
                    ? Stream.of(assertion.getSubject(), object) : Stream.of(assertion.getSubject());
        }
        if (axiom instanceof OWLClassAssertionAxiom assertion && !assertion.getClassExpression().isAnonymous()) {
            return Stream.of(assertion.getIndividual());
        }
        return Stream.concat(axiom.individualsInSignature().map(OWLIndividual.class::cast),
                axiom.anonymousIndividuals().map(OWLIndividual.class::cast));
    }
}
