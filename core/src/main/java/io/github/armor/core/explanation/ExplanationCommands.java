// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.explanation;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandGroup;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.reference.ReasonerCalls;
import io.github.armor.core.reference.Reference;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.parameters.AxiomAnnotations;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.UnsupportedEntailmentTypeException;

/**
 * The EXPLAIN commands: why a fact holds, as justifications (the minimal sets of the reference's
 * axioms that entail it). The answer's format is {@link JustificationLines}'s.
 */
public final class ExplanationCommands implements CommandGroup {
    /** The most justifications one directive may ask for: the search for each grows with the ones before. */
    static final int MAX_JUSTIFICATIONS = 20;

    @Override
    public void register(CommandTable table) {
        table.command("EXPLAIN IND CLASS").args("ind", "class").optional("justifications")
                .summary("why the individual is an instance of the class: its justifications")
                .query(c -> {
                    OWLNamedIndividual individual = c.individual(0);
                    OWLClass owlClass = c.owlClass(1);
                    return explain(c, c.factory().getOWLClassAssertionAxiom(owlClass, individual),
                            Set.of(individual), 2, r -> owlClass.isOWLThing()
                                    || r.getTypes(individual, false).containsEntity(owlClass));
                });
        table.command("EXPLAIN OBJECTPROP IND").args("prop", "ind", "value").optional("justifications")
                .summary("why the individual has the object property value: its justifications")
                .query(c -> {
                    OWLNamedIndividual subject = c.individual(1);
                    OWLNamedIndividual object = c.individual(2);
                    return explain(c, c.factory().getOWLObjectPropertyAssertionAxiom(c.objectProperty(0), subject,
                            object), new HashSet<>(List.of(subject, object)), 3, r -> r.getObjectPropertyValues(subject,
                            c.objectProperty(0)).containsEntity(object));
                });
        table.command("EXPLAIN DATAPROP IND").args("prop", "ind", "type", "value").optional("justifications")
                .summary("why the individual has the data property value: its justifications")
                .query(c -> {
                    OWLNamedIndividual individual = c.individual(1);
                    OWLLiteral value = c.literal(2, 3);
                    return explain(c, c.factory().getOWLDataPropertyAssertionAxiom(c.dataProperty(0), individual,
                            value), Set.of(individual), 4, r -> r.getDataPropertyValues(individual,
                            c.dataProperty(0)).contains(value));
                });
        table.command("EXPLAIN CLASS CLASS").args("sub class", "super class").optional("justifications")
                .summary("why the first class is a subclass of the second: its justifications")
                .query(c -> {
                    OWLClass sub = c.owlClass(0);
                    OWLClass sup = c.owlClass(1);
                    return explain(c, c.factory().getOWLSubClassOfAxiom(sub, sup), Set.of(), 2,
                            r -> sup.isOWLThing() || !r.isSatisfiable(sub)
                                    || r.getSuperClasses(sub, false).containsEntity(sup)
                                    || r.getEquivalentClasses(sub).contains(sup));
                });
        table.command("EXPLAIN INCONSISTENCY").optional("justifications")
                .summary("why the reference is inconsistent: the sets of axioms that contradict each other")
                .query(ExplanationCommands::explainInconsistency);
    }

    private static Response explain(CommandContext c, OWLAxiom fact, Set<OWLNamedIndividual> individuals,
                                    int limitIndex, Predicate<OWLReasoner> holds) {
        int limit = limit(c, limitIndex);
        Reference reference = c.reference();
        JustificationLines lines = new JustificationLines(reference, c.config().fullEntityIri(), fact);
        if (reference.ontology().containsAxiom(fact, Imports.INCLUDED, AxiomAnnotations.IGNORE_AXIOM_ANNOTATIONS)) {
            return c.ok(lines.asserted()).withDescription("asserted: the fact is in the ontology itself");
        }
        Justifications.Found told = Justifications.ofToldPath(reference.ontology(), fact, limit,
                reference.reasonerName(), ReasonerCalls.deadline(c.config().reasonerTimeoutMs()));
        if (told != null) {
            return answer(c, lines, told, "the fact");
        }
        OWLReasoner reasoner = reference.reasonerForQuery();
        // The reasoner's own answer first (what QUERY answers); entailment checking covers what
        // a reasoner infers but does not list (HermiT's data values of a class's hasValue).
        if (!reference.guardReasoner(() -> holds.test(reasoner) || reasoner.isEntailmentCheckingSupported(
                fact.getAxiomType()) && entailed(reasoner, fact))) {
            throw new ArmorException(ExitCode.NOT_ENTAILED, "'" + lines.fact() + "' does not hold in reference '"
                    + reference.name() + "' (" + reference.reasonerName() + "): there is nothing to explain");
        }
        Justifications.Found found = Justifications.of(reference.ontology(), fact, individuals, limit,
                reference.reasonerName(), ReasonerCalls.deadline(c.config().reasonerTimeoutMs()));
        return answer(c, lines, found, "the fact");
    }

    private static boolean entailed(OWLReasoner reasoner, OWLAxiom fact) {
        try {
            return reasoner.isEntailed(fact);
        } catch (UnsupportedEntailmentTypeException e) {
            return false;
        }
    }

    private static Response explainInconsistency(CommandContext c) {
        int limit = limit(c, 0);
        Reference reference = c.reference();
        if (reference.isConsistent()) {
            throw new ArmorException(ExitCode.NOT_ENTAILED, "reference '" + reference.name()
                    + "' is consistent: there is no inconsistency to explain");
        }
        OWLDataFactory factory = reference.factory();
        JustificationLines lines = new JustificationLines(reference, c.config().fullEntityIri(),
                factory.getOWLSubClassOfAxiom(factory.getOWLThing(), factory.getOWLNothing()));
        Justifications.Found found = Justifications.ofInconsistency(reference.ontology(), limit,
                reference.reasonerName(), ReasonerCalls.deadline(c.config().reasonerTimeoutMs()));
        return answer(c, lines, found, "the inconsistency");
    }

    private static Response answer(CommandContext c, JustificationLines lines, Justifications.Found found,
                                   String what) {
        List<String> answer = lines.justifications(found.sets());
        String searched = "searched " + found.searchedAxioms() + " of " + found.ontologyAxioms() + " axioms with "
                + found.reasoner();
        if (found.partial()) {
            return new Response(false, true, ExitCode.TIMEOUT.code(), "partial: " + found.sets().size()
                    + " justification(s) of " + what + " found before the reasoner time limit of "
                    + c.config().reasonerTimeoutMs() + " ms; " + searched, c.reference().isConsistent(),
                    answer, List.of());
        }
        if (found.sets().isEmpty()) {
            throw new ArmorException(ExitCode.NOT_SUPPORTED, found.reasoner() + " found no justification of " + what
                    + " (" + searched + "); the reference's reasoner uses something it does not");
        }
        return Response.ok(c.reference().isConsistent(), answer).withDescription(found.sets().size()
                + " justification(s); " + searched);
    }

    private static int limit(CommandContext c, int index) {
        if (!c.hasArg(index)) {
            return 1;
        }
        try {
            int limit = Integer.parseInt(c.arg(index).trim());
            if (limit >= 1 && limit <= MAX_JUSTIFICATIONS) {
                return limit;
            }
        } catch (NumberFormatException e) {
            // answered below, naming what was sent
        }
        throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "the number of justifications must be a whole number"
                + " from 1 to " + MAX_JUSTIFICATIONS + ", got '" + c.arg(index) + "'");
    }
}
