// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.AboxModules.Module;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLDeclarationAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.util.OWLObjectDuplicator;

/**
 * Members of a module that its assertions cannot tell apart: five cups asserted Cup and inside
 * the same drawer, robots of one kind in one room. Such twins have the same types, and the
 * module reasoned on with one of them stands for the module with all of them, so a drawer with
 * five cups is reasoned on as a drawer with one, and shares that result with every drawer of
 * one cup.
 *
 * <p>Why it is exact. Twins t and r have the same assertions but for themselves, and no
 * assertion names both. Dropping t's assertions leaves A' ⊆ A, so every consequence of A' is one
 * of A; and a model of A' with t read as r is a model of A, since each assertion of t becomes one
 * of r and the schema names neither (the hub's individuals are never members here). So A and A'
 * are consistent together and give r the same types; swapping t and r maps A onto itself, so t
 * has r's types. There is no unique-name assumption to break: without a DifferentIndividuals
 * axiom between them (which names both, so they are not twins), t and r may be one element, and
 * nothing counted (a cardinality) can tell the five cups from the one. The step repeats on what
 * is left, since merging leaves can make their containers twins.
 */
final class ModuleTwins {
    private static final String SELF = "urn:armor:reasoning#self";
    /** Rounds of merging at most: each collapses one more level of a tree of look-alikes. */
    private static final int ROUNDS = 8;

    /** The module's assertions with twins dropped, the members kept, and each dropped member's kept twin. */
    record Collapsed(Set<OWLAxiom> axioms, List<OWLNamedIndividual> kept, Map<OWLNamedIndividual, OWLNamedIndividual> twinOf) {
        /** The types found for the kept members, given to every member. */
        <T> Map<OWLNamedIndividual, T> spread(Map<OWLNamedIndividual, T> ofKept) {
            if (twinOf.isEmpty()) {
                return ofKept;
            }
            Map<OWLNamedIndividual, T> all = new LinkedHashMap<>(ofKept);
            twinOf.forEach((dropped, kept) -> all.put(dropped, ofKept.get(kept)));
            return all;
        }
    }

    private final OWLOntologyManager manager;

    ModuleTwins(OWLOntologyManager manager) {
        this.manager = manager;
    }

    /** The module with its twins collapsed (all named members kept when there are none, or an individual is anonymous). */
    Collapsed collapse(Module module, Set<OWLAxiom> axioms) {
        List<OWLNamedIndividual> kept = new ArrayList<>(module.namedMembers().toList());
        if (kept.size() < 2 || kept.size() != module.members.size()) {
            return new Collapsed(axioms, kept, Map.of());
        }
        Map<OWLNamedIndividual, OWLNamedIndividual> twinOf = new HashMap<>();
        Set<OWLAxiom> left = axioms;
        for (int round = 0; round < ROUNDS; round++) {
            Map<OWLNamedIndividual, OWLNamedIndividual> merged = twinsIn(left, new HashSet<>(kept));
            if (merged.isEmpty()) {
                break;
            }
            twinOf.replaceAll((dropped, keeper) -> merged.getOrDefault(keeper, keeper));
            twinOf.putAll(merged);
            kept.removeAll(merged.keySet());
            Set<OWLAxiom> remaining = new LinkedHashSet<>();
            for (OWLAxiom axiom : left) {
                if (AboxLinks.individualsOf(axiom).noneMatch(merged::containsKey)) {
                    remaining.add(axiom);
                }
            }
            left = remaining;
        }
        return new Collapsed(left, List.copyOf(kept), Map.copyOf(twinOf));
    }

    /** Each member with a twin (but the first of its look-alikes by IRI) mapped to that first one. */
    private Map<OWLNamedIndividual, OWLNamedIndividual> twinsIn(Set<OWLAxiom> axioms, Set<OWLNamedIndividual> members) {
        Map<OWLNamedIndividual, Set<OWLAxiom>> patterns = new HashMap<>();
        members.forEach(member -> patterns.put(member, new HashSet<>()));
        Map<OWLNamedIndividual, OWLObjectDuplicator> asSelf = new HashMap<>();
        for (OWLAxiom axiom : axioms) {
            if (axiom instanceof OWLDeclarationAxiom) {
                continue;
            }
            AboxLinks.individualsOf(axiom).distinct().forEach(individual -> {
                if (individual instanceof OWLNamedIndividual member && members.contains(member)) {
                    patterns.get(member).add(asSelf.computeIfAbsent(member, this::renamingToSelf).duplicateObject(axiom));
                }
            });
        }
        Map<Set<OWLAxiom>, List<OWLNamedIndividual>> alike = new HashMap<>();
        patterns.forEach((member, pattern) -> alike.computeIfAbsent(pattern, k -> new ArrayList<>()).add(member));
        Map<OWLNamedIndividual, OWLNamedIndividual> merged = new HashMap<>();
        for (Map.Entry<Set<OWLAxiom>, List<OWLNamedIndividual>> group : alike.entrySet()) {
            List<OWLNamedIndividual> twins = group.getValue();
            if (twins.size() < 2 || namesAny(group.getKey(), twins)) {
                continue;
            }
            twins.sort(Comparator.comparing(member -> member.getIRI().toString()));
            twins.subList(1, twins.size()).forEach(twin -> merged.put(twin, twins.get(0)));
        }
        return merged;
    }

    private OWLObjectDuplicator renamingToSelf(OWLNamedIndividual member) {
        Map<OWLEntity, IRI> renaming = Map.of(member, IRI.create(SELF));
        return new OWLObjectDuplicator(renaming, manager);
    }

    /** Whether a pattern names one of the look-alikes (then they are tied to each other, not twins). */
    private static boolean namesAny(Set<OWLAxiom> pattern, List<OWLNamedIndividual> lookAlikes) {
        Set<OWLIndividual> group = new HashSet<>(lookAlikes);
        return pattern.stream().flatMap(AboxLinks::individualsOf).anyMatch(group::contains);
    }
}
