// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * One assertion on a scene: {@code property(scene, object)}, property being a relation from an
 * element of a type ({@code rightSPHERE}). Relations of two subjects of the same type to the same
 * object make one assertion: the scene's cardinality counts these.
 */
public record SceneAssertion(Relation.Property property, int object) {
    /** The distinct assertions the facts make, in the facts' order. */
    public static List<SceneAssertion> of(Scene scene, List<SpatialRelations.Fact> facts) {
        Set<SceneAssertion> assertions = new LinkedHashSet<>();
        for (SpatialRelations.Fact fact : facts) {
            Shape subject = scene.elements().get(fact.subject()).shape();
            assertions.add(new SceneAssertion(new Relation.Property(fact.relation(), subject), fact.object()));
        }
        return new ArrayList<>(assertions);
    }
}
