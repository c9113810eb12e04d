// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command.builtin;

import io.github.armor.core.answers.Syntax;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.reference.ReasonerRegistry;
import io.github.armor.core.reference.Reference;
import java.util.List;
import java.util.Set;
import org.semanticweb.owl.explanation.api.Explanation;
import org.semanticweb.owl.explanation.api.ExplanationException;
import org.semanticweb.owl.explanation.api.ExplanationGenerator;
import org.semanticweb.owl.explanation.impl.blackbox.checker.InconsistentOntologyExplanationGeneratorFactory;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.parameters.Imports;

/** QUERY CONSISTENCY: the consistency flag and, when inconsistent, one set of axioms that causes it. */
final class Explanations {
    private static final long EXPLANATION_TIME_LIMIT_MS = 60_000;

    private Explanations() {}

    static Response answer(CommandContext c) {
        Reference reference = c.reference();
        if (reference.isConsistent()) {
            return Response.ok(true, List.of());
        }
        OWLDataFactory factory = reference.factory();
        InconsistentOntologyExplanationGeneratorFactory generators = new InconsistentOntologyExplanationGeneratorFactory(
                ReasonerRegistry.factory(reference.reasonerName()), factory, OWLManager::createOWLOntologyManager,
                EXPLANATION_TIME_LIMIT_MS);
        Set<OWLAxiom> axioms = reference.ontology().axioms(Imports.INCLUDED)
                .filter(OWLAxiom::isLogicalAxiom)
                .collect(java.util.stream.Collectors.toSet());
        ExplanationGenerator<OWLAxiom> generator = generators.createExplanationGenerator(axioms);
        Set<Explanation<OWLAxiom>> explanations;
        try {
            explanations = reference.guardReasoner(() -> generator.getExplanations(
                    factory.getOWLSubClassOfAxiom(factory.getOWLThing(), factory.getOWLNothing()), 1));
        } catch (ExplanationException e) {
            throw new ArmorException(ExitCode.REASONER_FAILED, "could not explain the inconsistency: "
                    + e.getMessage(), e);
        }
        List<String> lines = explanations.stream().flatMap(e -> e.getAxioms().stream())
                .map(a -> Syntax.render(reference, c.config().fullEntityIri(), a))
                .distinct().sorted().toList();
        return Response.ok(false, lines);
    }
}
