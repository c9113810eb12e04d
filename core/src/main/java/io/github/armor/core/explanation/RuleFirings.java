// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.explanation;

import io.github.armor.core.reference.Reference;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassAssertionAxiom;
import org.semanticweb.owlapi.model.OWLDataPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObject;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.SWRLArgument;
import org.semanticweb.owlapi.model.SWRLAtom;
import org.semanticweb.owlapi.model.SWRLClassAtom;
import org.semanticweb.owlapi.model.SWRLDataPropertyAtom;
import org.semanticweb.owlapi.model.SWRLIndividualArgument;
import org.semanticweb.owlapi.model.SWRLLiteralArgument;
import org.semanticweb.owlapi.model.SWRLObjectPropertyAtom;
import org.semanticweb.owlapi.model.SWRLRule;
import org.semanticweb.owlapi.model.SWRLVariable;
import org.semanticweb.owlapi.reasoner.OWLReasoner;

/**
 * The bindings under which a rule of a justification fired: values of its variables for which
 * the reasoner finds every class and property atom of its body true. The explained fact, when
 * it is an instance of the rule's head, fixes the head's variables first; the other variables
 * range over the individuals the justification names. Built-ins are not evaluated (they only
 * restrict which bindings fire, and the reasoner already found these did).
 */
final class RuleFirings {
    // Variables of a rule body rarely exceed a handful; past this many candidates per variable the
    // search is not worth its time for a line of text.
    private static final int MAX_CANDIDATES = 64;

    private RuleFirings() {}

    /** {@code "?x=robot1, ?r=kitchen"}, or empty when no binding was found. */
    static String bindings(Reference reference, SWRLRule rule, OWLAxiom fact, Set<OWLAxiom> justification,
                           Function<OWLObject, String> render) {
        Map<IRI, OWLObject> bound = new LinkedHashMap<>();
        for (SWRLAtom head : rule.head().toList()) {
            Map<IRI, OWLObject> unified = new LinkedHashMap<>();
            if (unify(head, fact, unified)) {
                bound.putAll(unified);
                break;
            }
        }
        List<OWLNamedIndividual> candidates = Stream.concat(justification.stream(), Stream.of(fact))
                .flatMap(OWLAxiom::individualsInSignature).distinct()
                .sorted().limit(MAX_CANDIDATES).toList();
        List<SWRLVariable> free = rule.body().flatMap(RuleFirings::individualVariables).distinct()
                .filter(v -> !bound.containsKey(v.getIRI())).toList();
        OWLReasoner reasoner = reference.reasonerForQuery();
        Optional<Map<IRI, OWLObject>> firing = reference.guardReasoner(() ->
                search(rule, reasoner, bound, free, 0, candidates));
        return firing.map(values -> values.entrySet().stream()
                .map(e -> "?" + variableName(e.getKey()) + "=" + render.apply(e.getValue()))
                .collect(Collectors.toCollection(TreeSet::new)))
                .map(lines -> String.join(", ", lines)).orElse("");
    }

    private static Optional<Map<IRI, OWLObject>> search(SWRLRule rule, OWLReasoner reasoner, Map<IRI, OWLObject> bound,
                                                       List<SWRLVariable> free, int next,
                                                       List<OWLNamedIndividual> candidates) {
        if (!bodyHolds(rule, reasoner, bound)) {
            return Optional.empty();
        }
        if (next == free.size()) {
            Map<IRI, OWLObject> complete = new LinkedHashMap<>(bound);
            bindData(rule, reasoner, complete);
            return Optional.of(complete);
        }
        for (OWLNamedIndividual candidate : candidates) {
            Map<IRI, OWLObject> tried = new LinkedHashMap<>(bound);
            tried.put(free.get(next).getIRI(), candidate);
            Optional<Map<IRI, OWLObject>> found = search(rule, reasoner, tried, free, next + 1, candidates);
            if (found.isPresent()) {
                return found;
            }
        }
        return Optional.empty();
    }

    /** Whether every class and object property atom whose individuals are all bound holds. */
    private static boolean bodyHolds(SWRLRule rule, OWLReasoner reasoner, Map<IRI, OWLObject> bound) {
        for (SWRLAtom atom : rule.body().toList()) {
            if (atom instanceof SWRLClassAtom classAtom && !classAtom.getPredicate().isAnonymous()) {
                OWLNamedIndividual individual = individual(classAtom.getArgument(), bound);
                if (individual != null && !reasoner.getTypes(individual, false)
                        .containsEntity(classAtom.getPredicate().asOWLClass())
                        && !classAtom.getPredicate().isOWLThing()) {
                    return false;
                }
            } else if (atom instanceof SWRLObjectPropertyAtom propertyAtom
                    && !propertyAtom.getPredicate().isAnonymous()) {
                OWLNamedIndividual subject = individual(propertyAtom.getFirstArgument(), bound);
                OWLNamedIndividual object = individual(propertyAtom.getSecondArgument(), bound);
                if (subject != null && object != null && !reasoner.getObjectPropertyValues(subject,
                        propertyAtom.getPredicate().asOWLObjectProperty()).containsEntity(object)) {
                    return false;
                }
            }
        }
        return true;
    }

    /** Data variables take the value the reasoner gives their individual's property (the smallest, for a stable text). */
    private static void bindData(SWRLRule rule, OWLReasoner reasoner, Map<IRI, OWLObject> bound) {
        for (SWRLAtom atom : rule.body().toList()) {
            if (atom instanceof SWRLDataPropertyAtom dataAtom && dataAtom.getSecondArgument() instanceof SWRLVariable v
                    && !bound.containsKey(v.getIRI()) && dataAtom.getPredicate().isOWLDataProperty()) {
                OWLNamedIndividual individual = individual(dataAtom.getFirstArgument(), bound);
                if (individual != null) {
                    reasoner.getDataPropertyValues(individual, dataAtom.getPredicate().asOWLDataProperty()).stream()
                            .min(Comparator.comparing(Object::toString)).ifPresent(value -> bound.put(v.getIRI(), value));
                }
            }
        }
    }

    private static OWLNamedIndividual individual(SWRLArgument argument, Map<IRI, OWLObject> bound) {
        if (argument instanceof SWRLIndividualArgument named && named.getIndividual().isNamed()) {
            return named.getIndividual().asOWLNamedIndividual();
        }
        if (argument instanceof SWRLVariable variable && bound.get(variable.getIRI()) instanceof OWLNamedIndividual i) {
            return i;
        }
        return null;
    }

    private static Stream<SWRLVariable> individualVariables(SWRLAtom atom) {
        List<SWRLArgument> arguments = new ArrayList<>();
        if (atom instanceof SWRLClassAtom classAtom) {
            arguments.add(classAtom.getArgument());
        } else if (atom instanceof SWRLObjectPropertyAtom propertyAtom) {
            arguments.add(propertyAtom.getFirstArgument());
            arguments.add(propertyAtom.getSecondArgument());
        } else if (atom instanceof SWRLDataPropertyAtom dataAtom) {
            arguments.add(dataAtom.getFirstArgument());
        }
        return arguments.stream().filter(SWRLVariable.class::isInstance).map(SWRLVariable.class::cast);
    }

    /** Binds the head atom's variables to the fact's entities if the fact is an instance of the atom. */
    private static boolean unify(SWRLAtom head, OWLAxiom fact, Map<IRI, OWLObject> bound) {
        if (head instanceof SWRLClassAtom atom && fact instanceof OWLClassAssertionAxiom assertion) {
            return atom.getPredicate().equals(assertion.getClassExpression())
                    && bind(atom.getArgument(), assertion.getIndividual(), bound);
        }
        if (head instanceof SWRLObjectPropertyAtom atom && fact instanceof OWLObjectPropertyAssertionAxiom assertion) {
            return atom.getPredicate().equals(assertion.getProperty())
                    && bind(atom.getFirstArgument(), assertion.getSubject(), bound)
                    && bind(atom.getSecondArgument(), assertion.getObject(), bound);
        }
        if (head instanceof SWRLDataPropertyAtom atom && fact instanceof OWLDataPropertyAssertionAxiom assertion) {
            return atom.getPredicate().equals(assertion.getProperty())
                    && bind(atom.getFirstArgument(), assertion.getSubject(), bound)
                    && bind(atom.getSecondArgument(), assertion.getObject(), bound);
        }
        return false;
    }

    private static boolean bind(SWRLArgument argument, OWLObject value, Map<IRI, OWLObject> bound) {
        if (argument instanceof SWRLVariable variable) {
            OWLObject previous = bound.putIfAbsent(variable.getIRI(), value);
            return previous == null || previous.equals(value);
        }
        if (argument instanceof SWRLIndividualArgument individual) {
            return individual.getIndividual().equals(value);
        }
        return argument instanceof SWRLLiteralArgument literal && literal.getLiteral().equals(value);
    }

    private static String variableName(IRI variable) {
        String text = variable.toString();
        int cut = Math.max(text.lastIndexOf('#'), text.lastIndexOf('/'));
        return text.substring(cut + 1);
    }
}
