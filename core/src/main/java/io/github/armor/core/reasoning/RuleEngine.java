// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.Builtins.DataValue;
import io.github.armor.core.reasoning.RuleProgram.Atom;
import io.github.armor.core.reasoning.RuleProgram.Image;
import io.github.armor.core.reasoning.RuleProgram.Kind;
import io.github.armor.core.reasoning.RuleProgram.Rule;
import io.github.armor.core.reasoning.RuleProgram.Term;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLDataPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLDifferentIndividualsAxiom;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLObjectPropertyExpression;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.parameters.Imports;

/**
 * The rules of a {@link RuleProgram} kept evaluated as the ABox changes: every conclusion with
 * the number of matches of rule bodies that give it. A fact that appears (a type the modules
 * found, an edge or a value asserted or concluded) is joined with the facts already there, from
 * its own atom onwards in each rule that reads it; a fact that goes is joined the same way just
 * before it goes. Each match is thereby counted once when its last fact appears and once when
 * its first fact goes, so a conclusion holds exactly while its count is positive: retraction is
 * exact without evaluating anything again (rules that feed one another in a cycle, where a
 * count could be kept up by a fact's own consequence, are refused by the program). Appearing
 * facts are handled before going ones, so a value replaced by another (the robot's clock) moves
 * counts without making conclusions that stay flicker.
 *
 * <p>The work of a change is the matches it makes or ends: a moved robot joins its new place's
 * neighbours; a clock value replaced by the next is joined from both side by side ({@link
 * #replaced}), and where the rest of the rule enumerates values that only linear comparisons
 * read, only the values in the ranges where those comparisons differ before and after are
 * visited ({@link FlipRanges}, over each property's values in numeric order, {@link
 * OrderedValues}): a tick costs the rooms whose urgency changed, not every room. What the modules
 * reason on again is only what changed.
 *
 * <p>Why not Jena's forward (RETE) engine, which has built-ins: its retraction is not exact.
 * With Jena 3.10's FORWARD_RETE, the rule (?a p ?b) -> (?b q x) and the facts (a1 p b), (a2 p b),
 * removing (a1 p b) removes (b q x), which (a2 p b) still gives; the way round is to evaluate
 * everything again after every removal, work proportional to the whole ABox.
 */
final class RuleEngine {
    /** A fact rules read or conclude: a type (object null), an edge (an individual) or a value (a data value). */
    record Fact(Kind kind, Object predicate, OWLNamedIndividual subject, Object object) {}

    private record Match(int rule, List<Object> binding) {}

    /** An edge relation with, for each edge, how many asserted or concluded edges give it. */
    private static final class Relation {
        final Map<OWLNamedIndividual, Map<OWLNamedIndividual, Integer>> out = new HashMap<>();
        final Map<OWLNamedIndividual, Set<OWLNamedIndividual>> in = new HashMap<>();
    }

    private final RuleProgram program;
    private final OWLDataFactory factory;
    private final Map<OWLObjectProperty, Relation> edges = new HashMap<>();
    private final Map<OWLDataProperty, Map<OWLNamedIndividual, Map<DataValue, Integer>>> values = new HashMap<>();
    private final Map<OWLDataProperty, OrderedValues> ordered = new HashMap<>();
    private final Map<OWLClass, Set<OWLNamedIndividual>> typed = new HashMap<>();
    private final Map<OWLNamedIndividual, Set<OWLClass>> typesOf = new HashMap<>();
    private final Map<OWLNamedIndividual, List<Set<OWLIndividual>>> differentSets = new HashMap<>();
    private final Map<Fact, Integer> support = new HashMap<>();
    private final Map<OWLNamedIndividual, Set<Fact>> conclusionsAbout = new HashMap<>();
    // Per batch: whether each conclusion that changed held before it.
    private final Map<Fact, Boolean> heldBefore = new LinkedHashMap<>();
    private String obstacle;

    RuleEngine(RuleProgram program, OWLDataFactory factory) {
        this.program = program;
        this.factory = factory;
        program.edgeProperties.forEach(p -> edges.put(p, new Relation()));
        program.valueProperties.forEach(p -> values.put(p, new HashMap<>()));
        program.valueProperties.forEach(p -> ordered.put(p, new OrderedValues()));
        program.bodyClasses.forEach(c -> typed.put(c, new HashSet<>()));
    }

    /** Why the rules cannot be evaluated here after all (a DifferentIndividuals atom on a pair not asserted different). */
    String obstacle() {
        return obstacle;
    }

    /** The classes of rule bodies (only their types are given to the engine). */
    Set<OWLClass> bodyClasses() {
        return program.bodyClasses;
    }

    /** Whether a DifferentIndividuals axiom change must be followed by {@link #load} (a rule reads difference). */
    boolean readsDifference() {
        return program.readsDifference;
    }

    /**
     * Everything from the ontology as it is: its edges, values and differences, and the types
     * {@code typesOf} gives (classes of rule bodies only). Answers the conclusions.
     */
    Set<Fact> load(OWLOntology ontology, java.util.function.Function<OWLClass, Collection<OWLNamedIndividual>> typesOf) {
        edges.values().forEach(r -> {
            r.out.clear();
            r.in.clear();
        });
        values.values().forEach(Map::clear);
        ordered.values().forEach(OrderedValues::clear);
        typed.values().forEach(Set::clear);
        this.typesOf.clear();
        support.clear();
        conclusionsAbout.clear();
        obstacle = null;
        differentSets.clear();
        ontology.axioms(AxiomType.DIFFERENT_INDIVIDUALS, Imports.INCLUDED).forEach(this::addDifference);
        heldBefore.clear();
        for (OWLClass owlClass : program.bodyClasses) {
            for (OWLNamedIndividual individual : typesOf.apply(owlClass)) {
                this.typesOf.computeIfAbsent(individual, k -> new HashSet<>()).add(owlClass);
                typed.get(owlClass).add(individual);
                appeared(new Fact(Kind.CLASS, owlClass, individual, null));
            }
        }
        ontology.axioms(AxiomType.OBJECT_PROPERTY_ASSERTION, Imports.INCLUDED).forEach(a -> asserted(a, true));
        ontology.axioms(AxiomType.DATA_PROPERTY_ASSERTION, Imports.INCLUDED).forEach(a -> asserted(a, true));
        return netChanges();
    }

    private void addDifference(OWLDifferentIndividualsAxiom axiom) {
        Set<OWLIndividual> members = new HashSet<>(axiom.getIndividualsAsList());
        for (OWLIndividual member : members) {
            if (member.isNamed()) {
                differentSets.computeIfAbsent(member.asOWLNamedIndividual(), k -> new ArrayList<>()).add(members);
            }
        }
    }

    /**
     * One batch: the asserted edges and values added and removed, and the new body-class types
     * of the individuals whose types changed (an empty set for one that is gone). Answers the
     * conclusions that appeared or went.
     */
    Set<Fact> update(List<OWLAxiom> added, List<OWLAxiom> removed, Map<OWLNamedIndividual, Set<OWLClass>> retyped) {
        heldBefore.clear();
        List<Fact> goneTypes = new ArrayList<>();
        retyped.forEach((individual, now) -> {
            Set<OWLClass> before = typesOf.getOrDefault(individual, Set.of());
            for (OWLClass owlClass : now) {
                if (!before.contains(owlClass)) {
                    typesOf.computeIfAbsent(individual, k -> new HashSet<>()).add(owlClass);
                    typed.get(owlClass).add(individual);
                    appeared(new Fact(Kind.CLASS, owlClass, individual, null));
                }
            }
            for (OWLClass owlClass : before) {
                if (!now.contains(owlClass)) {
                    goneTypes.add(new Fact(Kind.CLASS, owlClass, individual, null));
                }
            }
        });
        List<OWLAxiom> adding = new ArrayList<>(added);
        List<OWLAxiom> removing = new ArrayList<>(removed);
        replacements(adding, removing);
        adding.forEach(axiom -> asserted(axiom, true));
        for (Fact fact : goneTypes) {
            went(fact);
            typed.get((OWLClass) fact.predicate).remove(fact.subject);
            Set<OWLClass> left = typesOf.get(fact.subject);
            left.remove((OWLClass) fact.predicate);
            if (left.isEmpty()) {
                typesOf.remove(fact.subject);
            }
        }
        removing.forEach(axiom -> asserted(axiom, false));
        return netChanges();
    }

    /**
     * The data values replaced in a batch (one value of a property of an individual goes, another
     * comes: the robot's clock, a room's last visit) taken out of {@code adding} and
     * {@code removing} and handled as one step each ({@link #replaced}).
     */
    private void replacements(List<OWLAxiom> adding, List<OWLAxiom> removing) {
        Map<List<Object>, OWLDataPropertyAssertionAxiom> gone = new HashMap<>();
        for (OWLAxiom axiom : removing) {
            if (axiom instanceof OWLDataPropertyAssertionAxiom value && value.getSubject().isNamed()) {
                gone.putIfAbsent(List.of(value.getProperty(), value.getSubject()), value);
            }
        }
        if (gone.isEmpty()) {
            return;
        }
        for (OWLAxiom axiom : List.copyOf(adding)) {
            if (axiom instanceof OWLDataPropertyAssertionAxiom value && value.getSubject().isNamed()) {
                OWLDataPropertyAssertionAxiom old = gone.remove(List.of(value.getProperty(), value.getSubject()));
                if (old != null) {
                    adding.remove(axiom);
                    removing.remove(old);
                    for (OWLDataProperty image : program.imagesOf(value.getProperty().asOWLDataProperty())) {
                        replaced(image, value.getSubject().asOWLNamedIndividual(), DataValue.of(old.getObject()),
                                DataValue.of(value.getObject()));
                    }
                }
            }
        }
    }

    /**
     * A value of a kept data property replaced by another, as one step: each rule that reads the
     * property once is joined from the old and the new value side by side ({@link #pairedJoin}),
     * so a match that holds, with the same conclusions, before and after costs its join and no
     * count; only the matches that start or end move counts. A rule that reads the property twice,
     * or a value held twice, takes the two facts one after the other instead (new first).
     */
    private void replaced(OWLDataProperty image, OWLNamedIndividual subject, DataValue old, DataValue now) {
        Map<DataValue, Integer> held = values.get(image).computeIfAbsent(subject, k -> new LinkedHashMap<>());
        if (old.equals(now) || !program.readOnce(image) || held.getOrDefault(old, 0) != 1 || held.containsKey(now)) {
            valueOf(image, subject, now, true);
            valueOf(image, subject, old, false);
            return;
        }
        Map<Fact, Integer> delta = new LinkedHashMap<>();
        List<Rule> rules = program.rules;
        for (int r = 0; r < rules.size(); r++) {
            Rule rule = rules.get(r);
            for (int position = 0; position < rule.body().size(); position++) {
                Atom atom = rule.body().get(position);
                if (atom.kind() != Kind.VALUE || !atom.predicate().equals(image)) {
                    continue;
                }
                Object[] before = new Object[rule.variables()];
                Object[] after = new Object[rule.variables()];
                boolean was = unify(atom.term(0), subject, before) && unify(atom.term(1), old, before);
                boolean is = unify(atom.term(0), subject, after) && unify(atom.term(1), now, after);
                pairedJoin(r, rule, rule.plans()[position], 0, before, after, was, is, null, delta);
            }
        }
        // The store holds the new value before any conclusion moves (the step is one change).
        held.remove(old);
        held.put(now, 1);
        ordered.get(image).remove(subject, old);
        ordered.get(image).add(subject, now);
        List<Fact> came = new ArrayList<>();
        List<Fact> went = new ArrayList<>();
        delta.forEach((conclusion, change) -> {
            if (change == 0) {
                return;
            }
            int count = support.getOrDefault(conclusion, 0);
            int next = count + change;
            if (next <= 0) {
                support.remove(conclusion);
            } else {
                support.put(conclusion, next);
            }
            if (count == 0 && next > 0) {
                came.add(conclusion);
            } else if (count > 0 && next <= 0) {
                went.add(conclusion);
            }
        });
        for (Fact conclusion : came) {
            heldBefore.putIfAbsent(conclusion, false);
            concluded(conclusion, true);
        }
        for (Fact conclusion : went) {
            heldBefore.putIfAbsent(conclusion, true);
            concluded(conclusion, false);
        }
    }

    /**
     * Joins a rule's remaining atoms from two bindings at once, the one with the old value
     * ({@code before}) and the one with the new ({@code after}), alive or not: an atom whose
     * terms are the same in both is joined once for both (a room enumerated once), one that
     * differs is tested in each (the clock's subtraction and comparison, twice per room). Where
     * an atom would enumerate from terms that differ, the two go on apart. At the end the
     * conclusions of the match before are uncounted and those after counted, in {@code delta};
     * equal ones cancel.
     */
    private void pairedJoin(int ruleNumber, Rule rule, int[] plan, int step, Object[] before, Object[] after,
                            boolean was, boolean is, String unsure, Map<Fact, Integer> delta) {
        if (!was && !is) {
            return;
        }
        if (step == plan.length) {
            if (undecided(unsure)) {
                return;
            }
            if (was) {
                conclusions(new Match(ruleNumber, Arrays.asList(before))).forEach(f -> delta.merge(f, -1, Integer::sum));
            }
            if (is) {
                conclusions(new Match(ruleNumber, Arrays.asList(after))).forEach(f -> delta.merge(f, 1, Integer::sum));
            }
            return;
        }
        Atom atom = rule.body().get(plan[step]);
        boolean same = was && is;
        boolean binds = false;
        for (Term term : atom.terms()) {
            if (term.isVariable()) {
                Object one = before[term.variable()];
                Object other = after[term.variable()];
                same &= one == null ? other == null : one.equals(other);
                binds |= one == null || other == null;
            }
        }
        if (was && is && binds) {
            FlipRanges.Flips flips = FlipRanges.of(rule, plan, step, before, after);
            if (flips != null) {
                // Only the values whose matches differ before and after are joined (FlipRanges).
                Atom enumerated = rule.body().get(flips.atom());
                ordered.get((OWLDataProperty) enumerated.predicate()).within(flips.ranges(), (subject, value) -> {
                    Object[] nextBefore = before.clone();
                    Object[] nextAfter = after.clone();
                    nextBefore[flips.subject()] = subject;
                    nextAfter[flips.subject()] = subject;
                    nextBefore[flips.value()] = value;
                    nextAfter[flips.value()] = value;
                    pairedJoin(ruleNumber, rule, plan, step, nextBefore, nextAfter, true, true, unsure, delta);
                });
                return;
            }
        }
        if (same) {
            // One join for both: every variable it binds is bound alike in both.
            joinOne(rule, plan[step], before.clone(), unsure, (b, u) ->
                    pairedJoin(ruleNumber, rule, plan, step + 1, b.clone(), mergeBound(after, b), true, true, u, delta));
            return;
        }
        if (!binds || atom.kind() == Kind.BUILTIN && Builtins.binds((IRI) atom.predicate())) {
            // A test (or a computed value) that reads what differs: each world on its own, still side by side.
            Object[] nextBefore = before.clone();
            Object[] nextAfter = after.clone();
            boolean[] alive = {false, false};
            String[] unsures = {unsure, unsure};
            if (was) {
                joinOne(rule, plan[step], before.clone(), unsure, (b, u) -> {
                    System.arraycopy(b, 0, nextBefore, 0, b.length);
                    alive[0] = true;
                    unsures[0] = u;
                });
            }
            if (is) {
                joinOne(rule, plan[step], after.clone(), unsure, (b, u) -> {
                    System.arraycopy(b, 0, nextAfter, 0, b.length);
                    alive[1] = true;
                    unsures[1] = u;
                });
            }
            if (Objects.equals(unsures[0], unsures[1])) {
                pairedJoin(ruleNumber, rule, plan, step + 1, nextBefore, nextAfter, alive[0], alive[1], unsures[0],
                        delta);
                return;
            }
            pairedJoin(ruleNumber, rule, plan, step + 1, nextBefore, nextAfter, alive[0], false, unsures[0], delta);
            pairedJoin(ruleNumber, rule, plan, step + 1, nextBefore, nextAfter, false, alive[1], unsures[1], delta);
            return;
        }
        // An enumeration from terms that differ: the two worlds go on apart.
        Set<Match> gone = new LinkedHashSet<>();
        Set<Match> come = new LinkedHashSet<>();
        if (was) {
            join(ruleNumber, rule, plan, step, before.clone(), unsure, gone);
        }
        if (is) {
            join(ruleNumber, rule, plan, step, after.clone(), unsure, come);
        }
        gone.forEach(match -> conclusions(match).forEach(f -> delta.merge(f, -1, Integer::sum)));
        come.forEach(match -> conclusions(match).forEach(f -> delta.merge(f, 1, Integer::sum)));
    }

    /** {@code into} with every variable {@code bound} binds and {@code into} does not. */
    private static Object[] mergeBound(Object[] into, Object[] bound) {
        Object[] merged = into.clone();
        for (int i = 0; i < merged.length; i++) {
            if (merged[i] == null) {
                merged[i] = bound[i];
            }
        }
        return merged;
    }

    private Set<Fact> netChanges() {
        Set<Fact> changed = new LinkedHashSet<>();
        heldBefore.forEach((fact, before) -> {
            if (before != support.containsKey(fact)) {
                changed.add(fact);
            }
        });
        heldBefore.clear();
        return changed;
    }

    /** An asserted edge or value that appeared or went (other axioms are not read here). */
    private void asserted(OWLAxiom axiom, boolean appears) {
        if (axiom instanceof OWLObjectPropertyAssertionAxiom edge && edge.getSubject().isNamed()
                && edge.getObject().isNamed()) {
            OWLObjectPropertyExpression property = edge.getProperty();
            OWLNamedIndividual subject = edge.getSubject().asOWLNamedIndividual();
            OWLNamedIndividual object = edge.getObject().asOWLNamedIndividual();
            if (property.isAnonymous()) {
                edge(property.getNamedProperty(), object, subject, appears);
            } else {
                edge(property.asOWLObjectProperty(), subject, object, appears);
            }
        } else if (axiom instanceof OWLDataPropertyAssertionAxiom value && value.getSubject().isNamed()) {
            value(value.getProperty().asOWLDataProperty(), value.getSubject().asOWLNamedIndividual(),
                    DataValue.of(value.getObject()), appears);
        }
    }

    /** An edge of {@code property}, asserted or concluded, that appeared or went: its images move. */
    private void edge(OWLObjectProperty property, OWLNamedIndividual subject, OWLNamedIndividual object,
                      boolean appears) {
        for (Image image : program.imagesOf(property)) {
            OWLNamedIndividual from = image.reversed() ? object : subject;
            OWLNamedIndividual to = image.reversed() ? subject : object;
            Relation relation = edges.get(image.property());
            Map<OWLNamedIndividual, Integer> targets = relation.out.computeIfAbsent(from, k -> new HashMap<>());
            int count = targets.getOrDefault(to, 0);
            Fact fact = new Fact(Kind.EDGE, image.property(), from, to);
            if (appears) {
                targets.put(to, count + 1);
                if (count == 0) {
                    relation.in.computeIfAbsent(to, k -> new HashSet<>()).add(from);
                    appeared(fact);
                }
            } else if (count == 1) {
                went(fact);
                targets.remove(to);
                if (targets.isEmpty()) {
                    relation.out.remove(from);
                }
                Set<OWLNamedIndividual> sources = relation.in.get(to);
                sources.remove(from);
                if (sources.isEmpty()) {
                    relation.in.remove(to);
                }
            } else if (count > 1) {
                targets.put(to, count - 1);
            }
        }
    }

    private void value(OWLDataProperty property, OWLNamedIndividual subject, DataValue value, boolean appears) {
        for (OWLDataProperty image : program.imagesOf(property)) {
            valueOf(image, subject, value, appears);
        }
    }

    /** A value of a kept property that appeared or went. */
    private void valueOf(OWLDataProperty image, OWLNamedIndividual subject, DataValue value, boolean appears) {
        Map<OWLNamedIndividual, Map<DataValue, Integer>> bySubject = values.get(image);
        Map<DataValue, Integer> held = bySubject.computeIfAbsent(subject, k -> new LinkedHashMap<>());
        int count = held.getOrDefault(value, 0);
        Fact fact = new Fact(Kind.VALUE, image, subject, value);
        if (appears) {
            if (count == 0) {
                // A value asserted twice (two literals of one value) is kept with the first literal.
                held.put(value, 1);
                ordered.get(image).add(subject, value);
                appeared(fact);
            } else {
                held.put(value, count + 1);
            }
        } else if (count == 1) {
            went(fact);
            held.remove(value);
            ordered.get(image).remove(subject, value);
            if (held.isEmpty()) {
                bySubject.remove(subject);
            }
        } else if (count > 1) {
            held.put(value, count - 1);
        }
    }

    /** A fact now in the store: the matches it completes are counted. */
    private void appeared(Fact fact) {
        for (Match match : matchesWith(fact)) {
            for (Fact conclusion : conclusions(match)) {
                int count = support.getOrDefault(conclusion, 0);
                support.put(conclusion, count + 1);
                if (count == 0) {
                    heldBefore.putIfAbsent(conclusion, false);
                    concluded(conclusion, true);
                }
            }
        }
    }

    /** A fact about to leave the store: the matches it was part of are uncounted. */
    private void went(Fact fact) {
        for (Match match : matchesWith(fact)) {
            for (Fact conclusion : conclusions(match)) {
                int count = support.get(conclusion);
                if (count == 1) {
                    support.remove(conclusion);
                    heldBefore.putIfAbsent(conclusion, true);
                    concluded(conclusion, false);
                } else {
                    support.put(conclusion, count - 1);
                }
            }
        }
    }

    /** A conclusion that appeared or went: an edge or value concluded is read like an asserted one. */
    private void concluded(Fact conclusion, boolean appears) {
        if (appears) {
            conclusionsAbout.computeIfAbsent(conclusion.subject, k -> new LinkedHashSet<>()).add(conclusion);
            if (conclusion.object instanceof OWLNamedIndividual object) {
                conclusionsAbout.computeIfAbsent(object, k -> new LinkedHashSet<>()).add(conclusion);
            }
        } else {
            forget(conclusion.subject, conclusion);
            if (conclusion.object instanceof OWLNamedIndividual object) {
                forget(object, conclusion);
            }
        }
        if (conclusion.kind == Kind.EDGE) {
            edge((OWLObjectProperty) conclusion.predicate, conclusion.subject, (OWLNamedIndividual) conclusion.object,
                    appears);
        } else if (conclusion.kind == Kind.VALUE) {
            value((OWLDataProperty) conclusion.predicate, conclusion.subject, (DataValue) conclusion.object, appears);
        }
    }

    private void forget(OWLNamedIndividual individual, Fact conclusion) {
        Set<Fact> about = conclusionsAbout.get(individual);
        if (about != null) {
            about.remove(conclusion);
            if (about.isEmpty()) {
                conclusionsAbout.remove(individual);
            }
        }
    }

    /** Whether the rules concluded anything about the individual that the modules must reason with. */
    boolean concludedAbout(OWLNamedIndividual individual) {
        Set<Fact> about = conclusionsAbout.get(individual);
        return about != null && about.stream().anyMatch(f -> program.seenBySchema(f.predicate));
    }

    /**
     * The conclusions about a member of a module, as assertions the module is reasoned on with:
     * an edge to an individual outside the module becomes what it says about this end (as
     * {@link AboxModules#axiomsOf} does with asserted ones; such a property does not link).
     */
    List<OWLAxiom> conclusionsAbout(OWLNamedIndividual individual, Set<OWLIndividual> module) {
        List<OWLAxiom> axioms = new ArrayList<>();
        for (Fact fact : conclusionsAbout.getOrDefault(individual, Set.of())) {
            if (!program.seenBySchema(fact.predicate)) {
                continue;
            }
            switch (fact.kind) {
                case CLASS -> axioms.add(factory.getOWLClassAssertionAxiom((OWLClass) fact.predicate, individual));
                case VALUE -> axioms.add(factory.getOWLDataPropertyAssertionAxiom((OWLDataProperty) fact.predicate,
                        individual, ((DataValue) fact.object).literal));
                default -> {
                    OWLObjectProperty property = (OWLObjectProperty) fact.predicate;
                    OWLNamedIndividual object = (OWLNamedIndividual) fact.object;
                    if (module.contains(fact.subject) && module.contains(object)) {
                        axioms.add(factory.getOWLObjectPropertyAssertionAxiom(property, fact.subject, object));
                    } else {
                        OWLObjectPropertyExpression end = fact.subject.equals(individual) ? property
                                : property.getInverseProperty();
                        axioms.add(factory.getOWLClassAssertionAxiom(factory.getOWLObjectSomeValuesFrom(end,
                                factory.getOWLThing()), individual));
                    }
                }
            }
        }
        return axioms;
    }

    /** The individuals related to {@code individual} by a property the engine keeps, or null when it keeps none such. */
    Set<OWLNamedIndividual> objectValues(OWLNamedIndividual individual, OWLObjectPropertyExpression property) {
        Relation relation = edges.get(property.getNamedProperty());
        if (relation == null) {
            return null;
        }
        if (property.isAnonymous()) {
            return Set.copyOf(relation.in.getOrDefault(individual, Set.of()));
        }
        return Set.copyOf(relation.out.getOrDefault(individual, Map.of()).keySet());
    }

    /** The conclusions held now (for tests and the log). */
    int conclusions() {
        return support.size();
    }

    /** Every match of a rule body that uses the fact, each once. */
    private Set<Match> matchesWith(Fact fact) {
        Set<Match> found = new LinkedHashSet<>();
        List<Rule> rules = program.rules;
        for (int r = 0; r < rules.size(); r++) {
            Rule rule = rules.get(r);
            for (int position = 0; position < rule.body().size(); position++) {
                Atom atom = rule.body().get(position);
                if (atom.kind() != fact.kind || !atom.predicate().equals(fact.predicate)) {
                    continue;
                }
                Object[] binding = new Object[rule.variables()];
                if (unify(atom.term(0), fact.subject, binding)
                        && (fact.kind == Kind.CLASS || unify(atom.term(1), fact.object, binding))) {
                    join(r, rule, rule.plans()[position], 0, binding, null, found);
                }
            }
        }
        return found;
    }

    private static boolean unify(Term term, Object value, Object[] binding) {
        if (!term.isVariable()) {
            return term.constant().equals(value);
        }
        Object bound = binding[term.variable()];
        if (bound == null) {
            binding[term.variable()] = value;
            return true;
        }
        return bound.equals(value);
    }

    private static Object resolve(Term term, Object[] binding) {
        return term.isVariable() ? binding[term.variable()] : term.constant();
    }

    /** Whether a complete match rests on individuals not asserted different: then an obstacle, said once. */
    private boolean undecided(String unsure) {
        if (unsure != null && obstacle == null) {
            obstacle = "a SWRL rule's DifferentIndividuals atom matched individuals not asserted different ("
                    + unsure + ")";
        }
        return unsure != null;
    }

    /**
     * Joins the atoms of {@code plan} from {@code step} on; {@code unsure} names a pair a
     * DifferentIndividuals atom could not decide (a complete match with one is an obstacle).
     */
    private void join(int ruleNumber, Rule rule, int[] plan, int step, Object[] binding, String unsure,
                      Set<Match> found) {
        if (step == plan.length) {
            if (undecided(unsure)) {
                return;
            }
            found.add(new Match(ruleNumber, Arrays.asList(binding.clone())));
            return;
        }
        joinOne(rule, plan[step], binding, unsure, (bound, stillUnsure) -> join(ruleNumber, rule, plan, step + 1, bound,
                stillUnsure, found));
    }

    /** What continues a join once an atom matched: the binding (reset after the call) and an undecided pair. */
    private interface Next {
        void accept(Object[] binding, String unsure);
    }

    /**
     * Matches one atom of a rule's body on the binding, calling {@code next} once per way it
     * matches. A join only reads the store (matches are collected, then counted), so it walks the
     * store's own collections.
     */
    private void joinOne(Rule rule, int index, Object[] binding, String unsure, Next next) {
        Atom atom = rule.body().get(index);
        switch (atom.kind()) {
            case CLASS -> {
                Object value = resolve(atom.term(0), binding);
                if (value != null) {
                    if (value instanceof OWLNamedIndividual individual
                            && typesOf.getOrDefault(individual, Set.of()).contains((OWLClass) atom.predicate())) {
                        next.accept(binding, unsure);
                    }
                    return;
                }
                for (OWLNamedIndividual individual : typed.get((OWLClass) atom.predicate())) {
                    binding[atom.term(0).variable()] = individual;
                    next.accept(binding, unsure);
                }
                binding[atom.term(0).variable()] = null;
            }
            case EDGE -> joinEdge(binding, unsure, next, atom);
            case VALUE -> joinValue(binding, unsure, next, atom);
            case BUILTIN -> {
                IRI builtin = (IRI) atom.predicate();
                Term[] terms = atom.terms();
                if (Builtins.binds(builtin)) {
                    DataValue[] operands = new DataValue[terms.length - 1];
                    for (int i = 1; i < terms.length; i++) {
                        if (!(resolve(terms[i], binding) instanceof DataValue operand)) {
                            return;
                        }
                        operands[i - 1] = operand;
                    }
                    DataValue result = Builtins.compute(builtin, operands);
                    if (result == null) {
                        return;
                    }
                    Object bound = resolve(terms[0], binding);
                    if (bound == null) {
                        binding[terms[0].variable()] = result;
                        next.accept(binding, unsure);
                        binding[terms[0].variable()] = null;
                    } else if (result.equals(bound)) {
                        next.accept(binding, unsure);
                    }
                } else if (resolve(terms[0], binding) instanceof DataValue left
                        && resolve(terms[1], binding) instanceof DataValue right && Builtins.test(builtin, left, right)) {
                    next.accept(binding, unsure);
                }
            }
            case SAME -> {
                if (resolve(atom.term(0), binding).equals(resolve(atom.term(1), binding))) {
                    next.accept(binding, unsure);
                }
            }
            case DIFFERENT -> {
                Object first = resolve(atom.term(0), binding);
                Object second = resolve(atom.term(1), binding);
                if (first.equals(second)) {
                    return;
                }
                boolean asserted = differentSets.getOrDefault(first, List.of()).stream()
                        .anyMatch(set -> set.contains(second));
                next.accept(binding, asserted || unsure != null ? unsure : first + " and " + second);
            }
        }
    }

    /** Matches the object of an atom whose subject is bound: {@code held} are the subject's objects. */
    private static void objectsOf(Set<?> held, Atom atom, Object object, Object[] binding, String unsure, Next next) {
        if (object != null) {
            if (held.contains(object)) {
                next.accept(binding, unsure);
            }
            return;
        }
        for (Object each : held) {
            binding[atom.term(1).variable()] = each;
            next.accept(binding, unsure);
        }
        binding[atom.term(1).variable()] = null;
    }

    private void joinEdge(Object[] binding, String unsure, Next next, Atom atom) {
        Relation relation = edges.get((OWLObjectProperty) atom.predicate());
        Object subject = resolve(atom.term(0), binding);
        Object object = resolve(atom.term(1), binding);
        if (subject != null) {
            objectsOf(relation.out.getOrDefault(subject, Map.of()).keySet(), atom, object, binding, unsure, next);
            return;
        }
        if (object != null) {
            for (OWLNamedIndividual source : relation.in.getOrDefault(object, Set.of())) {
                binding[atom.term(0).variable()] = source;
                next.accept(binding, unsure);
            }
            binding[atom.term(0).variable()] = null;
            return;
        }
        boolean loop = atom.term(0).variable() == atom.term(1).variable();
        for (Map.Entry<OWLNamedIndividual, Map<OWLNamedIndividual, Integer>> entry
                : relation.out.entrySet()) {
            binding[atom.term(0).variable()] = entry.getKey();
            for (OWLNamedIndividual target : entry.getValue().keySet()) {
                if (loop && !target.equals(entry.getKey())) {
                    continue;
                }
                binding[atom.term(1).variable()] = target;
                next.accept(binding, unsure);
            }
        }
        binding[atom.term(0).variable()] = null;
        binding[atom.term(1).variable()] = null;
    }

    private void joinValue(Object[] binding, String unsure, Next next, Atom atom) {
        Map<OWLNamedIndividual, Map<DataValue, Integer>> bySubject = values.get((OWLDataProperty) atom.predicate());
        Object subject = resolve(atom.term(0), binding);
        Object value = resolve(atom.term(1), binding);
        if (subject != null) {
            objectsOf(bySubject.getOrDefault(subject, Map.of()).keySet(), atom, value, binding, unsure, next);
            return;
        }
        for (Map.Entry<OWLNamedIndividual, Map<DataValue, Integer>> entry : bySubject.entrySet()) {
            binding[atom.term(0).variable()] = entry.getKey();
            for (DataValue each : entry.getValue().keySet()) {
                if (value != null && !value.equals(each)) {
                    continue;
                }
                if (value == null) {
                    binding[atom.term(1).variable()] = each;
                }
                next.accept(binding, unsure);
            }
        }
        binding[atom.term(0).variable()] = null;
        if (value == null) {
            binding[atom.term(1).variable()] = null;
        }
    }

    /** The conclusions of a match: its rule's head, with the match's values. */
    private List<Fact> conclusions(Match match) {
        Rule rule = program.rules.get(match.rule);
        Object[] binding = match.binding.toArray();
        List<Fact> facts = new ArrayList<>(rule.head().size());
        for (Atom atom : rule.head()) {
            if (!(resolve(atom.term(0), binding) instanceof OWLNamedIndividual subject)) {
                continue;
            }
            Object object = atom.kind() == Kind.CLASS ? null : resolve(atom.term(1), binding);
            if (atom.kind() == Kind.VALUE && !(object instanceof DataValue value && value.literal != null)
                    || atom.kind() == Kind.EDGE && !(object instanceof OWLNamedIndividual)) {
                continue;
            }
            facts.add(new Fact(atom.kind(), atom.predicate(), subject, object));
        }
        return facts;
    }
}
