// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.bench;

import io.github.armor.core.answers.Syntax;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.semanticweb.HermiT.ReasonerFactory;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasoner;

/**
 * An EXPLAIN answer read as a careful user would (ExplanationsTest, the explanations bench): each
 * line an axiom of the ontology, each justification entailing the fact on its own (HermiT on the
 * set alone), and none still entailing it without one of its axioms.
 */
public final class JustificationCheck {
    private final Map<String, OWLAxiom> byText = new HashMap<>();

    /** How many justifications were right, and what is wrong with the others. */
    public record Verdict(int right, List<String> problems) {}

    public JustificationCheck(OWLOntology ontology, boolean fullIri) {
        ontology.logicalAxioms(Imports.INCLUDED).forEach(axiom -> byText.put(Syntax.render(null, fullIri, axiom),
                axiom.getAxiomWithoutAnnotations()));
    }

    public Verdict check(OWLAxiom fact, List<String> lines) {
        List<String> problems = new ArrayList<>();
        Map<String, Set<OWLAxiom>> justifications = new LinkedHashMap<>();
        for (String line : lines) {
            String[] parts = line.split(" ", 3);
            OWLAxiom axiom = parts.length < 3 ? null : byText.get(parts[2]);
            if (axiom == null) {
                problems.add("not an axiom of the ontology: '" + line + "'");
            } else {
                justifications.computeIfAbsent(parts[0], n -> new HashSet<>()).add(axiom);
            }
        }
        if (justifications.isEmpty()) {
            problems.add("no justification");
        }
        int right = 0;
        for (Set<OWLAxiom> justification : justifications.values()) {
            String problem = entails(justification, fact) ? null : "does not entail the fact";
            for (OWLAxiom axiom : justification) {
                Set<OWLAxiom> smaller = new HashSet<>(justification);
                smaller.remove(axiom);
                if (problem == null && entails(smaller, fact)) {
                    problem = "is not minimal: it entails the fact without " + axiom;
                }
            }
            if (problem == null) {
                right++;
            } else {
                problems.add(justification + " " + problem);
            }
        }
        return new Verdict(right, problems);
    }

    private static boolean entails(Set<OWLAxiom> axioms, OWLAxiom fact) {
        try {
            OWLOntology alone = OWLManager.createOWLOntologyManager().createOntology(axioms);
            OWLReasoner reasoner = new ReasonerFactory().createReasoner(alone);
            try {
                return reasoner.isEntailed(fact);
            } finally {
                reasoner.dispose();
            }
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }
}
