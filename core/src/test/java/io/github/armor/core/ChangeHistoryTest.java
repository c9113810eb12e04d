// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.reference.ChangeHistory;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * GET REF REVISION and GET REF CHANGES: how a client whose answer was lost learns whether its
 * change was applied (issue 20 item 6), in memory and across a restart with checkpoints.
 */
class ChangeHistoryTest {
    private static final String ROBOTICS = CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString();

    @TempDir
    Path stateDir;

    private final List<ArmorCore> cores = new ArrayList<>();

    @AfterEach
    void closeCores() {
        cores.forEach(ArmorCore::close);
    }

    private ArmorCore core(int checkpointEvery) {
        return CoreFixture.restartOn(cores, stateDir, "PELLET", true, false, checkpointEvery);
    }

    private static Response run(ArmorCore core, String client, String reference, String words, String... args) {
        return new CoreFixture(core).runAs(client, reference, words, args);
    }

    private static Response ok(ArmorCore core, String client, String reference, String words, String... args) {
        Response response = run(core, client, reference, words, args);
        assertTrue(response.success(), () -> words + ": " + response.exitCode() + " " + response.errorDescription());
        return response;
    }

    private static long revision(ArmorCore core, String reference) {
        return Long.parseLong(ok(core, "c", "", "GET REF REVISION", reference).queriedObjects().get(0));
    }

    private static List<JsonObject> changes(ArmorCore core, String reference, long since) {
        return ok(core, "c", "", "GET REF CHANGES", reference, Long.toString(since)).queriedObjects().stream()
                .map(line -> JsonParser.parseString(line).getAsJsonObject()).toList();
    }

    /** "client COMMAND PRIMARY SECONDARY arg..." of each directive of a change. */
    private static List<String> described(JsonObject change) {
        List<String> out = new ArrayList<>();
        change.getAsJsonArray("directives").forEach(element -> {
            JsonObject d = element.getAsJsonObject();
            StringBuilder text = new StringBuilder(d.get("client_name").getAsString()).append(' ')
                    .append(d.get("command").getAsString()).append(' ')
                    .append(d.get("primary_command_spec").getAsString()).append(' ')
                    .append(d.get("secondary_command_spec").getAsString());
            d.getAsJsonArray("args").forEach(arg -> text.append(' ').append(arg.getAsString()));
            out.add(text.toString());
        });
        return out;
    }

    @Test
    void eachAcknowledgedChangeIsKeptWithItsRevisionAndClientAndNothingElse() {
        ArmorCore core = core(1000);
        ok(core, "c", "map", "LOAD FILE", ROBOTICS, "", "false", "PELLET", "false");
        assertEquals(0, revision(core, "map"));
        ok(core, "alice", "map", "ADD IND CLASS", "robot2", "Robot");
        assertFalse(run(core, "alice", "map", "ADD IND CLASS", "robot3").success());   // refused: no revision
        ok(core, "bob", "map", "QUERY IND CLASS", "Robot");                            // a read: no revision
        Response list = core.executeList(List.of(
                Directive.of("bob", "map", "ADD", "IND", "CLASS", "robot4", "Robot"),
                Directive.of("bob", "map", "ADD", "IND", "CLASS", "robot5", "Robot"))).responses().get(0);
        assertTrue(list.success());

        assertEquals(2, revision(core, "map"));
        List<JsonObject> all = changes(core, "map", 0);
        assertEquals(List.of(1L, 2L), all.stream().map(c -> c.get("revision").getAsLong()).toList());
        assertEquals(List.of("alice ADD IND CLASS robot2 Robot"), described(all.get(0)));
        assertEquals(List.of("bob ADD IND CLASS robot4 Robot", "bob ADD IND CLASS robot5 Robot"),
                described(all.get(1)));
        assertEquals(1, changes(core, "map", 1).size());
        assertEquals(List.of(), changes(core, "map", 2));
        // Only the changes one client took part in.
        List<String> bobs = ok(core, "c", "", "GET REF CHANGES", "map", "", "bob").queriedObjects();
        assertEquals(1, bobs.size());
        assertTrue(bobs.get(0).contains("robot4"), bobs.get(0));
        assertEquals(List.of(), ok(core, "c", "", "GET REF CHANGES", "map", "1", "alice").queriedObjects());
        // No argument: the directive's own reference, every kept change.
        assertEquals(2, ok(core, "c", "map", "GET REF CHANGES").queriedObjects().size());
        assertEquals(List.of("2"), ok(core, "c", "map", "GET REF REVISION").queriedObjects());
    }

    @Test
    void aBadRevisionOrAnUnknownReferenceIsAClearError() {
        ArmorCore core = core(1000);
        ok(core, "c", "map", "LOAD FILE", ROBOTICS, "", "false", "PELLET", "false");
        assertEquals(101, run(core, "c", "", "GET REF CHANGES", "map", "three").exitCode());
        assertEquals(206, run(core, "c", "", "GET REF CHANGES", "nowhere").exitCode());
        assertEquals(206, run(core, "c", "", "GET REF REVISION", "nowhere").exitCode());
    }

    @Test
    void theHistoryOutlivesARestartAndTheCheckpointsThatDeleteItsJournals() {
        ArmorCore first = core(3);
        ok(first, "c", "map", "LOAD FILE", ROBOTICS, "", "false", "PELLET", "false");
        for (int i = 1; i <= 10; i++) {
            ok(first, "c" + i, "map", "ADD IND CLASS", "robot" + (100 + i), "Robot");
        }
        ArmorCore second = core(3);
        assertEquals(10, revision(second, "map"));
        List<JsonObject> kept = changes(second, "map", 0);
        assertEquals(10, kept.size());
        for (int i = 1; i <= 10; i++) {
            assertEquals(i, kept.get(i - 1).get("revision").getAsLong());
            assertEquals(List.of("c" + i + " ADD IND CLASS robot" + (100 + i) + " Robot"), described(kept.get(i - 1)));
        }
        ok(second, "d", "map", "ADD IND CLASS", "robot200", "Robot");
        assertEquals(11, changes(core(3), "map", 0).size());
    }

    @Test
    void onlyTheLatestChangesAreKeptAndTheAnswerSaysWhereItStarts() {
        ArmorCore core = core(100_000);
        ok(core, "c", "map", "CREATE", "http://example.org/h", "false", "PELLET", "true");
        int made = ChangeHistory.MAX_CHANGES + 5;
        for (int i = 0; i < made; i++) {
            ok(core, "c", "map", "ADD IND", "i" + i);
        }
        Response answer = ok(core, "c", "", "GET REF CHANGES", "map", "0");
        assertTrue(answer.errorDescription().contains("from revision 1 to 5 are no longer kept"),
                answer.errorDescription());
        // Every kept change, one bounded answer after the other, each saying where to go on.
        List<Long> revisions = new java.util.ArrayList<>();
        while (true) {
            List<String> page = answer.queriedObjects();
            assertTrue(page.size() <= ChangeHistory.PAGE_CHANGES, page.size() + " changes in one answer");
            page.forEach(text -> revisions.add(JsonParser.parseString(text).getAsJsonObject().get("revision")
                    .getAsLong()));
            int more = answer.errorDescription().indexOf(ChangeHistory.MORE_AFTER);
            if (more < 0) {
                break;
            }
            long last = revisions.get(revisions.size() - 1);
            assertTrue(answer.errorDescription().startsWith(ChangeHistory.MORE_AFTER + last, more),
                    answer.errorDescription());
            answer = ok(core, "c", "", "GET REF CHANGES", "map", Long.toString(last));
        }
        assertEquals(java.util.stream.LongStream.rangeClosed(6, made).boxed().toList(), revisions);
        assertEquals("", ok(core, "c", "", "GET REF CHANGES", "map", Long.toString(made - 10)).errorDescription());
    }
}
