// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Every relation that holds between the elements of a scene, tested on each ordered pair of
 * distinct elements (d, r) with the scene's two thresholds (docs/scenes.md, the table of
 * relations). Left, front and below are the inverses of right, behind and above, never a second
 * name for the same direction.
 */
public final class SpatialRelations {
    private SpatialRelations() {}

    /** {@code relation(subject, object)}: elements as indexes into the scene's list. */
    public record Fact(Relation relation, int subject, int object) {}

    /** The facts, each once, in a stable order (by pair, then by relation). */
    public static List<Fact> of(Scene scene) {
        List<SceneElement> elements = scene.elements();
        Set<Fact> facts = new LinkedHashSet<>();
        double near = scene.position();
        for (int d = 0; d < elements.size(); d++) {
            if (Thread.interrupted()) {
                throw new IllegalStateException("interrupted while relating the scene's elements");
            }
            for (int r = 0; r < elements.size(); r++) {
                if (d == r) {
                    continue;
                }
                SceneElement a = elements.get(d);
                SceneElement b = elements.get(r);
                double dx = a.x() - b.x();
                double dy = a.y() - b.y();
                double dz = a.z() - b.z();
                directional(facts, dy >= near, Relation.RIGHT, Relation.LEFT, d, r);
                directional(facts, dx >= near, Relation.BEHIND, Relation.FRONT, d, r);
                directional(facts, dz >= near, Relation.ABOVE, Relation.BELOW, d, r);
                symmetric(facts, Math.abs(dy) <= near && Math.abs(dz) <= near, Relation.ALONG_X, d, r);
                symmetric(facts, Math.abs(dx) <= near && Math.abs(dz) <= near, Relation.ALONG_Y, d, r);
                symmetric(facts, Math.abs(dx) <= near && Math.abs(dy) <= near, Relation.ALONG_Z, d, r);
                if (a.hasAxis() && b.hasAxis()) {
                    symmetric(facts, parallel(a.axis(), b.axis(), scene.axis()), Relation.PARALLEL, d, r);
                    symmetric(facts, Math.abs(dot(a.axis(), b.axis())) <= scene.axis(), Relation.PERPENDICULAR, d, r);
                }
                if (a.hasAxis() && squaredDistanceToAxis(b.centre(), a.centre(), a.axis()) <= scene.axis()) {
                    facts.add(new Fact(Relation.COAXIAL, d, r));
                    facts.add(new Fact(Relation.COAXIAL, r, d));
                }
            }
        }
        return new ArrayList<>(facts);
    }

    private static void directional(Set<Fact> facts, boolean holds, Relation relation, Relation inverse, int d, int r) {
        if (holds) {
            facts.add(new Fact(relation, d, r));
            facts.add(new Fact(inverse, r, d));
        }
    }

    private static void symmetric(Set<Fact> facts, boolean holds, Relation relation, int d, int r) {
        if (holds) {
            facts.add(new Fact(relation, d, r));
            facts.add(new Fact(relation, r, d));
        }
    }

    /** Every component of the cross product within the threshold. */
    static boolean parallel(double[] a, double[] b, double threshold) {
        double[] cross = cross(a, b);
        return Math.abs(cross[0]) <= threshold && Math.abs(cross[1]) <= threshold && Math.abs(cross[2]) <= threshold;
    }

    /** The squared distance from {@code point} to the line through {@code origin} along {@code direction}. */
    static double squaredDistanceToAxis(double[] point, double[] origin, double[] direction) {
        double[] offset = {point[0] - origin[0], point[1] - origin[1], point[2] - origin[2]};
        double[] cross = cross(offset, direction);
        return dot(cross, cross) / dot(direction, direction);
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
}
