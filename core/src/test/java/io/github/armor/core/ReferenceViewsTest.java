// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.view.ReferenceViews;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The web page's read-only views (view/ReferenceViews) over the robotics ontology. */
class ReferenceViewsTest {
    private CoreFixture fixture;
    private ReferenceViews views;

    @BeforeEach
    void loadRobotics() {
        fixture = new CoreFixture();
        views = fixture.core.views();
        fixture.ok("map", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "", "false",
                "HERMIT", "false");
    }

    private JsonObject view(String json) {
        JsonObject answer = views.answer(JsonParser.parseString(json).getAsJsonObject());
        assertFalse(answer.has("error"), () -> json + " failed: " + answer);
        return answer;
    }

    private int errorCode(String json) {
        JsonObject answer = views.answer(JsonParser.parseString(json).getAsJsonObject());
        assertTrue(answer.has("error"), () -> json + " should fail but answered " + answer);
        assertFalse(answer.getAsJsonObject("error").get("description").getAsString().isBlank());
        return answer.getAsJsonObject("error").get("exit_code").getAsInt();
    }

    private static List<String> names(JsonArray entities) {
        List<String> names = new ArrayList<>();
        entities.forEach(e -> names.add(e.getAsJsonObject().get("name").getAsString()));
        return names;
    }

    /** name -> asserted, of a list of entities marked asserted or inferred. */
    private static Map<String, Boolean> marked(JsonArray entities) {
        Map<String, Boolean> marks = new TreeMap<>();
        entities.forEach(e -> marks.put(e.getAsJsonObject().get("name").getAsString(),
                e.getAsJsonObject().get("asserted").getAsBoolean()));
        return marks;
    }

    private static JsonObject byName(JsonArray items, String name) {
        for (JsonElement item : items) {
            if (item.getAsJsonObject().get("name").getAsString().equals(name)) {
                return item.getAsJsonObject();
            }
        }
        throw new AssertionError(name + " not in " + items);
    }

    @Test
    void overviewSummarisesEveryReference() {
        fixture.ok("other", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "", "true",
                "PELLET", "true");
        fixture.runAs("alice_client", "other", "MOUNT");
        JsonArray references = view("{\"name\": \"overview\"}").getAsJsonArray("references");
        assertEquals(List.of("map", "other"), names(references));
        JsonObject map = byName(references, "map");
        assertEquals("HERMIT", map.get("reasoner").getAsString());
        assertFalse(map.get("buffered_manipulation").getAsBoolean());
        assertTrue(map.get("consistent").getAsBoolean());
        assertEquals(8, map.get("classes").getAsInt());
        assertEquals(5, map.get("individuals").getAsInt());
        assertTrue(map.get("axioms").getAsInt() > map.get("logical_axioms").getAsInt());
        assertTrue(map.get("last_reasoning_at_ms").getAsLong() > 0);
        assertTrue(map.get("last_reasoning_ms").getAsDouble() >= 0);
        assertEquals("", map.get("mounted_by").getAsString());
        assertFalse(map.get("busy").getAsBoolean());
        JsonObject other = byName(references, "other");
        assertEquals("PELLET", other.get("reasoner").getAsString());
        assertTrue(other.get("buffered_manipulation").getAsBoolean() && other.get("buffered_reasoner").getAsBoolean());
        assertEquals("alice_client", other.get("mounted_by").getAsString());
        assertFalse(other.has("lease_left_s"), "mounts never expire with mount_lease_s = 0");
        // How each is reasoned on (issue 28 item 4): robotics.owl in modules; a buffered reasoner on the whole.
        assertTrue(map.get("reasoning").getAsString().startsWith("in modules: "), map.get("reasoning").toString());
        assertFalse(map.get("reasoned_on_whole").getAsBoolean());
        assertTrue(other.get("reasoned_on_whole").getAsBoolean());
        assertTrue(other.get("reasoning").getAsString().startsWith("on the whole ontology: buffered reasoner"),
                other.get("reasoning").toString());

        fixture.ok("map", "ADD IND CLASS", "carol", "Person");
        assertEquals(6, byName(view("{\"name\": \"overview\"}").getAsJsonArray("references"), "map")
                .get("individuals").getAsInt());
    }

    @Test
    void leaseLeftCountsDownFromTheHoldersLastDirective() {
        CoreConfig config = new CoreConfig(true, "HERMIT", List.of(CoreFixture.ONTOLOGIES), false, 30_000, 0, 60,
                CoreConfig.Durability.NONE);
        CoreFixture leased = new CoreFixture(config);
        leased.ok("map", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "", "false",
                "HERMIT", "false");
        leased.runAs("holder", "map", "MOUNT");
        JsonObject map = leased.core.views().answer(JsonParser.parseString("{\"name\": \"reference\", "
                + "\"reference\": \"map\"}").getAsJsonObject());
        double left = map.get("lease_left_s").getAsDouble();
        assertTrue(left > 50 && left <= 60, () -> "lease left " + left);
        assertEquals(List.of("connectedTo", "contains", "isIn"), names(map.getAsJsonArray("object_properties")));
        assertEquals(List.of("batteryLevel", "visitedAt"), names(map.getAsJsonArray("data_properties")));
    }

    @Test
    void hierarchyTellsAssertedFromInferredLinksAndFlagsUnsatisfiableClasses() {
        fixture.ok("map", "ADD AXIOM", "Located EquivalentTo isIn some Location");
        fixture.ok("map", "ADD AXIOM", "Impossible SubClassOf Room and Corridor");
        JsonObject hierarchy = view("{\"name\": \"classes\", \"reference\": \"map\"}");
        assertTrue(hierarchy.get("inferred").getAsBoolean());
        JsonArray classes = hierarchy.getAsJsonArray("classes");
        assertEquals(Map.of("Location", true), marked(byName(classes, "Room").getAsJsonArray("parents")));
        // RobotInRoom = Robot and isIn some Room: Robot is stated, Located only follows.
        assertEquals(Map.of("Robot", true, "Located", false),
                marked(byName(classes, "RobotInRoom").getAsJsonArray("parents")));
        assertEquals(Map.of(), marked(byName(classes, "Agent").getAsJsonArray("parents")));
        assertTrue(byName(classes, "Impossible").get("unsatisfiable").getAsBoolean());
        assertFalse(byName(classes, "Room").get("unsatisfiable").getAsBoolean());
        assertEquals(Map.of("Corridor", true, "Room", true),
                marked(byName(classes, "Impossible").getAsJsonArray("parents")));
    }

    @Test
    void classDetailGivesItsDefinitionAndItsInstancesAssertedOrInferred() {
        JsonObject occupied = view("{\"name\": \"class\", \"reference\": \"map\", \"class\": \"OccupiedRoom\"}");
        assertEquals(List.of("Room and (contains some Agent)"), strings(occupied.getAsJsonArray("equivalent_to")));
        assertEquals(List.of("contains some Agent"), strings(occupied.getAsJsonArray("restrictions")));
        assertEquals(Map.of("kitchen", false), marked(occupied.getAsJsonArray("instances")));
        assertEquals(List.of("Location", "Room"), names(occupied.getAsJsonArray("inferred_superclasses")));
        assertFalse(occupied.get("unsatisfiable").getAsBoolean());

        fixture.ok("map", "ADD OBJECTPROP IND", "isIn", "alice", "bedroom");
        occupied = view("{\"name\": \"class\", \"reference\": \"map\", \"class\": \"OccupiedRoom\"}");
        assertEquals(Map.of("bedroom", false, "kitchen", false), marked(occupied.getAsJsonArray("instances")));
        assertEquals(2, occupied.get("instance_count").getAsInt());

        JsonObject room = view("{\"name\": \"class\", \"reference\": \"map\", \"class\": \"Room\", \"limit\": 1}");
        assertEquals(Map.of("bedroom", true), marked(room.getAsJsonArray("instances")));
        assertEquals(2, room.get("instance_count").getAsInt());
        assertEquals(List.of("Location"), strings(room.getAsJsonArray("subclass_of")));
        assertEquals(List.of("Corridor"), strings(room.getAsJsonArray("disjoint_with")));
    }

    private static List<String> strings(JsonArray array) {
        List<String> values = new ArrayList<>();
        array.forEach(e -> values.add(e.getAsString()));
        return values;
    }

    @Test
    void individualsArePagedAndFoundByName() {
        List<String> batch = new ArrayList<>();
        for (int i = 0; i < 120; i++) {
            fixture.ok("map", "ADD IND CLASS", String.format("probe%03d", i), "Robot");
        }
        JsonObject page = view("{\"name\": \"individuals\", \"reference\": \"map\", \"search\": \"PROBE\", "
                + "\"offset\": 100, \"limit\": 50}");
        assertEquals(120, page.get("total").getAsInt());
        JsonArray items = page.getAsJsonArray("individuals");
        assertEquals(20, items.size());
        assertEquals("probe100", names(items).get(0));
        assertEquals(Map.of("Robot", true), marked(byName(items, "probe119").getAsJsonArray("types")));

        JsonObject rooms = view("{\"name\": \"individuals\", \"reference\": \"map\", \"search\": \"room\"}");
        assertEquals(List.of("bedroom"), names(rooms.getAsJsonArray("individuals")));
        JsonObject all = view("{\"name\": \"individuals\", \"reference\": \"map\", \"limit\": 3}");
        assertEquals(List.of("alice", "bedroom", "corridor1"), names(all.getAsJsonArray("individuals")));
        JsonObject kitchen = byName(view("{\"name\": \"individuals\", \"reference\": \"map\", \"search\": "
                + "\"kitchen\"}").getAsJsonArray("individuals"), "kitchen");
        assertEquals(Map.of("Room", true, "OccupiedRoom", false), marked(kitchen.getAsJsonArray("types")));
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT"})
    void mostSpecificTypesStaySoAsChangesComeIn(String reasoner) {
        fixture.ok("live", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "", "false",
                reasoner, "false");
        view("{\"name\": \"individuals\", \"reference\": \"live\"}");
        fixture.ok("live", "ADD OBJECTPROP IND", "isIn", "alice", "bedroom");
        view("{\"name\": \"individuals\", \"reference\": \"live\"}");
        fixture.ok("live", "ADD IND CLASS", "carol", "Person");
        JsonObject bedroom = byName(view("{\"name\": \"individuals\", \"reference\": \"live\", \"search\": "
                + "\"bedroom\"}").getAsJsonArray("individuals"), "bedroom");
        assertEquals(Map.of("OccupiedRoom", false, "Room", true), marked(bedroom.getAsJsonArray("types")));
        JsonObject graph = view("{\"name\": \"graph\", \"reference\": \"live\", \"class\": \"Room\"}");
        assertEquals(List.of("OccupiedRoom"), names(byName(graph.getAsJsonArray("nodes"), "bedroom")
                .getAsJsonArray("types")));
    }

    @Test
    void individualDetailTellsAssertedFromInferredValues() {
        JsonObject robot = view("{\"name\": \"individual\", \"reference\": \"map\", \"individual\": \"robot1\"}");
        assertEquals(Map.of("Agent", false, "Robot", true, "RobotInRoom", false),
                marked(robot.getAsJsonArray("types")));
        JsonObject isIn = byProperty(robot.getAsJsonArray("object_values"), "isIn");
        assertEquals(Map.of("kitchen", true), marked(isIn.getAsJsonArray("values")));
        JsonObject battery = byProperty(robot.getAsJsonArray("data_values"), "batteryLevel");
        JsonObject value = battery.getAsJsonArray("values").get(0).getAsJsonObject();
        assertEquals("\"80\"^^xsd:integer", value.get("value").getAsString());
        assertTrue(value.get("asserted").getAsBoolean());

        JsonObject kitchen = view("{\"name\": \"individual\", \"reference\": \"map\", \"individual\": \"kitchen\"}");
        assertEquals(Map.of("robot1", false), marked(byProperty(kitchen.getAsJsonArray("object_values"), "contains")
                .getAsJsonArray("values")));
        JsonObject corridor = view("{\"name\": \"individual\", \"reference\": \"map\", \"individual\": "
                + "\"corridor1\"}");
        assertEquals(Map.of("bedroom", false, "kitchen", false),
                marked(byProperty(corridor.getAsJsonArray("object_values"), "connectedTo").getAsJsonArray("values")));
    }

    private static JsonObject byProperty(JsonArray values, String property) {
        for (JsonElement entry : values) {
            if (entry.getAsJsonObject().getAsJsonObject("property").get("name").getAsString().equals(property)) {
                return entry.getAsJsonObject();
            }
        }
        throw new AssertionError(property + " not in " + values);
    }

    @Test
    void graphLinksIndividualsByTheChosenPropertiesAsAMap() {
        JsonObject map = view("{\"name\": \"graph\", \"reference\": \"map\", \"properties\": [\"connectedTo\"], "
                + "\"class\": \"Location\"}");
        assertEquals(List.of("bedroom", "corridor1", "kitchen"), names(map.getAsJsonArray("nodes")));
        assertEquals(List.of("OccupiedRoom"), names(byName(map.getAsJsonArray("nodes"), "kitchen")
                .getAsJsonArray("types")));
        // A free reference is read itself: the links the reasoner infers too (the reverse of a symmetric one).
        assertTrue(map.get("inferred_links").getAsBoolean());
        JsonArray edges = map.getAsJsonArray("edges");
        assertEquals(2, edges.size(), edges::toString);
        for (JsonElement edge : edges) {
            assertTrue(edge.getAsJsonObject().get("both_ways").getAsBoolean(), "connectedTo is symmetric");
            assertTrue(edge.getAsJsonObject().get("asserted").getAsBoolean());
            assertEquals("connectedTo", edge.getAsJsonObject().get("property_name").getAsString());
        }
        assertFalse(map.get("truncated").getAsBoolean());

        // A reference that publishes no state (a buffered reasoner) is read under its lock the same way.
        fixture.ok("buffered", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "", "false",
                "HERMIT", "true");
        JsonObject reasoned = view("{\"name\": \"graph\", \"reference\": \"buffered\", \"properties\": "
                + "[\"connectedTo\"], \"class\": \"Location\"}");
        assertTrue(reasoned.get("inferred_links").getAsBoolean());
        for (JsonElement edge : reasoned.getAsJsonArray("edges")) {
            assertTrue(edge.getAsJsonObject().get("both_ways").getAsBoolean(), "connectedTo is symmetric");
        }
        // Every property when none is named: connectedTo (2, both ways), isIn (2), contains (2, inferred).
        assertEquals(6, view("{\"name\": \"graph\", \"reference\": \"buffered\"}").getAsJsonArray("edges")
                .size());

        JsonObject none = view("{\"name\": \"graph\", \"reference\": \"map\", \"properties\": []}");
        assertEquals(5, none.getAsJsonArray("nodes").size());
        assertEquals(0, none.getAsJsonArray("edges").size());
        // Every property when none is named: connectedTo (2, both ways), isIn (2), contains (2, inferred).
        assertEquals(6, view("{\"name\": \"graph\", \"reference\": \"map\"}").getAsJsonArray("edges").size());
        JsonObject isIn = view("{\"name\": \"graph\", \"reference\": \"map\", \"properties\": [\"isIn\"]}");
        assertEquals(5, isIn.getAsJsonArray("nodes").size());
        assertEquals(2, isIn.getAsJsonArray("edges").size());

        // A sample grown from a room reaches the agent that states it is there.
        JsonObject sample = view("{\"name\": \"graph\", \"reference\": \"map\", \"properties\": [\"isIn\", "
                + "\"connectedTo\"], \"focus\": \"kitchen\", \"limit\": 3}");
        assertEquals(3, sample.getAsJsonArray("nodes").size());
        assertTrue(names(sample.getAsJsonArray("nodes")).containsAll(List.of("kitchen", "robot1", "corridor1")),
                sample::toString);
        assertTrue(sample.get("truncated").getAsBoolean());
        assertEquals(5, sample.get("candidates").getAsInt());
    }

    @Test
    void aLongViewLetsDirectivesInBetweenItsSlices() throws Exception {
        fixture.ok("slow", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "", "false",
                SlowTypesReasonerFactory.class.getName(), "false");
        for (int i = 0; i < 60; i++) {
            fixture.ok("slow", "ADD IND CLASS", "probe" + i, "Robot");
        }
        // A page of 65 individuals asks the reasoner 65 times or more: at least 650 ms in all.
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newSingleThreadExecutor();
        java.util.concurrent.Future<JsonObject> page = pool.submit(() -> view(
                "{\"name\": \"individuals\", \"reference\": \"slow\", \"limit\": 100}"));
        Thread.sleep(100);
        assertFalse(page.isDone(), "the view should still be running");
        fixture.ok("slow", "ADD IND CLASS", "late_robot", "Robot");
        // The change got the reference between two slices, long before the view ended.
        assertFalse(page.isDone(), "the change waited for the whole view");
        assertEquals(65, page.get().getAsJsonArray("individuals").size());
        pool.shutdown();
    }

    @Test
    void recentDirectivesAreNewestFirstWithClientCodeAndLatency() {
        fixture.runAs("robot_brain", "map", "QUERY IND CLASS", "Room");
        fixture.runAs("page", "map", "QUERY IND CLASS", "Room");
        fixture.runAs("robot_brain", "map", "ADD IND CLASS", "x", "NoSuchThing", "extra");
        JsonArray recent = view("{\"name\": \"recent\", \"reference\": \"map\", \"exclude_clients\": [\"page\"]}")
                .getAsJsonArray("directives");
        JsonObject newest = recent.get(0).getAsJsonObject();
        assertEquals("robot_brain", newest.get("client").getAsString());
        assertEquals("ADD IND CLASS", newest.get("command").getAsString());
        assertEquals(207, newest.get("exit_code").getAsInt());
        assertFalse(newest.get("success").getAsBoolean());
        JsonObject before = recent.get(1).getAsJsonObject();
        assertEquals("QUERY IND CLASS", before.get("command").getAsString());
        assertEquals("robot_brain", before.get("client").getAsString());
        assertTrue(before.get("latency_ms").getAsDouble() >= 0);
        String oldest = recent.get(recent.size() - 1).getAsJsonObject().get("command").getAsString();
        assertTrue(oldest.startsWith("LOAD FILE"), oldest);
        assertEquals(1, view("{\"name\": \"recent\", \"limit\": 1}").getAsJsonArray("directives").size());
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void anInconsistentReferenceIsStillShownFromWhatItAsserts(String reasoner) {
        fixture.ok("bad", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "", "false",
                reasoner, "false");
        fixture.ok("bad", "ADD IND CLASS", "kitchen", "Corridor");
        assertFalse(fixture.ok("bad", "QUERY CONSISTENCY").isConsistent());
        JsonObject hierarchy = view("{\"name\": \"classes\", \"reference\": \"bad\"}");
        assertFalse(hierarchy.get("consistent").getAsBoolean());
        assertFalse(hierarchy.get("inferred").getAsBoolean());
        assertEquals(Map.of("Location", true), marked(byName(hierarchy.getAsJsonArray("classes"), "Room")
                .getAsJsonArray("parents")));
        JsonObject kitchen = byName(view("{\"name\": \"individuals\", \"reference\": \"bad\", \"search\": "
                + "\"kitchen\"}").getAsJsonArray("individuals"), "kitchen");
        assertEquals(Map.of("Corridor", true, "Room", true), marked(kitchen.getAsJsonArray("types")));
        assertFalse(byName(view("{\"name\": \"overview\"}").getAsJsonArray("references"), "bad")
                .get("consistent").getAsBoolean());
        assertEquals(3, view("{\"name\": \"graph\", \"reference\": \"bad\", \"class\": \"Location\"}")
                .getAsJsonArray("nodes").size());
    }

    @Test
    void viewsChangeNothing() {
        long axioms = byName(view("{\"name\": \"overview\"}").getAsJsonArray("references"), "map")
                .get("axioms").getAsLong();
        for (String request : List.of("{\"name\": \"classes\", \"reference\": \"map\"}",
                "{\"name\": \"class\", \"reference\": \"map\", \"class\": \"Room\"}",
                "{\"name\": \"individuals\", \"reference\": \"map\"}",
                "{\"name\": \"individual\", \"reference\": \"map\", \"individual\": \"alice\"}",
                "{\"name\": \"graph\", \"reference\": \"map\"}")) {
            view(request);
        }
        assertEquals(axioms, byName(view("{\"name\": \"overview\"}").getAsJsonArray("references"), "map")
                .get("axioms").getAsLong());
    }

    @Test
    void badRequestsAreRefusedWithACodeAndAReason() {
        assertEquals(205, errorCode("{\"name\": \"everything\"}"));
        assertEquals(207, errorCode("{}"));
        assertEquals(206, errorCode("{\"name\": \"classes\", \"reference\": \"nowhere\"}"));
        assertEquals(207, errorCode("{\"name\": \"individuals\", \"reference\": \"map\", \"limit\": 0}"));
        assertEquals(207, errorCode("{\"name\": \"individuals\", \"reference\": \"map\", \"offset\": \"x\"}"));
        assertEquals(207, errorCode("{\"name\": \"graph\", \"reference\": \"map\", \"properties\": \"isIn\"}"));
        assertEquals(224, errorCode("{\"name\": \"class\", \"reference\": \"map\", \"class\": \"Roon\"}"));
        assertEquals(224, errorCode("{\"name\": \"individual\", \"reference\": \"map\", \"individual\": \"bob\"}"));
        assertEquals(224, errorCode("{\"name\": \"graph\", \"reference\": \"map\", \"properties\": [\"isOn\"]}"));
        assertEquals(208, errorCode("{\"name\": \"class\", \"reference\": \"map\", \"class\": \"<bad\"}"));
    }
}
