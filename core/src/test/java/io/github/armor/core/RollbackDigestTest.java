// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import io.github.armor.core.api.Directive;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A list that is rolled back leaves the reference exactly as it was: the same axioms, written the same way. */
class RollbackDigestTest {
    private final CoreFixture fx = new CoreFixture();

    @Test
    void aRolledBackRemovalOfAnAxiomStoredTheOtherWayRoundRestoresItAsStored() {
        fx.loadRobotics("map", "PELLET", true);
        fx.ok("map", "ADD OBJECTPROP INVERSE", "visitedAt", "batteryLevel");
        String before = fx.ok("map", "GET REF DIGEST").queriedObjects().get(0);
        io.github.armor.core.api.ListResponse undone = fx.core.executeList(List.of(
                Directive.of("test", "map", "REMOVE", "OBJECTPROP", "INVERSE", "batteryLevel", "visitedAt"),
                Directive.of("test", "map", "QUERY", "-", "-")));
        assertFalse(undone.success());
        assertEquals(before, fx.ok("map", "GET REF DIGEST").queriedObjects().get(0));
    }
}
