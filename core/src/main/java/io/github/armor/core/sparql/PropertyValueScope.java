// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.ClassExpressionType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLDataPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLDataPropertyRangeAxiom;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLObjectPropertyExpression;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLQuantifiedDataRestriction;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasoner;

/**
 * Which property values a reasoner can conclude for an individual, so that it is asked only
 * those questions that can have answers.
 *
 * <p>Unless an ontology has nominals (value and one-of restrictions, data ranges narrower than a
 * datatype), self restrictions, anything that can make two individuals equal (functional or
 * inverse-functional properties, cardinalities, keys, same-individual assertions), rules,
 * reflexive properties, property chains or the universal properties, a reasoner concludes
 * "x p y" (y an individual or a literal) only from asserted values between x and y, through the
 * property hierarchy, inverses, symmetry and transitivity: the models in which nothing else
 * holds satisfy such an ontology. The values of x are then found among the super-properties of
 * the properties of its asserted values, and a changed assertion changes the values of its own
 * individuals only, unless its property is below a transitive one, which carries values along
 * paths. Any other ontology is "open": every individual is asked about every property.
 */
final class PropertyValueScope {
    private static final Set<AxiomType<?>> OPENING_AXIOMS = Set.of(AxiomType.SWRL_RULE, AxiomType.SAME_INDIVIDUAL,
            AxiomType.FUNCTIONAL_OBJECT_PROPERTY, AxiomType.INVERSE_FUNCTIONAL_OBJECT_PROPERTY,
            AxiomType.REFLEXIVE_OBJECT_PROPERTY, AxiomType.HAS_KEY, AxiomType.SUB_PROPERTY_CHAIN_OF,
            AxiomType.DATATYPE_DEFINITION);
    private static final Set<ClassExpressionType> OPENING_EXPRESSIONS = Set.of(ClassExpressionType.OBJECT_HAS_VALUE,
            ClassExpressionType.OBJECT_ONE_OF, ClassExpressionType.OBJECT_HAS_SELF, ClassExpressionType.DATA_HAS_VALUE,
            ClassExpressionType.OBJECT_MIN_CARDINALITY, ClassExpressionType.OBJECT_MAX_CARDINALITY,
            ClassExpressionType.OBJECT_EXACT_CARDINALITY);

    private final boolean closed;
    private final List<OWLObjectProperty> objectProperties;
    private final List<OWLDataProperty> dataProperties;
    private final Set<OWLObjectProperty> transitive;
    // Filled on first use, under the reference's lock (only graph builders use a scope).
    private final Map<OWLObjectPropertyExpression, Set<OWLObjectProperty>> objectAbove = new HashMap<>();
    private final Map<OWLDataProperty, Set<OWLDataProperty>> dataAbove = new HashMap<>();

    private PropertyValueScope(boolean closed, List<OWLObjectProperty> objectProperties,
                               List<OWLDataProperty> dataProperties, Set<OWLObjectProperty> transitive) {
        this.closed = closed;
        this.objectProperties = objectProperties;
        this.dataProperties = dataProperties;
        this.transitive = transitive;
    }

    static PropertyValueScope of(OWLOntology ontology) {
        List<OWLObjectProperty> objectProperties = ontology.objectPropertiesInSignature(Imports.INCLUDED).toList();
        List<OWLDataProperty> dataProperties = ontology.dataPropertiesInSignature(Imports.INCLUDED).toList();
        Set<OWLObjectProperty> transitive = new LinkedHashSet<>();
        ontology.axioms(AxiomType.TRANSITIVE_OBJECT_PROPERTY, Imports.INCLUDED)
                .forEach(axiom -> transitive.add(axiom.getProperty().getNamedProperty()));
        boolean closed = objectProperties.stream().noneMatch(OWLObjectProperty::isOWLTopObjectProperty)
                && dataProperties.stream().noneMatch(OWLDataProperty::isOWLTopDataProperty)
                && ontology.importsClosure().allMatch(o -> OPENING_AXIOMS.stream().allMatch(t -> o.getAxiomCount(t) == 0))
                && schemaAxioms(ontology).noneMatch(PropertyValueScope::opens);
        return new PropertyValueScope(closed, objectProperties, dataProperties, transitive);
    }

    /** The axioms that can hold class expressions or data ranges: all but assertions of named classes. */
    private static Stream<OWLAxiom> schemaAxioms(OWLOntology ontology) {
        return Stream.of(ontology.tboxAxioms(Imports.INCLUDED), ontology.rboxAxioms(Imports.INCLUDED),
                ontology.axioms(AxiomType.CLASS_ASSERTION, Imports.INCLUDED)
                        .filter(a -> a.getClassExpression().isAnonymous())).flatMap(s -> s);
    }

    private static boolean opens(OWLAxiom axiom) {
        if (axiom instanceof OWLDataPropertyRangeAxiom range && !range.getRange().isOWLDatatype()) {
            return true;
        }
        return axiom.nestedClassExpressions().anyMatch(PropertyValueScope::opens);
    }

    private static boolean opens(OWLClassExpression expression) {
        if (OPENING_EXPRESSIONS.contains(expression.getClassExpressionType())) {
            return true;
        }
        return expression instanceof OWLQuantifiedDataRestriction restriction && !restriction.getFiller().isOWLDatatype();
    }

    /** Whether values follow from asserted values alone (see the class comment). */
    boolean closed() {
        return closed;
    }

    /** The object properties that may have values for {@code individual}. */
    Collection<OWLObjectProperty> objectProperties(OWLReasoner reasoner, OWLOntology ontology,
                                                    OWLNamedIndividual individual) {
        if (!closed) {
            return objectProperties;
        }
        Set<OWLObjectProperty> candidates = new LinkedHashSet<>();
        ontology.referencingAxioms(individual, Imports.INCLUDED).forEach(axiom -> {
            if (axiom instanceof OWLObjectPropertyAssertionAxiom assertion) {
                if (assertion.getSubject().equals(individual)) {
                    candidates.addAll(above(reasoner, assertion.getProperty()));
                }
                if (assertion.getObject().equals(individual)) {
                    candidates.addAll(above(reasoner, assertion.getProperty().getInverseProperty()));
                }
            }
        });
        return candidates;
    }

    /** The data properties that may have values for {@code individual}. */
    Collection<OWLDataProperty> dataProperties(OWLReasoner reasoner, OWLOntology ontology,
                                                OWLNamedIndividual individual) {
        if (!closed) {
            return dataProperties;
        }
        Set<OWLDataProperty> candidates = new LinkedHashSet<>();
        ontology.importsClosure().flatMap(o -> o.dataPropertyAssertionAxioms(individual))
                .map(OWLDataPropertyAssertionAxiom::getProperty).filter(p -> !p.isAnonymous())
                .forEach(p -> candidates.addAll(dataAbove.computeIfAbsent(p.asOWLDataProperty(),
                        d -> above(reasoner, d))));
        return candidates;
    }

    /**
     * Whether a changed value of {@code property} can change the values of individuals other
     * than its own: always in an open ontology, and below a transitive property.
     */
    boolean spreads(OWLReasoner reasoner, OWLObjectProperty property) {
        if (!closed) {
            return true;
        }
        if (transitive.isEmpty()) {
            return false;
        }
        return above(reasoner, property).stream().anyMatch(transitive::contains)
                || above(reasoner, property.getInverseProperty()).stream().anyMatch(transitive::contains);
    }

    /** The named properties equivalent to or above {@code property} (itself included, owl:topObjectProperty not). */
    private Set<OWLObjectProperty> above(OWLReasoner reasoner, OWLObjectPropertyExpression property) {
        return objectAbove.computeIfAbsent(property, p -> {
            Set<OWLObjectProperty> found = new LinkedHashSet<>();
            Stream.concat(reasoner.getEquivalentObjectProperties(p).entities(),
                            reasoner.getSuperObjectProperties(p, false).entities())
                    .filter(e -> e.isNamed() && !e.isOWLTopObjectProperty())
                    .forEach(e -> found.add(e.asOWLObjectProperty()));
            if (p.isNamed()) {
                found.add(p.asOWLObjectProperty());
            }
            return found;
        });
    }

    private static Set<OWLDataProperty> above(OWLReasoner reasoner, OWLDataProperty property) {
        Set<OWLDataProperty> found = new LinkedHashSet<>();
        found.add(property);
        Stream.concat(reasoner.getEquivalentDataProperties(property).entities(),
                        reasoner.getSuperDataProperties(property, false).entities())
                .filter(d -> !d.isOWLTopDataProperty()).forEach(found::add);
        return found;
    }
}
