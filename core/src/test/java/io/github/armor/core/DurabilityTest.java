// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.iris;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Acknowledged changes survive a new core on the same state directory (issue 5). */
class DurabilityTest {
    private static final String ROBOTICS = CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString();

    @TempDir
    Path stateDir;

    private final java.util.List<ArmorCore> cores = new java.util.ArrayList<>();

    @org.junit.jupiter.api.AfterEach
    void closeCores() {
        cores.forEach(ArmorCore::close);
    }

    /** A core on the state directory; the previous one is closed first, as a restart does. */
    private ArmorCore core(boolean restore, int checkpointEvery) {
        return CoreFixture.restartOn(cores, stateDir, "HERMIT", restore, true, checkpointEvery);
    }

    private static Response ok(ArmorCore core, String client, String reference, String words, String... args) {
        String[] parts = (words + " - -").split("\\s+");
        Response response = core.execute(Directive.of(client, reference, parts[0], parts[1], parts[2], args));
        assertTrue(response.success(), () -> words + ": " + response.exitCode() + " " + response.errorDescription());
        return response;
    }

    private static List<String> robots(ArmorCore core) {
        return ok(core, "c", "map", "QUERY IND CLASS", "Robot").queriedObjects();
    }

    @Test
    void acknowledgedChangesAndTheMountSurviveARestart() {
        ArmorCore first = core(true, 1000);
        ok(first, "c", "map", "LOAD FILE", ROBOTICS, "", "false", "PELLET", "true");
        ok(first, "c", "map", "ADD IND CLASS", "robot2", "Robot");
        ok(first, "c", "map", "REPLACE DATAPROP IND", "batteryLevel", "robot1", "INT", "55", "80");
        ok(first, "planner", "map", "MOUNT");

        ArmorCore second = core(true, 1000);
        assertEquals(iris("robot1", "robot2"), robots(second));
        assertEquals(List.of("\"55\"^^xsd:integer"),
                ok(second, "c", "map", "QUERY DATAPROP IND", "batteryLevel", "robot1").queriedObjects());
        assertEquals(List.of("planner"), ok(second, "c", "", "GET REF CLIENT", "map").queriedObjects());
        assertEquals(102, second.execute(Directive.of("c", "map", "ADD", "IND", "CLASS", "robot3", "Robot")).exitCode());
        // The preload of a restarted node names the same file: the restored reference is reused.
        ok(second, "c", "map", "LOAD FILE", ROBOTICS, "", "false", "PELLET", "true");
        assertEquals(iris("robot1", "robot2"), robots(second));
    }

    /**
     * LUBM's univ-bench defines Dean by an owl:intersectionOf of one restriction, which functional
     * syntax (the checkpoint's) writes as the restriction alone: the same class, kept (LOAD was 225).
     */
    @Test
    void anIntersectionOfOneClassIsKeptAsThatClass() {
        String department = LubmQueriesTest.LUBM.resolve("university0-department0.owl").toString();
        java.util.function.Supplier<ArmorCore> restart = () -> {
            cores.forEach(ArmorCore::close);
            ArmorCore core = new ArmorCore(new io.github.armor.core.api.CoreConfig(true, "PELLET",
                    List.of(LubmQueriesTest.LUBM), false, 30_000, 0, 0,
                    new io.github.armor.core.api.CoreConfig.Durability(stateDir, true, true, 1000, 3600)));
            core.restoreState();
            cores.add(core);
            return core;
        };
        ArmorCore first = restart.get();
        ok(first, "c", "lubm", "LOAD FILE", department, "", "false", "PELLET", "false");
        List<String> deans = ok(first, "c", "lubm", "QUERY IND CLASS", "Dean").queriedObjects();
        List<String> chairs = ok(first, "c", "lubm", "QUERY IND CLASS", "Chair").queriedObjects();
        assertTrue(!chairs.isEmpty(), "the department has a chair");

        ArmorCore second = restart.get();
        assertEquals(deans, ok(second, "c", "lubm", "QUERY IND CLASS", "Dean").queriedObjects());
        assertEquals(chairs, ok(second, "c", "lubm", "QUERY IND CLASS", "Chair").queriedObjects());
    }

    /** Issue 35 item 9: a restored reference shows the time its reasoning took, not a no-op's 0.0 ms. */
    @Test
    void aRestoredReferenceShowsTheReasoningItsRestoreDid() {
        ArmorCore first = core(true, 1000);
        ok(first, "c", "map", "LOAD FILE", ROBOTICS, "", "false", BlockingReasonerFactory.class.getName(), "false");
        // Making this reasoner takes 300 ms: the restore makes one, a flush with nothing to do does not.
        BlockingReasonerFactory.START_BLOCK_MS.set(300);
        try {
            ArmorCore second = core(true, 1000);
            double restoredMs = lastReasoningMs(second);
            assertTrue(restoredMs >= 300, "reasoned in " + restoredMs + " ms after the restore");
        } finally {
            BlockingReasonerFactory.reset();
        }
    }

    private static double lastReasoningMs(ArmorCore core) {
        com.google.gson.JsonObject summary = core.views().answer(com.google.gson.JsonParser
                .parseString("{\"name\": \"overview\"}").getAsJsonObject())
                .getAsJsonArray("references").get(0).getAsJsonObject();
        assertEquals("map", summary.get("name").getAsString());
        return summary.get("last_reasoning_ms").getAsDouble();
    }

    @Test
    void aTornLastRecordIsDroppedAndEverythingBeforeItReplays() throws Exception {
        ArmorCore first = core(true, 1000);
        ok(first, "c", "map", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true");
        ok(first, "c", "map", "ADD IND CLASS", "robot2", "Robot");
        ok(first, "c", "map", "ADD IND CLASS", "robot3", "Robot");
        Path journal = journals().get(0);
        byte[] bytes = Files.readAllBytes(journal);
        Files.write(journal, java.util.Arrays.copyOf(bytes, bytes.length - 5));
        Files.write(journal, new byte[] {0, 0, 1, 0, 42}, StandardOpenOption.APPEND);

        ArmorCore second = core(true, 1000);
        assertEquals(iris("robot1", "robot2"), robots(second));
        ok(second, "c", "map", "ADD IND CLASS", "robot4", "Robot");
        assertEquals(iris("robot1", "robot2", "robot4"), robots(core(true, 1000)));
    }

    @Test
    void checkpointsBoundTheJournalAndRestoreTheSameAnswers() throws Exception {
        ArmorCore first = core(true, 5);
        ok(first, "c", "map", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true");
        for (int i = 0; i < 12; i++) {
            ok(first, "c", "map", "ADD IND CLASS", "bot" + i, "Robot");
        }
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (checkpointNumber() < 2 && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertTrue(checkpointNumber() >= 2, "no checkpoint after 12 changes with a checkpoint every 5");
        List<String> expected = robots(first);
        assertEquals(13, expected.size());
        assertEquals(expected, robots(core(true, 5)));
    }

    @Test
    void aFailedListLeavesNothingInTheJournal() {
        ArmorCore first = core(true, 1000);
        ok(first, "c", "map", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true");
        ListResponse list = first.executeList(List.of(
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot2", "Robot"),
                Directive.of("c", "map", "ADD", "IND", "CLASS", "broken")));
        assertFalse(list.success());
        ListResponse good = first.executeList(List.of(
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot3", "Robot"),
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot4", "Robot")));
        assertTrue(good.success());
        assertEquals(iris("robot1", "robot3", "robot4"), robots(core(true, 1000)));
    }

    @Test
    void bufferedChangesComeBackStillBuffered() {
        ArmorCore first = core(true, 1000);
        ok(first, "c", "map", "LOAD FILE", ROBOTICS, "", "true", "HERMIT", "true");
        ok(first, "c", "map", "ADD IND CLASS", "robot2", "Robot");
        ArmorCore second = core(true, 1000);
        assertEquals(iris("robot1"), robots(second));
        ok(second, "c", "map", "APPLY");
        assertEquals(iris("robot1", "robot2"), robots(second));
    }

    @Test
    void dropDeletesTheStateAndACleanStartIgnoresIt() {
        ArmorCore first = core(true, 1000);
        ok(first, "c", "gone", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true");
        ok(first, "c", "kept", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true");
        ok(first, "c", "gone", "DROP");
        assertEquals(List.of("kept"), ok(core(true, 1000), "c", "", "GET ALL REFS").queriedObjects());
        assertEquals(List.of(), ok(core(false, 1000), "c", "", "GET ALL REFS").queriedObjects());
        assertEquals(List.of(), ok(core(true, 1000), "c", "", "GET ALL REFS").queriedObjects());
    }

    private List<Path> journals() throws Exception {
        try (Stream<Path> files = Files.walk(stateDir)) {
            return files.filter(f -> f.getFileName().toString().startsWith("journal-")).sorted().toList();
        }
    }

    /** The checkpoint recovery would start from: the one meta.json names. */
    private long checkpointNumber() throws Exception {
        String meta = Files.readString(stateDir.resolve("refs").resolve("map").resolve("meta.json"));
        String file = com.google.gson.JsonParser.parseString(meta).getAsJsonObject().getAsJsonObject("meta")
                .getAsJsonObject("current").get("file").getAsString();
        return Long.parseLong(file.replaceAll("\\D", ""));
    }
}
