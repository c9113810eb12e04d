// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassAssertionAxiom;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDifferentIndividualsAxiom;
import org.semanticweb.owlapi.model.OWLHasKeyAxiom;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLNaryPropertyAxiom;
import org.semanticweb.owlapi.model.OWLNegativeObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLObjectPropertyDomainAxiom;
import org.semanticweb.owlapi.model.OWLObjectPropertyExpression;
import org.semanticweb.owlapi.model.OWLObjectPropertyRangeAxiom;
import org.semanticweb.owlapi.model.OWLPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLSameIndividualAxiom;
import org.semanticweb.owlapi.model.OWLSubObjectPropertyOfAxiom;
import org.semanticweb.owlapi.model.OWLSubPropertyChainOfAxiom;

/**
 * Which ABox assertions tie individuals together under a given schema: the basis of reasoning on
 * a part of the ABox only ({@link AboxModules}).
 *
 * <h2>What ties</h2>
 * A property P is <em>observed</em> when something can tell its edges apart from "this
 * individual has some P-edge": P occurs in a class expression (other than as the property of a
 * domain or range axiom), in a key, in a negative property assertion, or with a characteristic
 * that compares edges (functional, inverse functional, asymmetric, irreflexive, disjoint
 * properties). P is <em>seen</em> when it is observed or has a domain or range. A property
 * <em>links</em> when it or one of its super-properties (through sub-property, equivalence and
 * inverse axioms; a named property stands for its inverse, which can only link more) is
 * observed, or when it is a link of a chain whose super-property, or one above it, is seen or
 * links. Assertions of linking properties, sameness and negative property assertions tie their
 * individuals into one module; the individuals named in the schema (nominals) are tied into one
 * module too, the <em>hub</em>. Nothing else ties: a transitive part-of tree or a symmetric
 * adjacency that nothing observes, and DifferentIndividuals (each module keeps the pairs among
 * its own members).
 *
 * <h2>Why a module's answers are the whole ontology's</h2>
 * Each module is reasoned on with the whole schema and its own assertions, where an edge P(a, b)
 * of a property that does not link and leaves the module is replaced by what it says about this
 * end: a : ∃P.⊤ (or b : ∃P⁻.⊤). Everything a module's reasoner concludes follows from the whole
 * ontology (its assertions do), so only the converse needs an argument: a model of every module
 * gives a model of the whole ontology in which each individual has exactly the types it has in
 * its module's model. Take the disjoint union of the modules' models (individuals of different
 * modules are then different elements, which satisfies every DifferentIndividuals axiom across
 * modules) and add back each split edge P(a, b), closed under the super-properties, inverses,
 * symmetry, transitivity and chains of the properties that do not link (every property these
 * produce edges of does not link either, else P would):
 * <ul>
 * <li>class expressions, keys and edge-comparing characteristics mention only linking properties,
 *     whose edges are unchanged, so every element keeps its types and those axioms still hold;</li>
 * <li>a domain or range of a property that gets new edges holds: an edge added from a split edge,
 *     a super-property, an inverse, symmetry or transitivity starts at an element that already had
 *     an edge of that property in its module's model (the module asserts a : ∃P.⊤ and has the
 *     schema) and ends at one that already had an incoming one; only a chain can give an element
 *     an edge of a new property, and the links of a chain whose super-property is seen link;</li>
 * <li>sub-property, inverse, symmetry, transitivity and chain axioms hold by the closure.</li>
 * </ul>
 * So the ontology is consistent exactly when its schema and every module are, and each individual
 * has the types its module gives it.
 *
 * <h2>Nominals</h2>
 * With individuals named in the schema, each module's model has its own copy of them, and the
 * union needs one. The hub holds every nominal, so its model is a model of the whole schema for
 * its part. For the other modules, read each nominal of the schema as ⊥ (the nominals live in the
 * hub's part, so within another part they are empty): call that schema S'. The modules' assertions
 * use a signature Σ; if the ⊥-locality module of S' for Σ contains no axiom that had a nominal
 * ({@link NominalIndependence}), then every model of that locality module and a module's
 * assertions, with every other symbol empty, is a model of S' and of those assertions: a part of
 * the union as above. The module's reasoner reasons with the real schema, which is between the two
 * (it contains the locality module's axioms, and what it concludes the whole ontology does), so it
 * concludes exactly what the whole ontology does. An upper ontology that enumerates its own
 * individuals (SOMA's execution states) thus leaves an ABox that never uses those classes alone; a
 * hasValue class over an individual of the ABox ties only what is linked to that individual.
 *
 * <p>SWRL rules are not read here: {@link RuleProgram} evaluates them beside the modules, or
 * sends the ontology to a reasoner on the whole of it, saying why.
 *
 * <p>Not covered (the ontology is then reasoned on whole and {@link #obstacle()} says why): keys
 * over data properties, the universal property, anonymous individuals in the schema,
 * and nominals whose classes the ABox's signature reaches.
 */
final class AboxLinks {
    private final Set<OWLObjectProperty> linking;
    private final Set<OWLNamedIndividual> nominals;
    private final String obstacle;

    private AboxLinks(Set<OWLObjectProperty> linking, Set<OWLNamedIndividual> nominals, String obstacle) {
        this.linking = Set.copyOf(linking);
        this.nominals = Set.copyOf(nominals);
        this.obstacle = obstacle;
    }

    /** The links of the ontology whose logical axioms (imports included) are {@code axioms}. */
    static AboxLinks of(Stream<OWLAxiom> axioms) {
        Properties properties = new Properties();
        Set<OWLNamedIndividual> nominals = new LinkedHashSet<>();
        String[] obstacle = {null};
        axioms.forEach(axiom -> {
            String found = properties.inspect(axiom, nominals);
            if (found != null && obstacle[0] == null) {
                obstacle[0] = found;
            }
        });
        return new AboxLinks(properties.linking(), nominals, obstacle[0]);
    }

    /** Why the ABox cannot be split into modules, if it cannot. */
    Optional<String> obstacle() {
        return Optional.ofNullable(obstacle);
    }

    boolean links(OWLObjectPropertyExpression property) {
        return linking.contains(property.getNamedProperty());
    }

    /** The properties that link (for tests and the reasoning statement). */
    Set<OWLObjectProperty> linking() {
        return linking;
    }

    /** The individuals the schema names: they share one module, the hub. */
    Set<OWLNamedIndividual> nominals() {
        return nominals;
    }

    /** Whether an ABox axiom ties its individuals into one module. */
    boolean ties(OWLAxiom axiom) {
        if (axiom instanceof OWLObjectPropertyAssertionAxiom assertion) {
            return links(assertion.getProperty());
        }
        // A class assertion naming individuals ({a}, P value a) joins the hub, where those individuals are.
        return axiom instanceof OWLSameIndividualAxiom || axiom instanceof OWLNegativeObjectPropertyAssertionAxiom
                || axiom instanceof OWLClassAssertionAxiom assertion && assertion.getClassExpression().isAnonymous()
                && assertion.getClassExpression().individualsInSignature().findAny().isPresent();
    }

    /** Whether an ABox axiom can change what links (a class assertion on a class expression, a negative assertion). */
    static boolean shapesLinks(OWLAxiom axiom) {
        return axiom instanceof OWLClassAssertionAxiom assertion && assertion.getClassExpression().isAnonymous()
                || axiom instanceof OWLNegativeObjectPropertyAssertionAxiom;
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof AboxLinks that && linking.equals(that.linking) && nominals.equals(that.nominals)
                && Objects.equals(obstacle, that.obstacle);
    }

    @Override
    public int hashCode() {
        return linking.hashCode();
    }

    /** What the schema says about object properties, gathered axiom by axiom. */
    private static final class Properties {
        final Set<OWLObjectProperty> observed = new HashSet<>();
        final Set<OWLObjectProperty> seen = new HashSet<>();
        // Edges from a property to the properties its edges are also edges of (both ways for equivalence, inverse).
        final Map<OWLObjectProperty, Set<OWLObjectProperty>> supers = new HashMap<>();
        final List<OWLSubPropertyChainOfAxiom> chains = new ArrayList<>();

        /** Records what one axiom says; answers an obstacle to splitting, or null. */
        String inspect(OWLAxiom axiom, Set<OWLNamedIndividual> nominals) {
            if (axiom.isOfType(AxiomType.ABoxAxiomTypes)) {
                if (axiom instanceof OWLClassAssertionAxiom assertion && assertion.getClassExpression().isAnonymous()) {
                    return observe(assertion.getClassExpression(), nominals);
                }
                if (axiom instanceof OWLNegativeObjectPropertyAssertionAxiom negative) {
                    observed.add(negative.getProperty().getNamedProperty());
                }
                return null;
            }
            if (axiom.isOfType(AxiomType.SWRL_RULE)) {
                // Rules are evaluated beside the modules (RuleProgram says when they can be).
                return null;
            }
            if (axiom.anonymousIndividuals().findAny().isPresent()) {
                return "anonymous individuals in the schema";
            }
            if (axiom.objectPropertiesInSignature().anyMatch(OWLObjectProperty::isOWLTopObjectProperty)) {
                return "the universal object property";
            }
            axiom.individualsInSignature().forEach(nominals::add);
            if (axiom instanceof OWLHasKeyAxiom key) {
                if (key.dataPropertyExpressions().findAny().isPresent()) {
                    return "keys over data properties (HasKey)";
                }
                key.objectPropertyExpressions().forEach(p -> observed.add(p.getNamedProperty()));
            }
            if (axiom instanceof OWLObjectPropertyDomainAxiom domain) {
                seen.add(domain.getProperty().getNamedProperty());
                return observe(domain.getDomain(), nominals);
            }
            if (axiom instanceof OWLObjectPropertyRangeAxiom range) {
                seen.add(range.getProperty().getNamedProperty());
                return observe(range.getRange(), nominals);
            }
            axiom.nestedClassExpressions().forEach(expression -> observe(expression, nominals));
            if (axiom instanceof OWLSubObjectPropertyOfAxiom sub) {
                above(sub.getSubProperty(), sub.getSuperProperty());
            } else if (axiom instanceof OWLNaryPropertyAxiom<?> || axiom.isOfType(AxiomType.INVERSE_OBJECT_PROPERTIES)) {
                if (axiom.isOfType(AxiomType.DISJOINT_OBJECT_PROPERTIES)) {
                    axiom.objectPropertiesInSignature().forEach(observed::add);
                } else if (!axiom.isOfType(AxiomType.DISJOINT_DATA_PROPERTIES, AxiomType.EQUIVALENT_DATA_PROPERTIES)) {
                    List<OWLObjectProperty> members = axiom.objectPropertiesInSignature().toList();
                    for (OWLObjectProperty one : members) {
                        members.forEach(other -> above(one, other));
                    }
                }
            } else if (axiom instanceof OWLSubPropertyChainOfAxiom chain) {
                chains.add(chain);
            } else if (axiom.isOfType(AxiomType.FUNCTIONAL_OBJECT_PROPERTY, AxiomType.INVERSE_FUNCTIONAL_OBJECT_PROPERTY,
                    AxiomType.ASYMMETRIC_OBJECT_PROPERTY, AxiomType.IRREFLEXIVE_OBJECT_PROPERTY)) {
                axiom.objectPropertiesInSignature().forEach(observed::add);
            }
            // Transitivity, symmetry and reflexivity give an element edges of a property it already has edges of.
            return null;
        }

        private String observe(OWLClassExpression expression, Set<OWLNamedIndividual> nominals) {
            if (expression.objectPropertiesInSignature().anyMatch(OWLObjectProperty::isOWLTopObjectProperty)) {
                return "the universal object property";
            }
            expression.individualsInSignature().forEach(nominals::add);
            expression.objectPropertiesInSignature().forEach(observed::add);
            return null;
        }

        private void above(OWLObjectPropertyExpression sub, OWLObjectPropertyExpression sup) {
            supers.computeIfAbsent(sub.getNamedProperty(), k -> new HashSet<>()).add(sup.getNamedProperty());
        }

        /** The property and every property above it. */
        private Set<OWLObjectProperty> upwards(OWLObjectProperty property) {
            Set<OWLObjectProperty> reached = new HashSet<>(Set.of(property));
            List<OWLObjectProperty> frontier = new ArrayList<>(reached);
            while (!frontier.isEmpty()) {
                OWLObjectProperty next = frontier.remove(frontier.size() - 1);
                for (OWLObjectProperty up : supers.getOrDefault(next, Set.of())) {
                    if (reached.add(up)) {
                        frontier.add(up);
                    }
                }
            }
            return reached;
        }

        Set<OWLObjectProperty> linking() {
            Set<OWLObjectProperty> all = new HashSet<>(observed);
            all.addAll(seen);
            supers.forEach((sub, ups) -> {
                all.add(sub);
                all.addAll(ups);
            });
            chains.forEach(chain -> chain.objectPropertiesInSignature().forEach(all::add));
            Set<OWLObjectProperty> linking = new HashSet<>();
            boolean grew = true;
            while (grew) {
                grew = false;
                for (OWLObjectProperty property : all) {
                    if (!linking.contains(property)
                            && upwards(property).stream().anyMatch(p -> observed.contains(p) || linking.contains(p))) {
                        linking.add(property);
                        grew = true;
                    }
                }
                for (OWLSubPropertyChainOfAxiom chain : chains) {
                    boolean superSeen = upwards(chain.getSuperProperty().getNamedProperty()).stream()
                            .anyMatch(p -> seen.contains(p) || observed.contains(p) || linking.contains(p));
                    if (superSeen) {
                        for (OWLObjectPropertyExpression link : chain.getPropertyChain()) {
                            grew |= linking.add(link.getNamedProperty());
                        }
                    }
                }
            }
            return linking;
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
        if (axiom instanceof OWLDifferentIndividualsAxiom different) {
            return different.individuals();
        }
        return Stream.concat(axiom.individualsInSignature().map(OWLIndividual.class::cast),
                axiom.anonymousIndividuals().map(OWLIndividual.class::cast));
    }
}
