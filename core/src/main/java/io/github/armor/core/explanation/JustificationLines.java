// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.explanation;

import io.github.armor.core.answers.Syntax;
import io.github.armor.core.reference.Reference;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAnnotation;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLObject;
import org.semanticweb.owlapi.model.SWRLRule;
import org.semanticweb.owlapi.model.parameters.Imports;

/**
 * The text of an EXPLAIN answer: one line per axiom, {@code "<n> <kind> <axiom>"}, where
 * {@code n} numbers the justification (1, 2, ...: the lines of one justification share it, so a
 * client groups them by it) and {@code kind} is
 * <ul>
 *   <li>{@code asserted}: a fact of the ABox (an individual's class, property value, sameAs...);</li>
 *   <li>{@code axiom}: a schema axiom (classes, properties);</li>
 *   <li>{@code rule}: a SWRL rule, as {@code rule <label>: <rule> | ?x=a, ?y=b}, its label (or
 *   {@code -} without one) and the bindings of its variables under which it produced what the
 *   justification needs.</li>
 * </ul>
 * Axioms are in Manchester syntax with short names, or full IRIs under {@code full_entity_iri}.
 * Within a justification, facts come first, then axioms, then rules, each sorted by its text
 * with short names.
 */
final class JustificationLines {
    static final String ASSERTED = "asserted";
    static final String AXIOM = "axiom";
    static final String RULE = "rule";

    private final Reference reference;
    private final boolean fullIri;
    private final OWLAxiom fact;

    JustificationLines(Reference reference, boolean fullIri, OWLAxiom fact) {
        this.reference = reference;
        this.fullIri = fullIri;
        this.fact = fact;
    }

    /** The fact explained, as the answer renders it. */
    String fact() {
        return render(fact);
    }

    /** The answer for a fact that is itself in the ontology: one justification, the fact. */
    List<String> asserted() {
        return List.of("1 " + kindOf(fact) + " " + render(fact));
    }

    List<String> justifications(List<Set<OWLAxiom>> sets) {
        List<String> lines = new ArrayList<>();
        for (int i = 0; i < sets.size(); i++) {
            String number = String.valueOf(i + 1);
            Set<OWLAxiom> justification = sets.get(i);
            // By the short-name text: the same order whatever full_entity_iri is.
            justification.stream().sorted(Comparator.comparingInt(JustificationLines::order)
                            .thenComparing(axiom -> Syntax.render(reference, false, axiom)))
                    .forEach(axiom -> lines.add(number + " " + line(axiom, justification)));
        }
        return lines;
    }

    private String line(OWLAxiom axiom, Set<OWLAxiom> justification) {
        if (axiom instanceof SWRLRule rule) {
            String bindings = RuleFirings.bindings(reference, rule, fact, justification, this::render);
            return RULE + " " + label(rule) + ": " + render(rule) + (bindings.isEmpty() ? "" : " | " + bindings);
        }
        return kindOf(axiom) + " " + render(axiom);
    }

    private static String kindOf(OWLAxiom axiom) {
        return axiom.isOfType(AxiomType.ABoxAxiomTypes) ? ASSERTED : AXIOM;
    }

    private static int order(OWLAxiom axiom) {
        return axiom instanceof SWRLRule ? 2 : axiom.isOfType(AxiomType.ABoxAxiomTypes) ? 0 : 1;
    }

    /** The rule's rdfs:label, as ADD RULE names rules; the searched axioms lost their annotations. */
    private String label(SWRLRule rule) {
        return reference.ontology().axioms(AxiomType.SWRL_RULE, Imports.INCLUDED)
                .filter(r -> r.getAxiomWithoutAnnotations().equals(rule))
                .flatMap(SWRLRule::annotations)
                .filter(a -> a.getProperty().isLabel())
                .map(OWLAnnotation::getValue)
                .flatMap(v -> v.asLiteral().stream())
                .map(OWLLiteral::getLiteral)
                .sorted().findFirst().orElse("-");
    }

    private String render(OWLObject object) {
        return Syntax.render(reference, fullIri, object);
    }
}
