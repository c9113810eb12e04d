// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandTable;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * SIT SCENE and its queries in a core that loaded this plugin as a node does (ServiceLoader, a
 * jar that is not the core's): the checks of the specification's section 6 with both complete
 * reasoners, restarts, rollback, buffered references, mounts and refused input.
 */
class SitCommandsTest {
    private static final String NS = "http://www.emarolab.it/sit/simple#";
    private static final String TWO_SPHERES = "SPHERE 0 0 0; SPHERE 0.8 0 0.8";
    private static final String SPHERE_AND_CONE = "SPHERE 0 0 0; CONE -0.8 -0.8 0 0 0 1";
    private static final String ALL_THREE = "SPHERE 0 0 0; CONE -0.8 -0.8 0 0 0 1; SPHERE 0.8 0 0.8";
    private static final String TWO_CONES = "CONE 0 0 0 0 0 1; CONE 1 0 0 0.5 0.5 0";

    @TempDir
    Path scratch;

    private final List<ArmorCore> cores = new ArrayList<>();

    @AfterEach
    void close() {
        cores.forEach(ArmorCore::close);
    }

    /** A core with this plugin; with a state directory, the previous one is closed first, as a restart does. */
    private ArmorCore core(boolean durable) {
        cores.forEach(ArmorCore::close);
        CommandTable table = CommandTable.load(SitCommandsTest.class.getClassLoader());
        assertEquals("classes", table.find("SIT SCENE -").orElseThrow().origin());
        CoreConfig.Durability durability = durable
                ? new CoreConfig.Durability(scratch.resolve("state"), true, false, 1000, 3600)
                : CoreConfig.Durability.NONE;
        ArmorCore core = new ArmorCore(new CoreConfig(true, "PELLET", List.of(scratch), false, 30_000, 0, 0,
                durability), table);
        core.restoreState();
        cores.add(core);
        return core;
    }

    private static Response run(ArmorCore core, String client, String words, String... args) {
        String[] parts = (words + " - -").split("\\s+");
        return core.execute(Directive.of(client, "sit", parts[0], parts[1], parts[2], args));
    }

    private static Response ok(ArmorCore core, String words, String... args) {
        Response response = run(core, "test", words, args);
        assertTrue(response.success(), () -> words + ": " + response.exitCode() + " " + response.errorDescription());
        return response;
    }

    private static void create(ArmorCore core, String reasoner, boolean buffered) {
        ok(core, "CREATE", "http://www.emarolab.it/sit/simple", String.valueOf(buffered), reasoner, String.valueOf(buffered));
    }

    /** What SIT SCENE answered: the learned class ("" if none) and each recognised class's similarity. */
    private record Answer(String learned, Map<String, Double> recognised) {}

    private static Answer scene(ArmorCore core, String elements) {
        return read(ok(core, "SIT SCENE", "0.9", "0.03", "0.05", elements));
    }

    private static Answer read(Response response) {
        String learned = "";
        Map<String, Double> recognised = new LinkedHashMap<>();
        for (String line : response.queriedObjects()) {
            String[] words = line.split(" ");
            if (words[0].equals("learned")) {
                learned = words[1];
            } else {
                recognised.put(words[1], Double.parseDouble(words[2]));
            }
        }
        return new Answer(learned, recognised);
    }

    private static String iri(String name) {
        return "<" + NS + name + ">";
    }

    private static Map<String, JsonObject> sceneClasses(ArmorCore core) {
        Map<String, JsonObject> classes = new LinkedHashMap<>();
        for (String line : ok(core, "QUERY SIT SCENES").queriedObjects()) {
            JsonObject item = JsonParser.parseString(line).getAsJsonObject();
            classes.put(item.get("name").getAsString(), item);
        }
        return classes;
    }

    private static Set<String> restrictions(JsonObject sceneClass) {
        Set<String> shown = new java.util.TreeSet<>();
        sceneClass.getAsJsonArray("restrictions").forEach(r -> shown.add(r.getAsJsonObject().get("property").getAsString()
                + " min " + r.getAsJsonObject().get("min").getAsInt() + " " + r.getAsJsonObject().get("type").getAsString()));
        return shown;
    }

    /** Nothing of a scene is left: no individual at all in these references. */
    private static void noIndividualLeft(ArmorCore core) {
        assertEquals(List.of(), ok(core, "QUERY IND CLASS", "owl:Thing").queriedObjects());
    }

    @ParameterizedTest
    @ValueSource(strings = {"PELLET", "HERMIT"})
    void theSpecificationsChecksPass(String reasoner) {
        ArmorCore core = core(false);
        create(core, reasoner, false);

        Answer first = scene(core, TWO_SPHERES);
        assertEquals(new Answer(iri("SCENE-1"), Map.of()), first);
        assertEquals(new Answer("", Map.of(iri("SCENE-1"), 1.0)), scene(core, TWO_SPHERES));

        Answer second = scene(core, SPHERE_AND_CONE);
        assertEquals(iri("SCENE-2"), second.learned());
        Set<String> coneScene = restrictions(sceneClasses(core).get("SCENE-2"));
        assertTrue(coneScene.stream().anyMatch(r -> r.endsWith(" CONE")) && coneScene.stream().noneMatch(
                r -> r.contains("PLANE")), coneScene.toString());
        // The reasoner reads the class the same way: a scene with a sphere left of a cone is one.
        assertTrue(ok(core, "QUERY CLASS DL", "rightSPHERE min 1 CONE").queriedObjects().contains(iri("SCENE-2")));

        Answer third = scene(core, ALL_THREE);
        assertEquals(iri("SCENE-3"), third.learned());
        assertEquals(Set.of(iri("SCENE-1"), iri("SCENE-2")), third.recognised().keySet());
        int cardinality = sceneClasses(core).get("SCENE-3").get("cardinality").getAsInt();
        assertEquals(12, cardinality);
        for (String name : List.of("SCENE-1", "SCENE-2")) {
            double expected = (double) sceneClasses(core).get(name).get("cardinality").getAsInt() / cardinality;
            assertEquals(expected, third.recognised().get(iri(name)), 1e-12);
            assertTrue(expected > 0 && expected < 1);
        }
        Answer again = scene(core, ALL_THREE);
        assertEquals("", again.learned());
        assertEquals(1.0, again.recognised().get(iri("SCENE-3")));
        assertEquals(Set.of(iri("SCENE-1"), iri("SCENE-2"), iri("SCENE-3")), again.recognised().keySet());
        // Sub-scenes: the reasoner places SCENE-1 and SCENE-2 above SCENE-3.
        List<String> supers = ok(core, "QUERY CLASS SUPER", "SCENE-3").queriedObjects();
        assertTrue(supers.containsAll(List.of(iri("SCENE-1"), iri("SCENE-2"), iri("SCENE"))), supers.toString());
        Set<String> shownAbove = new java.util.TreeSet<>();
        sceneClasses(core).get("SCENE-3").getAsJsonArray("superscenes").forEach(s -> shownAbove.add(s.getAsString()));
        assertEquals(Set.of(iri("SCENE-1"), iri("SCENE-2")), shownAbove);

        Answer cones = scene(core, TWO_CONES);
        assertEquals(iri("SCENE-4"), cones.learned());
        JsonObject coneClass = sceneClasses(core).get("SCENE-4");
        assertEquals(6, coneClass.get("cardinality").getAsInt());
        assertEquals(Set.of("alongXCONE min 2 CONE", "perpendicularCONE min 2 CONE", "behindCONE min 1 CONE",
                "frontCONE min 1 CONE"), restrictions(coneClass));
        assertTrue(coneClass.get("definition").getAsString().contains("at least 2 CONE along X"));
        assertTrue(ok(core, "QUERY CLASS SUPER", "SCENE-4").queriedObjects().contains(iri("SCENE")));
        noIndividualLeft(core);
    }

    @Test
    void learnedClassesTheCounterAndRecognitionsSurviveARestart() {
        ArmorCore first = core(true);
        create(first, "PELLET", false);
        scene(first, TWO_SPHERES);
        scene(first, SPHERE_AND_CONE);
        // A removed class's number is not given again.
        ok(first, "REMOVE CLASS", "SCENE-2");

        ArmorCore second = core(true);
        assertEquals(new Answer("", Map.of(iri("SCENE-1"), 1.0)), scene(second, TWO_SPHERES));
        assertEquals(iri("SCENE-3"), scene(second, TWO_CONES).learned());
        ArmorCore third = core(true);
        assertEquals(Set.of("SCENE-1", "SCENE-3"), sceneClasses(third).keySet());
        assertEquals(iri("SCENE-4"), scene(third, SPHERE_AND_CONE).learned());
        noIndividualLeft(third);
    }

    @Test
    void aSceneInAFailedListIsUndoneWhole() {
        ArmorCore core = core(false);
        create(core, "PELLET", false);
        scene(core, TWO_SPHERES);
        long revision = Long.parseLong(ok(core, "GET REF REVISION", "sit").queriedObjects().get(0));
        var list = core.executeList(List.of(
                Directive.of("test", "sit", "SIT", "SCENE", "", "0.9", "0.03", "0.05", TWO_CONES),
                Directive.of("test", "sit", "QUERY", "IND", "CLASS")));
        assertFalse(list.success());
        assertEquals(Set.of("SCENE-1"), sceneClasses(core).keySet());
        assertEquals(revision, Long.parseLong(ok(core, "GET REF REVISION", "sit").queriedObjects().get(0)));
        noIndividualLeft(core);
        // The counter was undone with it: the next class is SCENE-2.
        assertEquals(iri("SCENE-2"), scene(core, TWO_CONES).learned());
    }

    @Test
    void aBufferedReferenceAsRos1LoadedItWorksAndKeepsOthersWaitingChanges() {
        ArmorCore core = core(false);
        create(core, "PELLET", true);
        assertEquals(iri("SCENE-1"), scene(core, TWO_SPHERES).learned());
        assertEquals(1.0, scene(core, TWO_SPHERES).recognised().get(iri("SCENE-1")));
        // A change waiting for APPLY is applied first, as APPLY would; a failed list restores the wait.
        ok(core, "ADD IND CLASS", "table1", "Table");
        var list = core.executeList(List.of(
                Directive.of("test", "sit", "SIT", "SCENE", "", "0.9", "0.03", "0.05", TWO_CONES),
                Directive.of("test", "sit", "QUERY", "IND", "CLASS")));
        assertFalse(list.success());
        assertEquals(List.of(), ok(core, "QUERY IND CLASS", "Table").queriedObjects());
        ok(core, "APPLY");
        ok(core, "REASON");
        assertEquals(List.of(iri("table1")), ok(core, "QUERY IND CLASS", "Table").queriedObjects());
        // ... and nothing of the undone scene waits to be applied with it.
        assertEquals(Set.of("SCENE-1"), sceneClasses(core).keySet());
    }

    @Test
    void anotherClientsMountRefusesAScene() {
        ArmorCore core = core(false);
        create(core, "PELLET", false);
        ok(core, "MOUNT");
        Response refused = run(core, "other", "SIT SCENE", "0.9", "0.03", "0.05", TWO_SPHERES);
        assertEquals(102, refused.exitCode(), refused.errorDescription());
        assertEquals(Map.of(), sceneClasses(core));
    }

    @Test
    void aSceneWithoutRelationsOrWithBadInputChangesNothing() {
        ArmorCore core = core(false);
        create(core, "PELLET", false);
        Response lone = ok(core, "SIT SCENE", "0.9", "0.03", "0.05", "CONE 0 0 0 0 0 1");
        assertEquals(List.of(), lone.queriedObjects());
        Map<String, Integer> refused = new LinkedHashMap<>();
        refused.put("CUBE 0 0 0; SPHERE 1 1 1", 207);
        refused.put("SPHERE 0 0 0 0 0 1; SPHERE 1 1 1", 207);
        refused.put("SPHERE 0 0; SPHERE 1 1 1", 207);
        refused.put("SPHERE 0 NaN 0; SPHERE 1 1 1", 101);
        refused.put("[{\"type\": \"SPHERE\", \"features\": [0, 0, Infinity]}, {\"type\": \"SPHERE\", \"features\": [1, 1, 1]}]", 101);
        refused.put("", 207);
        refused.put("SPHERE 0 0 0;".repeat(1000), 221);
        refused.forEach((elements, code) -> {
            Response response = run(core, "test", "SIT SCENE", "0.9", "0.03", "0.05", elements);
            assertEquals(code, response.exitCode(), response.errorDescription());
            assertFalse(response.errorDescription().isBlank());
        });
        assertEquals(207, run(core, "test", "SIT SCENE", "0.9", "0.03", "0.05").exitCode());
        assertEquals(101, run(core, "test", "SIT SCENE", "1.5", "0.03", "0.05", TWO_SPHERES).exitCode());
        assertEquals(101, run(core, "test", "SIT SCENE", "0.9", "-1", "0.05", TWO_SPHERES).exitCode());
        Response unknown = core.execute(Directive.of("test", "nowhere", "SIT", "SCENE", "",
                "0.9", "0.03", "0.05", TWO_SPHERES));
        assertEquals(206, unknown.exitCode());
        assertEquals(Map.of(), sceneClasses(core));
        noIndividualLeft(core);
        // Not even the vocabulary was declared.
        assertEquals(List.of(), ok(core, "QUERY CLASS CLASS", "owl:Thing").queriedObjects().stream()
                .filter(c -> c.contains("SCENE") || c.contains("SPHERE")).toList());
    }

    @Test
    void recentScenesExplainTheirRecognitions() {
        ArmorCore core = core(false);
        create(core, "PELLET", false);
        scene(core, TWO_SPHERES);
        scene(core, ALL_THREE);
        List<String> recent = ok(core, "QUERY SIT RECENT").queriedObjects();
        assertEquals(2, recent.size());
        JsonObject newest = JsonParser.parseString(recent.get(0)).getAsJsonObject();
        assertEquals(iri("SCENE-2"), newest.get("learned").getAsString());
        assertEquals(12, newest.get("cardinality").getAsInt());
        JsonObject recognition = newest.getAsJsonArray("recognitions").get(0).getAsJsonObject();
        assertEquals("SCENE-1", recognition.get("name").getAsString());
        Set<String> met = new java.util.TreeSet<>();
        recognition.getAsJsonArray("explanation").forEach(m -> {
            assertTrue(m.getAsJsonObject().get("counted").getAsInt() >= m.getAsJsonObject().get("min").getAsInt());
            m.getAsJsonObject().getAsJsonArray("relations").forEach(r -> met.add(r.getAsString()));
        });
        // SCENE-1's restriction "at least 1 SPHERE below a SPHERE" is met by the first sphere under the third.
        assertTrue(met.contains("SPHERE#1 below SPHERE#3"), met.toString());
        assertEquals(Set.of(), met.stream().filter(r -> r.contains("CONE")).collect(Collectors.toSet()));
    }
}
