// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import io.github.armor.core.reasoning.ModularReasoner;
import openllet.aterm.ATermAppl;
import openllet.core.KnowledgeBase;
import openllet.core.utils.ATermUtils;
import openllet.owlapi.PelletReasoner;
import org.apache.jena.graph.Node;
import org.apache.jena.graph.Triple;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.reasoner.InferenceType;
import org.semanticweb.owlapi.reasoner.OWLReasoner;

/**
 * What the reasoner concludes about the individuals, in bulk, as RDF terms: the answers the OWL
 * API's inferred-axiom generators collect (every named type, owl:Thing included; property
 * values), in fewer questions. Callers hold the reference and guard the reasoner.
 */
final class ReasonerAnswers {
    private ReasonerAnswers() {}

    /**
     * The named instances of each of {@code classes} (owl:Thing aside: every individual is one),
     * as IRIs, among {@code individuals}. One question per class, not per individual. Openllet's
     * answers are read from its realised knowledge base: its OWL API wrapper turns every answer
     * into OWL API objects, which takes about a hundred times as long as the lookup (50 ms against
     * 0.5 ms on one LUBM department).
     */
    static Map<OWLClass, Set<String>> instances(OWLReasoner reasoner, List<OWLClass> classes,
                                               Set<String> individuals) {
        Map<OWLClass, Set<String>> instances = new HashMap<>();
        if (reasoner instanceof ModularReasoner modular) {
            modular.realiseAgainst(classes);
        }
        for (OWLClass owlClass : classes) {
            if (owlClass.isOWLThing()) {
                continue;
            }
            Set<String> members = new HashSet<>();
            for (String instance : instances(reasoner, owlClass)) {
                if (individuals.contains(instance)) {
                    members.add(instance);
                }
            }
            instances.put(owlClass, members);
        }
        return instances;
    }

    private static Collection<String> instances(OWLReasoner reasoner, OWLClass owlClass) {
        if (reasoner instanceof PelletReasoner pellet && realised(pellet)) {
            KnowledgeBase knowledge = pellet.getKB();
            return knowledge.getInstances(pellet.term(owlClass)).stream().filter(term -> !ATermUtils.isBnode(term))
                    .map(ATermAppl::getName).toList();
        }
        return reasoner.getInstances(owlClass, false).entities().map(i -> i.getIRI().toString()).toList();
    }

    /** Realises through the OWL API (which turns Openllet's failures and time-outs into its own) first. */
    private static boolean realised(PelletReasoner pellet) {
        if (!pellet.getKB().isRealized()) {
            pellet.precomputeInferences(InferenceType.CLASS_ASSERTIONS);
        }
        return pellet.getKB().isRealized();
    }

    /** Passes every inferred property value of {@code individuals} to {@code out} (asserted ones included). */
    static void values(OWLReasoner reasoner, OWLOntology ontology, PropertyValueScope scope,
                       Collection<OWLNamedIndividual> individuals, Consumer<Triple> out) {
        for (OWLNamedIndividual individual : individuals) {
            Node subject = RdfTerms.entity(individual);
            for (OWLObjectProperty property : scope.objectProperties(reasoner, ontology, individual)) {
                Node predicate = RdfTerms.entity(property);
                reasoner.getObjectPropertyValues(individual, property).entities()
                        .forEach(value -> out.accept(Triple.create(subject, predicate, RdfTerms.entity(value))));
            }
            for (OWLDataProperty property : scope.dataProperties(reasoner, ontology, individual)) {
                Node predicate = RdfTerms.entity(property);
                reasoner.getDataPropertyValues(individual, property)
                        .forEach(value -> out.accept(Triple.create(subject, predicate, RdfTerms.literal(value))));
            }
        }
    }
}
