// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.reasoner.NodeSet;
import org.semanticweb.owlapi.reasoner.impl.OWLClassNode;
import org.semanticweb.owlapi.reasoner.impl.OWLClassNodeSet;

/**
 * The types a reasoner found for one individual, as it answered them: all of them and the most
 * specific ones, each as nodes of equivalent classes. Individuals of one kind share one profile
 * (see {@link Interner}), so ten thousand robots cost one profile, not ten thousand.
 *
 * <p>A profile of a reference over an upper ontology may be partial: it then holds owl:Thing and
 * the classes the reference realises against ({@link RealisationScope}) that the individual
 * belongs to, nothing about other classes, and no most specific classes.
 *
 * @param all      every named class of the individual (owl:Thing included), by equivalence node
 * @param direct   its most specific named classes, by equivalence node
 * @param complete whether {@code all} holds every class (else only the realised ones it has)
 */
record TypeProfile(Set<Set<OWLClass>> all, Set<Set<OWLClass>> direct, boolean complete) {

    TypeProfile(Set<Set<OWLClass>> all, Set<Set<OWLClass>> direct) {
        this(all, direct, true);
    }

    static TypeProfile of(NodeSet<OWLClass> all, NodeSet<OWLClass> direct) {
        return new TypeProfile(nodes(all), nodes(direct));
    }

    /** The classes among those realised that an individual belongs to, and owl:Thing. */
    static TypeProfile partial(Set<OWLClass> memberOf, OWLClass thing) {
        Set<Set<OWLClass>> all = new java.util.HashSet<>();
        all.add(Set.of(thing));
        memberOf.forEach(owlClass -> all.add(Set.of(owlClass)));
        return new TypeProfile(Set.copyOf(all), Set.of(), false);
    }

    private static Set<Set<OWLClass>> nodes(NodeSet<OWLClass> nodeSet) {
        return nodeSet.nodes().map(node -> Set.copyOf(node.entities().collect(Collectors.toSet())))
                .collect(Collectors.toUnmodifiableSet());
    }

    boolean has(OWLClass owlClass, boolean directly) {
        for (Set<OWLClass> node : directly ? direct : all) {
            if (node.contains(owlClass)) {
                return true;
            }
        }
        return false;
    }

    NodeSet<OWLClass> nodeSet(boolean directly) {
        OWLClassNodeSet nodeSet = new OWLClassNodeSet();
        for (Set<OWLClass> node : directly ? direct : all) {
            nodeSet.addNode(new OWLClassNode(node));
        }
        return nodeSet;
    }

    /** One shared instance per distinct profile; its memory is the writer's, dropped with the schema. */
    static final class Interner {
        private final Map<TypeProfile, TypeProfile> known = new HashMap<>();

        TypeProfile intern(TypeProfile profile) {
            return known.computeIfAbsent(profile, p -> p);
        }
    }
}
