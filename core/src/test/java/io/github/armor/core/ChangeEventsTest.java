// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.events.ChangeEvent;
import io.github.armor.core.events.CoreEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Revisions and change events (issue 12): one per acknowledged change, in order, kept across restarts. */
class ChangeEventsTest {
    private static final String ROBOTICS = CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString();

    @TempDir
    Path stateDir;

    private final List<ArmorCore> cores = new ArrayList<>();
    private final LinkedBlockingQueue<ChangeEvent> events = new LinkedBlockingQueue<>();

    @AfterEach
    void closeCores() {
        cores.forEach(ArmorCore::close);
    }

    /** A core on the state directory (the previous one closed first, as a restart does), its events collected. */
    private ArmorCore core(int checkpointEvery) {
        ArmorCore core = CoreFixture.restartOn(cores, stateDir, "HERMIT", true, false, checkpointEvery);
        core.events().addListener(this::collect);
        return core;
    }

    private void collect(CoreEvent event) {
        if (event instanceof ChangeEvent change) {
            events.add(change);
        }
    }

    private static Response run(ArmorCore core, String client, String words, String... args) {
        String[] parts = (words + " - -").split("\\s+");
        return core.execute(Directive.of(client, "map", parts[0], parts[1], parts[2], args));
    }

    private static void ok(ArmorCore core, String words, String... args) {
        Response response = run(core, "c", words, args);
        assertTrue(response.success(), () -> words + ": " + response.exitCode() + " " + response.errorDescription());
    }

    private ChangeEvent next() throws InterruptedException {
        ChangeEvent event = events.poll(10, TimeUnit.SECONDS);
        assertNotNull(event, "no change event within 10 s");
        return event;
    }

    /** Nothing more arrives: the events so far were all there was. */
    private void noMore() throws InterruptedException {
        assertNull(events.poll(300, TimeUnit.MILLISECONDS));
    }

    @Test
    void eachAcknowledgedChangeIsOneRevisionAndFailuresAndQueriesNone() throws Exception {
        ArmorCore core = core(1000);
        ok(core, "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "false");
        ChangeEvent created = next();
        assertEquals("map", created.reference());
        assertEquals(0, created.revision());
        assertEquals("LOAD", created.directives().get(0).command());

        ok(core, "ADD OBJECTPROP IND", "isIn", "alice", "bedroom");
        ok(core, "QUERY IND CLASS", "OccupiedRoom");
        assertFalse(run(core, "c", "ADD IND CLASS", "only-one-argument").success());
        ok(core, "MOUNT");
        assertFalse(run(core, "intruder", "ADD IND CLASS", "robot9", "Robot").success());
        ok(core, "UNMOUNT");

        ChangeEvent add = next();
        assertEquals(1, add.revision());
        assertEquals("c", add.clientName());
        assertEquals(List.of("isIn", "alice", "bedroom"), add.directives().get(0).args());
        assertEquals(0, add.exitCode());
        assertTrue(add.consistent());
        assertTrue(Math.abs(System.currentTimeMillis() - add.stampNs() / 1_000_000) < 60_000, "stamp is wall time");
        assertEquals("MOUNT", next().directives().get(0).command());
        ChangeEvent unmount = next();
        assertEquals(3, unmount.revision());
        noMore();
    }

    @Test
    void anAtomicListIsOneRevisionPerReferenceAndARolledBackListNone() throws Exception {
        ArmorCore core = core(1000);
        ok(core, "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "false");
        next();
        ListResponse good = core.executeList(List.of(
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot2", "Robot"),
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot3", "Robot"),
                Directive.of("c", "map", "QUERY", "IND", "CLASS", "Robot")));
        assertTrue(good.success());
        ChangeEvent list = next();
        assertEquals(1, list.revision());
        assertEquals(2, list.directives().size(), "the list's changes, not its queries");

        ListResponse bad = core.executeList(List.of(
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot4", "Robot"),
                Directive.of("c", "map", "ADD", "IND", "CLASS", "broken")));
        assertFalse(bad.success());
        ListResponse created = core.executeList(List.of(
                Directive.of("c", "other", "CREATE", "", "", "http://example.org/other", "false", "HERMIT", "false"),
                Directive.of("c", "other", "ADD", "IND", "-", "thing"),
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot5", "Robot")));
        assertTrue(created.success(), () -> created.responses().toString());
        ChangeEvent creation = next();
        assertEquals("other", creation.reference());
        assertEquals(0, creation.revision());
        ChangeEvent otherChange = next();
        ChangeEvent mapChange = next();
        assertEquals("other", otherChange.reference());
        assertEquals(1, otherChange.revision());
        assertEquals("map", mapChange.reference());
        assertEquals(2, mapChange.revision(), "the rolled-back list made no revision");
        noMore();
    }

    @Test
    void bufferedChangesApplyAndReasonAreRevisionsAndDropIsTheLastEvent() throws Exception {
        ArmorCore core = core(1000);
        ok(core, "LOAD FILE", ROBOTICS, "", "true", "HERMIT", "true");
        ok(core, "ADD IND CLASS", "robot2", "Robot");
        ok(core, "APPLY");
        ok(core, "REASON");
        ok(core, "DROP");
        List<Long> revisions = new ArrayList<>();
        for (int i = 0; i < 5; i++) {
            revisions.add(next().revision());
        }
        assertEquals(List.of(0L, 1L, 2L, 3L, 4L), revisions);
        noMore();
        ok(core, "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "false");
        assertEquals(0, next().revision(), "a reference loaded again starts again");
    }

    @Test
    void revisionsContinueAfterARestartAcrossCheckpoints() throws Exception {
        ArmorCore first = core(3);
        ok(first, "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true");
        for (int i = 0; i < 10; i++) {
            ok(first, "ADD IND CLASS", "bot" + i, "Robot");
        }
        first.executeList(List.of(Directive.of("c", "map", "ADD", "IND", "CLASS", "bot10", "Robot"),
                Directive.of("c", "map", "ADD", "IND", "CLASS", "bot11", "Robot")));
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (checkpointRevision() == 0 && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertTrue(checkpointRevision() > 0, "no checkpoint was written");
        events.clear();

        ArmorCore second = core(3);
        noMore();
        ok(second, "ADD IND CLASS", "bot12", "Robot");
        assertEquals(12, next().revision());
    }

    @Test
    void journalsWrittenBeforeRevisionsCountOneRevisionPerRecord() throws Exception {
        ArmorCore first = core(1000);
        ok(first, "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true");
        ok(first, "ADD IND CLASS", "robot2", "Robot");
        ok(first, "ADD IND CLASS", "robot3", "Robot");
        first.close();
        // Rewrite the journal as the version before revisions did: each record a bare array.
        Path meta = stateDir.resolve("refs/map/meta.json");
        Files.writeString(meta, Files.readString(meta).replaceAll(",\"checkpoint_revision\":\\d+", ""));
        Path journal;
        try (Stream<Path> files = Files.list(stateDir.resolve("refs/map"))) {
            journal = files.filter(f -> f.getFileName().toString().startsWith("journal-")).findFirst().orElseThrow();
        }
        java.io.ByteArrayOutputStream old = new java.io.ByteArrayOutputStream();
        for (String robot : List.of("robot2", "robot3")) {
            byte[] payload = ("[{\"client_name\":\"c\",\"reference_name\":\"map\",\"command\":\"ADD\","
                    + "\"primary_command_spec\":\"IND\",\"secondary_command_spec\":\"CLASS\",\"args\":[\""
                    + robot + "\",\"Robot\"]}]").getBytes(java.nio.charset.StandardCharsets.UTF_8);
            java.util.zip.CRC32C crc = new java.util.zip.CRC32C();
            crc.update(payload);
            old.writeBytes(java.nio.ByteBuffer.allocate(8).putInt(payload.length).putInt((int) crc.getValue())
                    .array());
            old.writeBytes(payload);
        }
        Files.write(journal, old.toByteArray());
        events.clear();

        ArmorCore second = core(1000);
        assertEquals(CoreFixture.iris("robot1", "robot2", "robot3"),
                run(second, "c", "QUERY IND CLASS", "Robot").queriedObjects());
        ok(second, "ADD IND CLASS", "robot4", "Robot");
        assertEquals(3, next().revision());
    }

    @Test
    void noListenerNoQueue() {
        CoreFixture fixture = new CoreFixture();
        fixture.loadRobotics("map", "HERMIT", false);
        for (int i = 0; i < 50; i++) {
            fixture.ok("map", "ADD IND CLASS", "bot" + i, "Robot");
        }
        assertEquals(0, fixture.core.events().backlog(), "events nobody listens to are not kept");
    }

    private long checkpointRevision() throws Exception {
        String meta = Files.readString(stateDir.resolve("refs").resolve("map").resolve("meta.json"));
        var json = com.google.gson.JsonParser.parseString(meta).getAsJsonObject().getAsJsonObject("meta");
        return json.has("checkpoint_revision") ? json.get("checkpoint_revision").getAsLong() : 0;
    }
}
