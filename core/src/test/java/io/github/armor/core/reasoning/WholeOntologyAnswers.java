// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;

/** The truth modular reasoning is checked against: a fresh reasoner of the same kind on the whole ontology. */
final class WholeOntologyAnswers {
    private WholeOntologyAnswers() {
    }

    /**
     * Asserts that the modular reasoner answers as a fresh whole-ontology reasoner does: consistency,
     * every class's instances (owl:Thing too), every individual's types and direct types, and the
     * values of the properties SWRL rules conclude.
     */
    static void assertSameAnswers(OWLReasonerFactory reasonerFactory, OWLOntology ontology, ModularReasoner modular,
                                  String after) {
        OWLReasoner truth = reasonerFactory.createReasoner(ontology);
        try {
            assertEquals(truth.isConsistent(), modular.isConsistent(), () -> "consistency after " + after);
            if (!truth.isConsistent()) {
                return;
            }
            Set<OWLClass> classes = ontology.classesInSignature(Imports.INCLUDED).collect(Collectors.toSet());
            classes.add(ontology.getOWLOntologyManager().getOWLDataFactory().getOWLThing());
            for (OWLClass owlClass : classes) {
                assertEquals(names(truth.getInstances(owlClass, false).entities()),
                        names(modular.getInstances(owlClass, false).entities()),
                        () -> "instances of " + owlClass + " after " + after);
            }
            List<OWLObjectProperty> ruleProperties = ontology.axioms(AxiomType.SWRL_RULE)
                    .flatMap(rule -> rule.objectPropertiesInSignature())
                    .filter(p -> !p.getIRI().toString().startsWith("http://www.w3.org/2002/07/owl#")).distinct().toList();
            for (OWLNamedIndividual individual : ontology.individualsInSignature(Imports.INCLUDED).toList()) {
                for (OWLObjectProperty property : ruleProperties) {
                    assertEquals(names(truth.getObjectPropertyValues(individual, property).entities()),
                            names(modular.getObjectPropertyValues(individual, property).entities()),
                            () -> property + " of " + individual + " after " + after);
                }
                for (boolean direct : new boolean[] {false, true}) {
                    assertEquals(names(truth.getTypes(individual, direct).entities()),
                            names(modular.getTypes(individual, direct).entities()),
                            () -> (direct ? "direct " : "") + "types of " + individual + " after " + after);
                }
            }
        } finally {
            truth.dispose();
        }
    }

    /** Entities by short name, in order (what the comparisons and expectations read). */
    static Set<String> names(Stream<? extends OWLEntity> entities) {
        return entities.map(e -> e.getIRI().getShortForm()).collect(Collectors.toCollection(TreeSet::new));
    }
}
