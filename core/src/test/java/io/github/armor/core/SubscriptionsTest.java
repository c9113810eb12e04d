// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.iri;
import static io.github.armor.core.CoreFixture.iris;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.Directive;
import io.github.armor.core.events.AnswerEvent;
import io.github.armor.core.events.CoreEvent;
import io.github.armor.core.events.Subscriptions;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Standing queries (issue 12): answers that appear and disappear, inferred ones included. */
class SubscriptionsTest {
    private static final String OCCUPIED = "QUERY IND CLASS";

    private final CoreFixture fixture = new CoreFixture();
    private final LinkedBlockingQueue<AnswerEvent> answers = new LinkedBlockingQueue<>();

    @BeforeEach
    void load() {
        fixture.loadRobotics("map", "HERMIT", false);
        fixture.core.events().addListener(this::collect);
    }

    @AfterEach
    void close() {
        fixture.core.close();
    }

    private void collect(CoreEvent event) {
        if (event instanceof AnswerEvent answer) {
            answers.add(answer);
        }
    }

    private Subscriptions.Evaluation subscribe(String id, String words, String... args) {
        String[] parts = (words + " - -").split("\\s+");
        return fixture.core.subscriptions().subscribe(id, Directive.of("watcher", "map", parts[0], parts[1], parts[2],
                args), null);
    }

    private AnswerEvent next() throws InterruptedException {
        AnswerEvent event = answers.poll(20, TimeUnit.SECONDS);
        assertNotNull(event, "no answer event within 20 s");
        return event;
    }

    private void noMore() throws InterruptedException {
        assertNull(answers.poll(500, TimeUnit.MILLISECONDS));
    }

    @Test
    void anInferredAnswerAppearsWhenAPersonEntersARoomAndGoesWhenSheLeaves() throws Exception {
        Subscriptions.Evaluation first = subscribe("occupied", OCCUPIED, "OccupiedRoom");
        assertTrue(first.response().success());
        assertEquals(iris("kitchen"), first.response().queriedObjects());
        AnswerEvent initial = next();
        assertEquals("occupied", initial.subscription());
        assertEquals(List.of(iri("kitchen")), initial.added());
        assertEquals(first.revision(), initial.revision());

        fixture.ok("map", "REPLACE OBJECTPROP IND", "isIn", "alice", "bedroom", "corridor1");
        AnswerEvent entered = next();
        assertEquals(List.of(iri("bedroom")), entered.added());
        assertEquals(List.of(), entered.removed());
        assertEquals(first.revision() + 1, entered.revision());

        fixture.ok("map", "ADD IND CLASS", "robot2", "Robot");
        fixture.ok("map", "REPLACE OBJECTPROP IND", "isIn", "alice", "corridor1", "bedroom");
        AnswerEvent left = next();
        assertEquals(List.of(), left.added());
        assertEquals(List.of(iri("bedroom")), left.removed());
        assertEquals(first.revision() + 3, left.revision(), "a change that moves no answer says nothing");
        noMore();
    }

    @Test
    void sparqlRowsAreAnswersToo() throws Exception {
        Subscriptions.Evaluation first = subscribe("rows", "QUERY SPARQL FORMATTED",
                "SELECT ?who ?room WHERE { ?who :isIn ?room . ?room a :Room }");
        assertTrue(first.response().success(), first.response().errorDescription());
        assertEquals(List.of("who=" + iri("robot1") + "; room=" + iri("kitchen")), next().added());
        fixture.ok("map", "ADD OBJECTPROP IND", "isIn", "alice", "bedroom");
        assertEquals(List.of("who=" + iri("alice") + "; room=" + iri("bedroom")), next().added());
    }

    @Test
    void onlyQueriesCanBeSubscribedAndAFailedOneRegistersNothing() throws Exception {
        assertEquals(205, subscribe("change", "ADD IND CLASS", "robot9", "Robot").response().exitCode());
        assertEquals(208, subscribe("bad", "QUERY SPARQL", "SELECT WHERE {").response().exitCode());
        assertEquals(206, fixture.core.subscriptions().subscribe("gone", Directive.of("w", "nowhere", "QUERY", "IND",
                "CLASS", "Room"), null).response().exitCode());
        assertEquals(0, fixture.core.subscriptions().count());
        assertEquals(iris("robot1"), fixture.ok("map", "QUERY IND CLASS", "Robot").queriedObjects(),
                "the refused ADD changed nothing");
        noMore();
    }

    @Test
    void anUnsubscribedQueryIsNotAskedAgain() throws Exception {
        subscribe("robots", OCCUPIED, "Robot");
        next();
        assertTrue(fixture.core.subscriptions().unsubscribe("robots"));
        assertFalse(fixture.core.subscriptions().unsubscribe("robots"));
        fixture.ok("map", "ADD IND CLASS", "robot2", "Robot");
        noMore();
        assertEquals(0, fixture.core.subscriptions().count());
    }

    @Test
    void aDroppedReferenceRemovesEveryAnswerAndALoadBringsThemBack() throws Exception {
        subscribe("robots", OCCUPIED, "Robot");
        next();
        fixture.ok("map", "DROP");
        AnswerEvent dropped = next();
        assertEquals(206, dropped.exitCode());
        assertEquals(iris("robot1"), dropped.removed());
        fixture.loadRobotics("map", "HERMIT", false);
        AnswerEvent loaded = next();
        assertEquals(0, loaded.exitCode());
        assertEquals(iris("robot1"), loaded.added());
        assertEquals(0, loaded.revision());
    }

    @Test
    void anInconsistentReferenceIsAnnouncedOnceAndTheDiffResumesAfterIt() throws Exception {
        subscribe("robots", OCCUPIED, "Robot");
        next();
        fixture.ok("map", "ADD IND CLASS", "kitchen", "Corridor");
        AnswerEvent inconsistent = next();
        assertEquals(217, inconsistent.exitCode());
        assertTrue(inconsistent.added().isEmpty() && inconsistent.removed().isEmpty());
        fixture.ok("map", "ADD IND CLASS", "robot2", "Robot");
        noMore();
        fixture.ok("map", "REMOVE IND CLASS", "kitchen", "Corridor");
        AnswerEvent back = next();
        assertEquals(0, back.exitCode());
        assertEquals(List.of(iri("robot2")), back.added());
    }

    /** Issue 35 item 8: once the reference is consistent again, its subscriber hears so, even with the same answer. */
    @Test
    void theEndOfAnInconsistencyIsAnnouncedEvenWhenTheAnswerIsUnchanged() throws Exception {
        subscribe("robots", OCCUPIED, "Robot");
        next();
        fixture.ok("map", "ADD IND CLASS", "kitchen", "Corridor");
        assertEquals(217, next().exitCode());
        fixture.ok("map", "REMOVE IND CLASS", "kitchen", "Corridor");
        AnswerEvent repaired = next();
        assertEquals(0, repaired.exitCode());
        assertTrue(repaired.added().isEmpty() && repaired.removed().isEmpty());
        assertEquals(2, repaired.revision());
        fixture.ok("map", "ADD IND CLASS", "robot2", "Robot");
        assertEquals(List.of(iri("robot2")), next().added());
        noMore();
    }

    @Test
    void burstsOfChangesLoseAndRepeatNothingAndTheLastAnswerHoldsAtTheLastRevision() throws Exception {
        subscribe("robots", OCCUPIED, "Robot");
        next();
        for (int i = 0; i < 40; i++) {
            fixture.ok("map", "ADD IND CLASS", "bot" + i, "Robot");
        }
        java.util.Set<String> added = new java.util.HashSet<>();
        AnswerEvent event = null;
        while (added.size() < 40) {
            event = next();
            for (String robot : event.added()) {
                assertTrue(added.add(robot), "announced twice: " + robot);
            }
            assertTrue(event.removed().isEmpty());
        }
        assertEquals(40, event.revision());
        noMore();
    }

    @Test
    void aSteadyStreamOfChangesPostponesAnswersAtMostAboutASecond() throws Exception {
        subscribe("robots", OCCUPIED, "Robot");
        next();
        long start = System.nanoTime();
        long streamNanos = 3 * Subscriptions.MAX_DELAY_MS * 1_000_000L;
        int i = 0;
        while (System.nanoTime() - start < streamNanos) {
            fixture.ok("map", "ADD IND CLASS", "bot" + i++, "Robot");
        }
        long streamEnd = System.currentTimeMillis();
        AnswerEvent during = next();
        assertTrue(during.stampNs() / 1_000_000 < streamEnd, "no answer while the changes kept coming");
        assertTrue(during.revision() < i, "the first answer came only after the last change");
    }

    @Test
    void aClientThatKnowsTheAnswerIsToldOnlyWhatChanged() throws Exception {
        Subscriptions.Evaluation first = fixture.core.subscriptions().subscribe("again", Directive.of("w", "map",
                "QUERY", "IND", "CLASS", "Robot"), List.of(iri("robot1"), iri("robotGone")));
        assertTrue(first.response().success());
        AnswerEvent diff = next();
        assertEquals(List.of(), diff.added());
        assertEquals(List.of(iri("robotGone")), diff.removed());
        fixture.core.subscriptions().subscribe("same", Directive.of("w", "map", "QUERY", "IND", "CLASS", "Robot"),
                List.of(iri("robot1")));
        noMore();
    }
}
