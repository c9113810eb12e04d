// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Why a scene is an instance of a scene class: for each restriction of the class, the relations
 * of the scene that meet it ("CONE#2 left of SPHERE#1") and how many distinct elements they
 * count against the restriction's minimum.
 */
public final class Explanation {
    private Explanation() {}

    /** One restriction and what in the scene meets it. */
    public record Match(SceneDefinition.Restriction restriction, int counted, List<String> relations) {
        public boolean met() {
            return counted >= restriction.min();
        }
    }

    public static List<Match> of(Scene scene, List<SpatialRelations.Fact> facts, SceneDefinition definition) {
        List<Match> matches = new ArrayList<>();
        List<SceneElement> elements = scene.elements();
        for (SceneDefinition.Restriction restriction : definition.restrictions()) {
            Set<Integer> objects = new LinkedHashSet<>();
            List<String> relations = new ArrayList<>();
            for (SpatialRelations.Fact fact : facts) {
                SceneElement subject = elements.get(fact.subject());
                SceneElement object = elements.get(fact.object());
                if (fact.relation() == restriction.property().relation()
                        && subject.shape() == restriction.property().subject() && object.shape() == restriction.type()) {
                    objects.add(fact.object());
                    relations.add(object.label() + " " + fact.relation().fromObject() + " " + subject.label());
                }
            }
            matches.add(new Match(restriction, objects.size(), List.copyOf(relations)));
        }
        return matches;
    }
}
