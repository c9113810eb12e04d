// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.List;
import java.util.Optional;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassAssertionAxiom;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataAllValuesFrom;
import org.semanticweb.owlapi.model.OWLDataCardinalityRestriction;
import org.semanticweb.owlapi.model.OWLDataHasValue;
import org.semanticweb.owlapi.model.OWLDataIntersectionOf;
import org.semanticweb.owlapi.model.OWLDataOneOf;
import org.semanticweb.owlapi.model.OWLDataPropertyDomainAxiom;
import org.semanticweb.owlapi.model.OWLDataPropertyRangeAxiom;
import org.semanticweb.owlapi.model.OWLDataRange;
import org.semanticweb.owlapi.model.OWLDataSomeValuesFrom;
import org.semanticweb.owlapi.model.OWLDataUnionOf;
import org.semanticweb.owlapi.model.OWLDatatypeDefinitionAxiom;
import org.semanticweb.owlapi.model.OWLDisjointClassesAxiom;
import org.semanticweb.owlapi.model.OWLDisjointUnionAxiom;
import org.semanticweb.owlapi.model.OWLEquivalentClassesAxiom;
import org.semanticweb.owlapi.model.OWLObjectAllValuesFrom;
import org.semanticweb.owlapi.model.OWLObjectComplementOf;
import org.semanticweb.owlapi.model.OWLObjectIntersectionOf;
import org.semanticweb.owlapi.model.OWLObjectMinCardinality;
import org.semanticweb.owlapi.model.OWLObjectPropertyDomainAxiom;
import org.semanticweb.owlapi.model.OWLObjectPropertyRangeAxiom;
import org.semanticweb.owlapi.model.OWLObjectSomeValuesFrom;
import org.semanticweb.owlapi.model.OWLObjectUnionOf;
import org.semanticweb.owlapi.model.OWLSubClassOfAxiom;

/**
 * Whether an ontology's axioms are Horn and can make no two named individuals equal: then, when
 * it is consistent, it has one model in which a named individual is an instance of a class, and
 * two named individuals are related by a property, only when the ontology entails it (a canonical
 * model), which is what lets {@link RuleProgram}'s rules be evaluated on entailed facts alone.
 *
 * <p>Horn: no axiom forces a choice. A class expression may stand on the right of a subclass
 * axiom ("positive") when it is built from classes, intersections, existential and universal
 * restrictions, at-least restrictions, hasValue, self, and complements of left-hand expressions
 * (¬A ⊔ B counts as A → B); on the left ("negative") from classes, intersections, unions,
 * existential restrictions (at least 1), hasValue, enumerations and complements of right-hand
 * expressions. A universal restriction or an at-least-2 restriction on the left, a union of two
 * right-hand expressions, a disjoint union and a data union or complement where values are made
 * would each let a model choose, and so would a rule with two possible worlds behind it.
 *
 * <p>No equality: sameness, functional and inverse-functional object properties, keys, at-most
 * and exact object cardinalities and enumerations can each make two names one individual.
 */
final class HornSchema {
    private HornSchema() {
    }

    /**
     * Why these axioms (the schema, and the ABox's sameness and class assertions on expressions)
     * may have no canonical model, if they may not.
     */
    static Optional<String> obstacle(List<OWLAxiom> axioms) {
        for (OWLAxiom axiom : axioms) {
            String found = obstacle(axiom);
            if (found != null) {
                return Optional.of(found + ": " + axiom);
            }
        }
        return Optional.empty();
    }

    private static String obstacle(OWLAxiom axiom) {
        if (axiom.isOfType(AxiomType.SAME_INDIVIDUAL, AxiomType.FUNCTIONAL_OBJECT_PROPERTY,
                AxiomType.INVERSE_FUNCTIONAL_OBJECT_PROPERTY, AxiomType.HAS_KEY)) {
            return "an axiom that can make two individuals one";
        }
        if (axiom.nestedClassExpressions().anyMatch(e -> e.getClassExpressionType().getName().matches(
                "ObjectMaxCardinality|ObjectExactCardinality|ObjectOneOf"))) {
            return "an axiom that can make two individuals one";
        }
        boolean horn;
        if (axiom instanceof OWLSubClassOfAxiom sub) {
            horn = negative(sub.getSubClass()) && positive(sub.getSuperClass());
        } else if (axiom instanceof OWLEquivalentClassesAxiom equivalent) {
            horn = equivalent.classExpressions().allMatch(e -> negative(e) && positive(e));
        } else if (axiom instanceof OWLDisjointClassesAxiom disjoint) {
            horn = disjoint.classExpressions().allMatch(HornSchema::negative);
        } else if (axiom instanceof OWLDisjointUnionAxiom union) {
            horn = union.classExpressions().count() <= 1;
        } else if (axiom instanceof OWLObjectPropertyDomainAxiom domain) {
            horn = positive(domain.getDomain());
        } else if (axiom instanceof OWLObjectPropertyRangeAxiom range) {
            horn = positive(range.getRange());
        } else if (axiom instanceof OWLDataPropertyDomainAxiom domain) {
            horn = positive(domain.getDomain());
        } else if (axiom instanceof OWLDataPropertyRangeAxiom range) {
            horn = positiveData(range.getRange());
        } else if (axiom instanceof OWLDatatypeDefinitionAxiom definition) {
            horn = positiveData(definition.getDataRange());
        } else if (axiom instanceof OWLClassAssertionAxiom assertion) {
            horn = positive(assertion.getClassExpression());
        } else {
            // Property axioms, assertions, declarations: no choice in them (the equality ones are above).
            horn = true;
        }
        return horn ? null : "an axiom that lets a model choose (not Horn)";
    }

    /** Whether the expression may stand on the right of a subclass axiom. */
    static boolean positive(OWLClassExpression expression) {
        if (expression.isOWLClass()) {
            return true;
        }
        if (expression instanceof OWLObjectIntersectionOf and) {
            return and.operands().allMatch(HornSchema::positive);
        }
        if (expression instanceof OWLObjectUnionOf or) {
            // ¬A ⊔ ¬B ⊔ C: one operand may be positive, the others must be complements of negative ones.
            return or.operands().filter(o -> !(o instanceof OWLObjectComplementOf not && negative(not.getOperand())))
                    .allMatch(HornSchema::positive)
                    && or.operands().filter(o -> !(o instanceof OWLObjectComplementOf not
                    && negative(not.getOperand()))).count() <= 1;
        }
        if (expression instanceof OWLObjectComplementOf not) {
            return negative(not.getOperand());
        }
        if (expression instanceof OWLObjectSomeValuesFrom some) {
            return positive(some.getFiller());
        }
        if (expression instanceof OWLObjectAllValuesFrom all) {
            return positive(all.getFiller());
        }
        if (expression instanceof OWLObjectMinCardinality min) {
            return positive(min.getFiller());
        }
        if (expression instanceof OWLDataSomeValuesFrom some) {
            return positiveData(some.getFiller());
        }
        if (expression instanceof OWLDataAllValuesFrom all) {
            return positiveData(all.getFiller());
        }
        if (expression instanceof OWLDataCardinalityRestriction cardinality) {
            return positiveData(cardinality.getFiller());
        }
        // hasValue, hasSelf, data hasValue.
        return true;
    }

    /** Whether the expression may stand on the left of a subclass axiom. */
    static boolean negative(OWLClassExpression expression) {
        if (expression.isOWLClass()) {
            return true;
        }
        if (expression instanceof OWLObjectIntersectionOf and) {
            return and.operands().allMatch(HornSchema::negative);
        }
        if (expression instanceof OWLObjectUnionOf or) {
            return or.operands().allMatch(HornSchema::negative);
        }
        if (expression instanceof OWLObjectComplementOf not) {
            return positive(not.getOperand());
        }
        if (expression instanceof OWLObjectSomeValuesFrom some) {
            return negative(some.getFiller());
        }
        if (expression instanceof OWLObjectMinCardinality min) {
            return min.getCardinality() <= 1 && negative(min.getFiller());
        }
        if (expression instanceof OWLDataSomeValuesFrom some) {
            return !(some.getFiller() instanceof org.semanticweb.owlapi.model.OWLDataComplementOf);
        }
        if (expression instanceof OWLDataHasValue) {
            return true;
        }
        if (expression instanceof OWLDataCardinalityRestriction cardinality) {
            return cardinality.getClassExpressionType().getName().equals("DataMinCardinality")
                    && cardinality.getCardinality() <= 1;
        }
        // hasValue and hasSelf can stand anywhere; universal restrictions and the rest cannot stand on the left.
        return expression.getClassExpressionType().getName().matches("ObjectHasValue|ObjectHasSelf");
    }

    /** Whether a data range can be where values are made without a choice among them. */
    private static boolean positiveData(OWLDataRange range) {
        if (range instanceof OWLDataIntersectionOf and) {
            return and.operands().allMatch(HornSchema::positiveData);
        }
        if (range instanceof OWLDataOneOf oneOf) {
            return oneOf.values().count() <= 1;
        }
        return !(range instanceof OWLDataUnionOf) && !(range instanceof org.semanticweb.owlapi.model.OWLDataComplementOf);
    }
}
