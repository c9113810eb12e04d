// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.answers;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reference.Reference;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.search.EntitySearcher;
import org.semanticweb.owlapi.util.InferredAxiomGenerator;
import org.semanticweb.owlapi.util.InferredClassAssertionAxiomGenerator;
import org.semanticweb.owlapi.util.InferredDataPropertyCharacteristicAxiomGenerator;
import org.semanticweb.owlapi.util.InferredEquivalentClassAxiomGenerator;
import org.semanticweb.owlapi.util.InferredPropertyAssertionGenerator;
import org.semanticweb.owlapi.util.InferredSubClassAxiomGenerator;

/**
 * Answers as the contract wants them: the union of what the ontology asserts and what the
 * reasoner infers. The asserted half matters with a buffered reasoner, which has not yet seen
 * the changes applied since the last REASON. Public for plugins: a plugin's command answers
 * from the same knowledge as the built-in queries.
 */
public final class Inferences {
    private Inferences() {}

    /**
     * What the reasoner answers, or nothing when this reasoner cannot answer that kind of
     * question (ELK has no property-value queries): the asserted half still answers.
     */
    public static <T> Stream<T> inferred(Reference reference, Function<OWLReasoner, Stream<T>> question) {
        OWLReasoner reasoner = reference.reasonerForQuery();
        try {
            return reference.guardReasoner(() -> question.apply(reasoner).toList()).stream();
        } catch (ArmorException e) {
            if (e.exitCode() == ExitCode.NOT_SUPPORTED) {
                return Stream.empty();
            }
            throw e;
        }
    }

    /**
     * Whether the ontology mentions the entity. One it does not mention has no facts, asserted or
     * inferred; reasoners asked about it anyway answer wrongly (JFact) or fail.
     */
    public static boolean known(Reference reference, OWLEntity entity) {
        return entity.isBuiltIn() || reference.ontology().containsEntityInSignature(entity, Imports.INCLUDED);
    }

    public static Stream<OWLOntology> closure(Reference reference) {
        return reference.ontology().importsClosure();
    }

    public static Set<OWLNamedIndividual> instances(Reference reference, OWLClassExpression owlClass, boolean direct) {
        if (!owlClass.isAnonymous() && !known(reference, owlClass.asOWLClass())) {
            return Set.of();
        }
        Stream<OWLNamedIndividual> asserted = owlClass.isAnonymous() ? Stream.empty()
                : EntitySearcher.getIndividuals(owlClass.asOWLClass(), closure(reference))
                .filter(i -> i.isNamed()).map(i -> i.asOWLNamedIndividual());
        return union(asserted, inferred(reference, r -> r.getInstances(owlClass, direct).entities()));
    }

    /**
     * The named classes entailed to be subclasses of {@code owlClass}, never the class itself. An
     * unsatisfiable class is a subclass of every class: reasoners list the unsatisfiable ones
     * under a satisfiable class, but under owl:Nothing or another unsatisfiable class only JFact
     * does, so all of them are added here for every reasoner (a direct query keeps the
     * reasoner's answer: the unsatisfiable classes are direct subclasses of the leaves only).
     */
    public static Set<OWLClass> subClasses(Reference reference, OWLClassExpression owlClass, boolean direct) {
        if (!owlClass.isAnonymous() && !known(reference, owlClass.asOWLClass())) {
            return Set.of();
        }
        Stream<OWLClass> asserted = owlClass.isAnonymous() ? Stream.empty()
                : EntitySearcher.getSubClasses(owlClass.asOWLClass(), closure(reference))
                .filter(c -> !c.isAnonymous()).map(OWLClassExpression::asOWLClass);
        Set<OWLClass> subclasses = union(asserted, inferred(reference, r -> direct
                ? r.getSubClasses(owlClass, true).entities()
                : Stream.concat(r.getSubClasses(owlClass, false).entities(), r.getUnsatisfiableClasses().entities())));
        if (!owlClass.isAnonymous()) {
            subclasses.remove(owlClass.asOWLClass());
        }
        return subclasses;
    }

    @SafeVarargs
    public static <T> Set<T> union(Stream<? extends T>... parts) {
        return Stream.of(parts).flatMap(s -> s).collect(Collectors.toCollection(LinkedHashSet::new));
    }

    /** The reference's axioms, its imports' included, in a new ontology of a manager of its own. */
    public static OWLOntology copyWithImports(Reference reference) {
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        try {
            OWLOntology copy = manager.createOntology(reference.ontology().getOntologyID());
            manager.addAxioms(copy, reference.ontology().axioms(Imports.INCLUDED));
            return copy;
        } catch (OWLOntologyCreationException e) {
            throw new ArmorException(ExitCode.INTERNAL_ERROR, "could not copy the ontology: " + e.getMessage(), e);
        }
    }

    /**
     * A copy of the ontology with the inferred class assertions, property assertions and class
     * hierarchy added; the live ontology is left as it was (SAVE INFERENCE).
     */
    public static OWLOntology withInferences(Reference reference) {
        OWLReasoner reasoner = reference.reasonerForQuery();
        OWLOntology copy = copyWithImports(reference);
        OWLOntologyManager manager = copy.getOWLOntologyManager();
        OWLOntologyManager liveManager = reference.manager();
        if (liveManager.getOntologyFormat(reference.ontology()) != null) {
            manager.setOntologyFormat(copy, liveManager.getOntologyFormat(reference.ontology()));
        }
        List<InferredAxiomGenerator<? extends OWLAxiom>> generators = List.of(
                new InferredSubClassAxiomGenerator(),
                new InferredEquivalentClassAxiomGenerator(),
                new InferredClassAssertionAxiomGenerator(),
                new InferredPropertyAssertionGenerator(),
                new InferredDataPropertyCharacteristicAxiomGenerator());
        for (InferredAxiomGenerator<? extends OWLAxiom> generator : generators) {
            try {
                Set<? extends OWLAxiom> axioms = reference.guardReasoner(
                        () -> generator.createAxioms(manager.getOWLDataFactory(), reasoner));
                manager.addAxioms(copy, axioms.stream().map(OWLAxiom.class::cast));
            } catch (ArmorException e) {
                if (e.exitCode() != ExitCode.NOT_SUPPORTED) {
                    throw e;
                }
            }
        }
        return copy;
    }
}
