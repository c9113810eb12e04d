// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLOntology;

/**
 * The learned scene classes of a reference (subclasses of SCENE stated equivalent to a scene
 * definition) and where the reasoner places them: each under the scenes it contains, that is,
 * the learned classes it is a subclass of, nearest first.
 *
 * <p>In a plain reference whose primitives stay pairwise disjoint and apart, one learned class is
 * a subclass of another exactly when it requires at least as many elements for each (property,
 * type) the other requires ({@link LearnedScenes#subsumes}): that is compared directly, since a
 * reasoner classifying a thousand such classes takes minutes. Elsewhere the reference's reasoner
 * is asked.
 */
final class SceneHierarchy {
    private SceneHierarchy() {}

    /** A learned class with its definition, its nearest learned superclasses and its equivalent learned classes. */
    record Placed(OWLClass owlClass, SceneDefinition definition, Set<OWLClass> parents, Set<OWLClass> equivalents) {}

    static List<Placed> of(SceneReference reference) {
        OWLOntology ontology = reference.ontology();
        SceneVocabulary vocabulary = new SceneVocabulary(reference);
        Map<OWLClass, SceneDefinition> learned = new LinkedHashMap<>();
        if (!vocabulary.known(vocabulary.scene())) {
            return List.of();
        }
        LearnedScenes scenes = LearnedScenes.of(reference, vocabulary.scene());
        scenes.classes().forEach(each -> learned.put(each.owlClass(), each.definition()));
        boolean compared = scenes.plain() && SceneSchema.of(reference, vocabulary, scenes).shapesApart();
        Map<OWLClass, Set<OWLClass>> above = new LinkedHashMap<>();
        Map<OWLClass, Set<OWLClass>> same = new LinkedHashMap<>();
        for (LearnedScenes.Learned each : scenes.classes()) {
            if (Thread.interrupted()) {
                throw new IllegalStateException("interrupted while placing the scene classes");
            }
            OWLClass owlClass = each.owlClass();
            Set<OWLClass> equivalents = new LinkedHashSet<>();
            Set<OWLClass> supers = new LinkedHashSet<>();
            if (compared) {
                for (LearnedScenes.Learned other : scenes.classes()) {
                    if (other != each && scenes.subsumes(other, each)) {
                        (scenes.subsumes(each, other) ? equivalents : supers).add(other.owlClass());
                    }
                }
            } else {
                equivalents.addAll(reference.equivalentClasses(owlClass));
                equivalents.retainAll(learned.keySet());
                supers.addAll(reference.superClasses(owlClass));
                supers.retainAll(learned.keySet());
                supers.removeAll(equivalents);
                supers.remove(owlClass);
            }
            above.put(owlClass, supers);
            same.put(owlClass, equivalents);
        }
        List<Placed> placed = new ArrayList<>();
        for (Map.Entry<OWLClass, SceneDefinition> entry : learned.entrySet()) {
            Set<OWLClass> supers = above.get(entry.getKey());
            Set<OWLClass> nearest = new LinkedHashSet<>();
            for (OWLClass candidate : supers) {
                boolean throughAnother = supers.stream().anyMatch(other -> !other.equals(candidate)
                        && !same.get(other).contains(candidate) && above.get(other).contains(candidate));
                if (!throughAnother) {
                    nearest.add(candidate);
                }
            }
            placed.add(new Placed(entry.getKey(), entry.getValue(), nearest, same.get(entry.getKey())));
        }
        return placed;
    }
}
