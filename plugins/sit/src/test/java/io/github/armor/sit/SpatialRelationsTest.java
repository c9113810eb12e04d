// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** The table of relations (docs/scenes.md), the scene's assertions and the learned definition, without a reasoner. */
class SpatialRelationsTest {
    private static Scene scene(String elements) {
        return Scene.parse(elements, "0.03", "0.05");
    }

    private static Set<String> facts(Scene scene) {
        return SpatialRelations.of(scene).stream()
                .map(f -> f.relation().word() + "(" + (f.subject() + 1) + "," + (f.object() + 1) + ")")
                .collect(Collectors.toSet());
    }

    @Test
    void leftFrontAndBelowAreTheInversesOfRightBehindAndAbove() {
        // 2 is right of, behind and above 1, by more than the threshold in each direction.
        assertEquals(Set.of("right(2,1)", "left(1,2)", "behind(2,1)", "front(1,2)", "above(2,1)", "below(1,2)"),
                facts(scene("SPHERE 0 0 0; SPHERE 0.1 0.1 0.1")));
    }

    @Test
    void directionsNeedTheThresholdAndAlongNeedsTheOtherTwoWithinIt() {
        // dx 0.02: not behind; dy, dz 0: along X, along Y (dx <= 0.03 and dz <= 0.03), along Z.
        assertEquals(Set.of("alongX(1,2)", "alongX(2,1)", "alongY(1,2)", "alongY(2,1)", "alongZ(1,2)", "alongZ(2,1)"),
                facts(scene("SPHERE 0 0 0; SPHERE 0.02 0 0")));
        // Exactly the threshold counts (>= and <=); the decimal difference of 0.03 is 0.03 here.
        assertTrue(facts(scene("SPHERE 0 0 0; SPHERE 0 0 0.03"))
                .containsAll(Set.of("above(2,1)", "below(1,2)", "alongZ(1,2)")));
    }

    @Test
    void axesGiveParallelPerpendicularAndCoaxial() {
        // Two cylinders stacked on one vertical axis: parallel, coaxial both ways, along Z, above/below.
        Set<String> stacked = facts(scene("CYLINDER 0 0 0 0 0 1; CYLINDER 0 0 0.5 0 0 2"));
        assertEquals(Set.of("parallel(1,2)", "parallel(2,1)", "coaxial(1,2)", "coaxial(2,1)", "alongZ(1,2)",
                "alongZ(2,1)", "above(2,1)", "below(1,2)"), stacked);
        // A plane and a cone at right angles, far apart: perpendicular only (and directions).
        Set<String> crossed = facts(scene("PLANE 0 0 0 0 0 1; CONE 1 0 0 1 0 0"));
        assertTrue(crossed.containsAll(Set.of("perpendicular(1,2)", "perpendicular(2,1)")), crossed.toString());
        assertFalse(crossed.contains("parallel(1,2)"));
        // A sphere on a cone's axis: coaxial(cone, sphere) and back; a sphere has no axis of its own.
        Set<String> onAxis = facts(scene("CONE 0 0 0 0 0 1; SPHERE 0.1 0 2"));
        assertTrue(onAxis.containsAll(Set.of("coaxial(1,2)", "coaxial(2,1)")), onAxis.toString());
        assertFalse(facts(scene("CONE 0 0 0 0 0 1; SPHERE 0.3 0 2")).contains("coaxial(1,2)"));
        // Without its axis a cone is related by position only.
        assertEquals(Set.of(), facts(scene("CONE 0 0 0; CONE 1 0 0")).stream()
                .filter(f -> f.startsWith("parallel") || f.startsWith("perpendicular") || f.startsWith("coaxial"))
                .collect(Collectors.toSet()));
    }

    @Test
    void theTwoConesOfTheSpecificationGiveCardinalitySixAndTheirDefinition() {
        Scene cones = scene("CONE 0 0 0 0 0 1; CONE 1 0 0 0.5 0.5 0");
        List<SpatialRelations.Fact> facts = SpatialRelations.of(cones);
        assertEquals(Set.of("alongX(1,2)", "alongX(2,1)", "perpendicular(1,2)", "perpendicular(2,1)", "behind(2,1)",
                "front(1,2)"), facts(cones));
        assertEquals(6, SceneAssertion.of(cones, facts).size());
        SceneDefinition definition = SceneDefinition.of(cones, facts);
        assertEquals(6, definition.cardinality());
        assertEquals(Set.of("alongXCONE min 2 CONE", "perpendicularCONE min 2 CONE", "behindCONE min 1 CONE",
                        "frontCONE min 1 CONE"),
                definition.restrictions().stream().map(r -> r.property().name() + " min " + r.min() + " " + r.type())
                        .collect(Collectors.toSet()));
        assertTrue(definition.words().contains("at least 2 CONE along X"), definition.words());
        assertTrue(definition.words().contains("at least 1 CONE in front of a CONE"), definition.words());
    }

    @Test
    void cardinalityCountsDistinctElementsNotRelations() {
        // Spheres 1 and 2 both right of the cone: rightSPHERE(scene, cone) once.
        Scene scene = scene("CONE 0 0 0; SPHERE 0 0.5 0; SPHERE 0.5 0.5 0.5");
        SceneDefinition definition = SceneDefinition.of(scene, SpatialRelations.of(scene));
        SceneDefinition.Restriction right = definition.restrictions().stream()
                .filter(r -> r.property().name().equals("rightSPHERE") && r.type() == Shape.CONE).findFirst().orElseThrow();
        assertEquals(1, right.min());
        SceneDefinition.Restriction left = definition.restrictions().stream()
                .filter(r -> r.property().name().equals("leftCONE") && r.type() == Shape.SPHERE).findFirst().orElseThrow();
        assertEquals(2, left.min());
        assertEquals("at least 2 SPHERE right of a CONE", left.words());
    }

    @Test
    void malformedElementsAreRefusedWithTheirReason() {
        assertEquals(InvalidScene.Kind.SHAPE, assertThrows(InvalidScene.class, () -> scene("CUBE 0 0 0")).kind());
        assertEquals(InvalidScene.Kind.SHAPE, assertThrows(InvalidScene.class, () -> scene("SPHERE 0 0 0 0 0 1")).kind());
        assertEquals(InvalidScene.Kind.SHAPE, assertThrows(InvalidScene.class, () -> scene("CONE 0 0 0 1")).kind());
        assertEquals(InvalidScene.Kind.SHAPE, assertThrows(InvalidScene.class, () -> scene("PLANE 0 0")).kind());
        assertEquals(InvalidScene.Kind.SHAPE, assertThrows(InvalidScene.class, () -> scene(" ; ")).kind());
        assertEquals(InvalidScene.Kind.VALUE, assertThrows(InvalidScene.class, () -> scene("SPHERE 0 NaN 0")).kind());
        assertEquals(InvalidScene.Kind.VALUE,
                assertThrows(InvalidScene.class, () -> scene("[{\"type\": \"SPHERE\", \"features\": [0, Infinity, 0]}]")).kind());
        assertEquals(InvalidScene.Kind.VALUE, assertThrows(InvalidScene.class, () -> scene("CONE 0 0 0 0 0 0")).kind());
        assertEquals(InvalidScene.Kind.TOO_LARGE, assertThrows(InvalidScene.class,
                () -> scene("SPHERE 0 0 0;".repeat(Scene.MAX_ELEMENTS + 1))).kind());
        // JSON keeps a type from smuggling in another element.
        InvalidScene smuggled = assertThrows(InvalidScene.class,
                () -> scene("[{\"type\": \"SPHERE 0 0 0; CONE\", \"features\": [1, 2, 3]}]"));
        assertTrue(smuggled.getMessage().contains("unknown type"), smuggled.getMessage());
        assertEquals(2, scene("[{\"type\": \"SPHERE\", \"features\": [0, 0, 0]}, "
                + "{\"type\": \"cone\", \"features\": [1, 0, 0, 0, 0, 1]}]").elements().size());
    }
}
