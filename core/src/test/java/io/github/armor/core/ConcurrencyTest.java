// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.assertFails;
import static io.github.armor.core.CoreFixture.iris;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Bounded waits, reasoner time limits, mount leases and list isolation (issue 4). */
class ConcurrencyTest {
    private static final String BLOCKING = BlockingReasonerFactory.class.getName();
    private static final String ROBOTICS = CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString();

    @AfterEach
    void unblock() {
        BlockingReasonerFactory.reset();
    }

    private static ArmorCore core(long lockWaitMs, long reasonerTimeoutMs, long mountLeaseS) {
        return new ArmorCore(new CoreConfig(true, "HERMIT", List.of(CoreFixture.ONTOLOGIES), false, lockWaitMs,
                reasonerTimeoutMs, mountLeaseS, CoreConfig.Durability.NONE));
    }

    private static Response run(ArmorCore core, String client, String reference, String words, String... args) {
        String[] parts = (words + " - -").split("\\s+");
        return core.execute(Directive.of(client, reference, parts[0], parts[1], parts[2], args));
    }

    @Test
    void aBusyReferenceAnswersTimeoutWhileOthersAnswerAtOnce() throws Exception {
        ArmorCore core = core(300, 0, 0);
        assertTrue(run(core, "a", "slow", "LOAD FILE", ROBOTICS, "", "false", BLOCKING, "true").success());
        assertTrue(run(core, "a", "fast", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true").success());
        BlockingReasonerFactory.BLOCK_MS.set(3_000);
        CompletableFuture<Response> reason = CompletableFuture.supplyAsync(() -> run(core, "a", "slow", "REASON"));
        Thread.sleep(200);

        long start = System.nanoTime();
        Response waiting = run(core, "b", "slow", "QUERY IND CLASS", "Robot");
        long waitedMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        assertFails(waiting, 211);
        assertTrue(waiting.timeout(), "a bounded wait must say timeout=true");
        assertTrue(waitedMs >= 250 && waitedMs < 2_500, "waited " + waitedMs + " ms for a 300 ms bound");

        assertEquals(iris("kitchen"), run(core, "b", "fast", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        assertTrue(!reason.isDone(), "the slow REASON should still be running");
        assertTrue(reason.get(10, TimeUnit.SECONDS).success());
        assertEquals(iris("robot1"), run(core, "b", "slow", "QUERY IND CLASS", "Robot").queriedObjects());
    }

    @Test
    void aReasonerOverItsTimeLimitIsInterruptedAndTheReferenceStaysUsable() {
        ArmorCore core = core(30_000, 500, 0);
        assertTrue(run(core, "a", "map", "LOAD FILE", ROBOTICS, "", "false", BLOCKING, "true").success());
        BlockingReasonerFactory.BLOCK_MS.set(60_000);
        long start = System.nanoTime();
        Response reason = run(core, "a", "map", "REASON");
        long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        assertFails(reason, 211);
        assertTrue(reason.timeout());
        assertTrue(reason.errorDescription().contains("interrupted"), reason.errorDescription());
        assertTrue(tookMs < 10_000, "the time limit did not stop the reasoner: " + tookMs + " ms");

        BlockingReasonerFactory.BLOCK_MS.set(0);
        assertTrue(run(core, "a", "map", "ADD IND CLASS", "robot2", "Robot").success());
        assertTrue(run(core, "a", "map", "REASON").success());
        assertEquals(iris("robot1", "robot2"), run(core, "a", "map", "QUERY IND CLASS", "Robot").queriedObjects());
    }

    @Test
    void aSilentHolderLosesItsMountAfterTheLease() throws Exception {
        ArmorCore core = core(30_000, 0, 1);
        assertTrue(run(core, "planner", "map", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true").success());
        assertTrue(run(core, "planner", "map", "MOUNT").success());
        assertFails(run(core, "other", "map", "ADD IND CLASS", "robot2", "Robot"), 102);
        Thread.sleep(1_500);
        assertTrue(run(core, "other", "map", "ADD IND CLASS", "robot2", "Robot").success());
        assertEquals(List.of(), run(core, "other", "", "GET REF CLIENT", "map").queriedObjects());
    }

    @Test
    void aListKeepsOtherWritersOutUntilItEnds() throws Exception {
        ArmorCore core = core(300, 0, 0);
        assertTrue(run(core, "a", "map", "LOAD FILE", ROBOTICS, "", "false", BLOCKING, "true").success());
        BlockingReasonerFactory.BLOCK_MS.set(1_500);
        CompletableFuture<ListResponse> list = CompletableFuture.supplyAsync(() -> core.executeList(List.of(
                Directive.of("a", "map", "ADD", "IND", "CLASS", "robot2", "Robot"),
                Directive.of("a", "map", "REASON", "", ""),
                Directive.of("a", "map", "ADD", "IND", "CLASS", "robot3", "Robot"),
                Directive.of("a", "map", "ADD", "IND", "CLASS", "robot4", "NoSuchArity", "extra"))));
        Thread.sleep(300);
        Response intruder = run(core, "b", "map", "ADD IND CLASS", "intruder", "Robot");
        assertFails(intruder, 211);
        ListResponse answer = list.get(10, TimeUnit.SECONDS);
        assertEquals(List.of(212, 212, 212, 207), answer.responses().stream().map(Response::exitCode).toList());
        assertEquals(iris("robot1"), run(core, "b", "map", "QUERY IND CLASS", "Robot").queriedObjects());
    }
}
