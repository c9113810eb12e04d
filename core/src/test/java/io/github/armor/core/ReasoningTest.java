// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.iri;
import static io.github.armor.core.CoreFixture.iris;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.Response;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The same questions through every reasoner: defined classes need inference to be answered. */
class ReasoningTest {
    private final CoreFixture fixture = new CoreFixture();

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT", "ELK"})
    void elDefinedClassIsAnsweredByEveryReasoner(String reasoner) {
        fixture.loadRobotics("map", reasoner, true);
        assertEquals(iris("robot1"), fixture.ok("map", "QUERY IND CLASS", "RobotInRoom").queriedObjects());
        assertEquals(iris("alice", "robot1"), fixture.ok("map", "QUERY IND CLASS", "Agent").queriedObjects());
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT"})
    void occupiedRoomFollowsTheRobotAfterReason(String reasoner) {
        fixture.loadRobotics("map", reasoner, true);
        assertEquals(iris("kitchen"), fixture.ok("map", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());

        fixture.ok("map", "REPLACE OBJECTPROP IND", "isIn", "robot1", "bedroom", "kitchen");
        // A buffered reasoner has not seen the change yet.
        assertEquals(iris("kitchen"), fixture.ok("map", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        fixture.ok("map", "REASON");
        assertEquals(iris("bedroom"), fixture.ok("map", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        assertEquals(iris("bedroom"), fixture.ok("map", "QUERY OBJECTPROP IND", "isIn", "robot1").queriedObjects());
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void nonBufferedReasonerSeesChangesAtOnce(String reasoner) {
        fixture.loadRobotics("map", reasoner, false);
        fixture.ok("map", "ADD OBJECTPROP IND", "isIn", "alice", "bedroom");
        assertEquals(iris("bedroom", "kitchen"), fixture.ok("map", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT"})
    void inconsistencyIsReportedAndExplained(String reasoner) {
        fixture.loadRobotics("map", reasoner, true);
        assertTrue(fixture.ok("map", "QUERY CONSISTENCY").isConsistent());
        fixture.ok("map", "ADD IND CLASS", "kitchen", "Corridor");
        fixture.ok("map", "REASON");
        Response consistency = fixture.ok("map", "QUERY CONSISTENCY");
        assertFalse(consistency.isConsistent());
        List<String> explanation = consistency.queriedObjects();
        assertTrue(explanation.stream().anyMatch(a -> a.contains("DisjointWith") || a.contains("DisjointClasses")),
                () -> "explanation lacks the disjointness axiom: " + explanation);
        CoreFixture.assertFails(fixture.run("map", "QUERY IND CLASS", "Room"), 217);
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void swrlRulesAreApplied(String reasoner) {
        fixture.loadRobotics("map", reasoner, true);
        fixture.ok("map", "ADD SWRL", "visitedByRobot", "Robot(?r), isIn(?r, ?l) -> Visited(?l)");
        fixture.ok("map", "REASON");
        assertEquals(iris("kitchen"), fixture.ok("map", "QUERY IND CLASS", "Visited").queriedObjects());
        fixture.ok("map", "REMOVE SWRL", "visitedByRobot", "Robot(?r), isIn(?r, ?l) -> Visited(?l)");
        fixture.ok("map", "REASON");
        assertEquals(List.of(), fixture.ok("map", "QUERY IND CLASS", "Visited").queriedObjects());
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void rulesMayCreatePropertiesAndCompareIndividuals(String reasoner) {
        fixture.loadRobotics("map", reasoner, true);
        fixture.ok("map", "ADD SWRL", "reach", "connectedTo(?a, ?b) -> reaches(?a, ?b)");
        fixture.ok("map", "ADD SWRL", "apart", "isIn(?x, ?a), isIn(?y, ?b), DifferentFrom(?a, ?b) -> apartFrom(?x, ?y)");
        // No unique-name assumption in OWL: the rule fires for individuals known to differ.
        fixture.ok("map", "DISJOINT IND", "kitchen", "corridor1");
        fixture.ok("map", "REASON");
        assertEquals(iris("corridor1"), fixture.ok("map", "QUERY OBJECTPROP IND", "reaches", "kitchen").queriedObjects());
        assertEquals(iris("alice"), fixture.ok("map", "QUERY OBJECTPROP IND", "apartFrom", "robot1").queriedObjects());
    }

    @org.junit.jupiter.api.Test
    void openlletAppliesRulesWithBuiltIns() {
        fixture.loadRobotics("map", "PELLET", true);
        fixture.ok("map", "ADD SWRL", "lowBattery",
                "Robot(?r), batteryLevel(?r, ?b), swrlb:lessThan(?b, 90) -> NeedsCharging(?r)");
        fixture.ok("map", "REASON");
        assertEquals(iris("robot1"), fixture.ok("map", "QUERY IND CLASS", "NeedsCharging").queriedObjects());
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void dlQueryAndDataValues(String reasoner) {
        fixture.loadRobotics("map", reasoner, true);
        assertEquals(iris("alice", "robot1"),
                fixture.ok("map", "QUERY IND DL", "Agent and (isIn some Location)").queriedObjects());
        assertEquals(List.of("\"80\"^^xsd:integer"),
                fixture.ok("map", "QUERY DATAPROP IND", "batteryLevel", "robot1").queriedObjects());
        assertEquals(iris("bedroom", "kitchen"),
                fixture.ok("map", "QUERY OBJECTPROP IND", "connectedTo", "corridor1").queriedObjects());
        assertEquals(List.of(iri("connectedTo")), fixture.ok("map", "QUERY IND OBJECTPROP", "bedroom").queriedObjects());
    }
}
