// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.assertFails;
import static io.github.armor.core.CoreFixture.iris;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.BlockingReasonerFactory.OnInterrupt;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Response;
import io.github.armor.core.reference.ReasonerCalls;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 21 items 1 and 4: a directive whose reasoner overran the time limit answers 211 itself,
 * never what the reasoner returned after the limit, and within the limit plus the margin even
 * when the reasoner ignores the interruption.
 */
class ReasonerTimeLimitTest {
    private static final String BLOCKING = BlockingReasonerFactory.class.getName();
    private static final String ROBOTICS = CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString();
    // Scheduling on a loaded two-core machine: the bound the tests allow beyond limit + margin.
    private static final long SLACK_MS = 2_000;

    @TempDir
    Path scratch;

    @AfterEach
    void unblock() {
        BlockingReasonerFactory.reset();
    }

    private CoreFixture core(long reasonerTimeoutMs) {
        CoreFixture f = new CoreFixture(new CoreConfig(true, "PELLET", List.of(CoreFixture.ONTOLOGIES, scratch),
                false, 30_000, reasonerTimeoutMs, 0, CoreConfig.Durability.NONE).withWriting(
                CoreConfig.Writing.into(scratch)));
        f.ok("map", "LOAD FILE", ROBOTICS, "http://www.example.org/robotics", "false", BLOCKING, "false");
        return f;
    }

    private record Timed(Response response, long ms) {}

    private static Timed timed(Supplier<Response> directive) {
        long start = System.nanoTime();
        Response response = directive.get();
        return new Timed(response, TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start));
    }

    private static void assertOverran(Timed answer, long limitMs) {
        assertFails(answer.response(), 211);
        assertTrue(answer.response().timeout(), "211 must say timeout=true");
        assertTrue(answer.ms() < limitMs + ReasonerCalls.MARGIN_MS + SLACK_MS, "answered after " + answer.ms()
                + " ms for a " + limitMs + " ms limit");
    }

    @ParameterizedTest
    @EnumSource(OnInterrupt.class)
    void aQueryOverTheLimitAnswers211ItselfWhateverTheReasonerDoesWhenInterrupted(OnInterrupt behaviour) {
        CoreFixture f = core(400);
        BlockingReasonerFactory.ON_INTERRUPT.set(behaviour);
        BlockingReasonerFactory.QUERY_BLOCK_MS.set(8_000);
        Timed answer = timed(() -> f.run("map", "QUERY IND CLASS", "Robot"));
        assertOverran(answer, 400);
        assertEquals(behaviour == OnInterrupt.IGNORE, answer.response().errorDescription().contains("ignored"),
                answer.response().errorDescription());

        BlockingReasonerFactory.QUERY_BLOCK_MS.set(0);
        int made = BlockingReasonerFactory.MADE.get();
        assertEquals(iris("robot1"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());
        assertEquals(made + 1, BlockingReasonerFactory.MADE.get(), "the next directive must get a fresh reasoner");
    }

    /** Every path that asks the reasoner: a partial answer after the limit is never a success. */
    @ParameterizedTest
    @ValueSource(strings = {"REASON", "QUERY IND CLASS|Robot", "QUERY IND|robot1", "QUERY CLASS CLASS|Agent",
            "QUERY CLASS DL|Agent", "QUERY IND DL|Agent", "QUERY CLASS IND|robot1|true", "DISJOINT IND CLASS|Room",
            "DISJOINT CLASS CLASS|Agent", "QUERY SPARQL|SELECT ?r WHERE { ?r a :Robot }", "SAVE INFERENCE|@out"})
    void everyReasonerPathAnswers211InsteadOfAPartialAnswer(String call) throws Exception {
        CoreFixture f = core(300);
        String before = saved(f, "before");
        BlockingReasonerFactory.ON_INTERRUPT.set(OnInterrupt.RETURN_PARTIAL);
        BlockingReasonerFactory.BLOCK_MS.set(60_000);
        BlockingReasonerFactory.QUERY_BLOCK_MS.set(60_000);
        String[] parts = call.split("\\|");
        Path out = scratch.resolve("inferred.owl");
        String[] args = java.util.Arrays.stream(parts, 1, parts.length).map(a -> a.equals("@out") ? out.toString() : a)
                .toArray(String[]::new);
        assertOverran(timed(() -> f.run("map", parts[0], args)), 300);
        assertFalse(Files.exists(out), "SAVE INFERENCE wrote a partial file");

        BlockingReasonerFactory.reset();
        assertEquals(before, saved(f, "after"), call + " changed the ontology though it failed");
        assertEquals(iris("robot1"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());
    }

    /** The limit is the directive's, not each reasoner call's: REASON's calls share it. */
    @Test
    void theReasonerCallsOfOneDirectiveShareOneLimit() {
        BlockingReasonerFactory.QUERY_BLOCK_MS.set(0);
        CoreFixture f = core(1_500);
        BlockingReasonerFactory.QUERY_BLOCK_MS.set(900);
        BlockingReasonerFactory.BLOCK_MS.set(900);
        // The consistency check and the classification each fit in 1.5 s; together they do not.
        assertOverran(timed(() -> f.run("map", "REASON")), 1_500);

        CoreFixture roomy = core(4_000);
        BlockingReasonerFactory.QUERY_BLOCK_MS.set(900);
        BlockingReasonerFactory.BLOCK_MS.set(900);
        assertTrue(roomy.run("map", "REASON").success(), "the same REASON within a 4 s limit must succeed");
    }

    @Test
    void aReasonerThatIgnoresTheInterruptionIsLeftBehindAndTheReferenceGoesOn() throws Exception {
        CoreFixture f = core(300);
        BlockingReasonerFactory.ON_INTERRUPT.set(OnInterrupt.IGNORE);
        BlockingReasonerFactory.BLOCK_MS.set(6_000);
        int disposed = BlockingReasonerFactory.DISPOSED.get();
        Timed reason = timed(() -> f.run("map", "REASON"));
        assertOverran(reason, 300);
        assertTrue(reason.ms() < 6_000, "waited for the reasoner: " + reason.ms() + " ms");

        // While the abandoned REASON still runs, the reference answers with a fresh reasoner.
        BlockingReasonerFactory.BLOCK_MS.set(0);
        f.ok("map", "ADD IND CLASS", "robot2", "Robot");
        f.ok("map", "REASON");
        assertEquals(iris("robot1", "robot2"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
        while (BlockingReasonerFactory.DISPOSED.get() == disposed && System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
        assertTrue(BlockingReasonerFactory.DISPOSED.get() > disposed, "the abandoned reasoner was never disposed");
    }

    /** Issue 28 item 5: a reasoner that runs away at LOAD ends at the limit with 211; the reference is there. */
    @Test
    void aReasonerThatRunsAwayAtLoadAnswers211AndLeavesTheReferenceUsable() {
        CoreFixture f = core(300);
        BlockingReasonerFactory.START_BLOCK_MS.set(5_000);
        Timed load = timed(() -> f.run("slow", "LOAD FILE", ROBOTICS, "", "false", BLOCKING, "false"));
        assertOverran(load, 300);
        BlockingReasonerFactory.START_BLOCK_MS.set(0);
        BlockingReasonerFactory.QUERY_BLOCK_MS.set(5_000);
        Timed checking = timed(() -> f.run("checking", "LOAD FILE", ROBOTICS, "", "false", BLOCKING, "false"));
        assertOverran(checking, 300);
        assertTrue(checking.response().errorDescription().contains("loaded but its first reasoning was stopped"),
                checking.response().errorDescription());
        BlockingReasonerFactory.QUERY_BLOCK_MS.set(0);
        assertEquals(List.of("checking", "map", "slow"), f.ok("", "GET ALL REFS").queriedObjects());
        assertEquals(iris("robot1"), f.ok("slow", "QUERY IND CLASS", "Robot").queriedObjects());
        assertEquals(iris("robot1"), f.ok("checking", "QUERY IND CLASS", "Robot").queriedObjects());
        f.ok("slow", "LOAD FILE", ROBOTICS, "", "false", BLOCKING, "false");
    }

    private String saved(CoreFixture f, String tag) throws Exception {
        Path file = scratch.resolve(tag + ".ofn");
        f.ok("map", "SAVE", file.toString(), "functional");
        return Files.readString(file);
    }
}
