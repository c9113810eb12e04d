// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.assertFails;
import static io.github.armor.core.CoreFixture.iris;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandTable;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;

/**
 * Questions about types on a reference that a writer holds are answered from the last state the
 * writer finished, at once and marked with its revision, instead of waiting (issue 15); the
 * writer's unfinished change stays invisible until it lets the reference go.
 */
class ReadersNeverWaitTest {
    private static final String ROBOTICS = CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString();
    private static final Pattern REVISION = Pattern.compile("revision (\\d+)");

    private final CountDownLatch writerInside = new CountDownLatch(1);
    private final CountDownLatch letWriterGo = new CountDownLatch(1);
    // What the slow writer does on its own thread while it holds the reference, before it says it is inside.
    private volatile Runnable whileHeld = () -> { };
    private final ArmorCore core = new ArmorCore(new CoreConfig(true, "HERMIT", List.of(CoreFixture.ONTOLOGIES), false,
            300, 0, 0, CoreConfig.Durability.NONE), withSlowWriter());

    /** The standard commands plus one that moves robot1 to the bedroom, then holds the reference until told. */
    private CommandTable withSlowWriter() {
        CommandTable table = CommandTable.standard();
        table.command("TEST MOVE SLOWLY").args("prop", "ind", "new room", "old room")
                .summary("moves an agent and keeps the reference").manipulation(c -> {
            OWLDataFactory factory = c.factory();
            OWLObjectProperty isIn = c.objectProperty(0);
            OWLNamedIndividual robot = c.individual(1);
            c.reference().change(List.of(
                    new org.semanticweb.owlapi.model.RemoveAxiom(c.reference().ontology(),
                            factory.getOWLObjectPropertyAssertionAxiom(isIn, robot, c.individual(3))),
                    new org.semanticweb.owlapi.model.AddAxiom(c.reference().ontology(),
                            factory.getOWLObjectPropertyAssertionAxiom(isIn, robot, c.individual(2)))));
            whileHeld.run();
            writerInside.countDown();
            try {
                letWriterGo.await(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return c.ok();
        });
        return table;
    }

    private Response run(String reference, String words, String... args) {
        String[] parts = (words + " - -").split("\\s+");
        return core.execute(Directive.of("test", reference, parts[0], parts[1], parts[2], args));
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT"})
    void typeQueriesOnAHeldReferenceAnswerTheLastFinishedStateAtOnce(String reasoner) throws Exception {
        assertTrue(run("map", "LOAD FILE", ROBOTICS, "", "false", reasoner, "false").success());
        assertEquals(iris("kitchen"), run("map", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        assertTrue(run("map", "ADD IND CLASS", "robot2", "Robot").success());

        CompletableFuture<Response> writer = CompletableFuture.supplyAsync(() -> run("map", "TEST MOVE SLOWLY",
                "isIn", "robot1", "bedroom", "kitchen"));
        assertTrue(writerInside.await(10, TimeUnit.SECONDS));

        // A reader that waited would get 211 after the 300 ms bound: the writer holds on for 10 s.
        Response occupied = run("map", "QUERY IND CLASS", "OccupiedRoom");
        Response types = run("map", "QUERY CLASS IND", "robot2", "true");
        assertTrue(occupied.success() && occupied.isConsistent(), occupied.errorDescription());
        assertEquals(iris("kitchen"), occupied.queriedObjects(), "the writer's unfinished move must not show");
        assertEquals(iris("Robot"), types.queriedObjects());
        assertEquals(iris("Agent", "Robot"), run("map", "QUERY IND", "robot2").queriedObjects());
        long before = revision(occupied);
        assertEquals(before, revision(types));
        // A question the state cannot answer still waits for the reference, within the bound.
        assertFails(run("map", "QUERY OBJECTPROP IND", "isIn", "robot1"), 211);
        assertFalse(writer.isDone());

        letWriterGo.countDown();
        assertTrue(writer.get(10, TimeUnit.SECONDS).success());
        assertEquals(iris("bedroom"), run("map", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        assertEquals("", run("map", "QUERY IND CLASS", "OccupiedRoom").errorDescription(),
                "an answer under the lock is the ordinary one, with no revision note");
    }

    /**
     * The web view's pages read the published state, off the reference's lock (issue 28): a page
     * refreshing while a writer holds the reference neither waits for it nor makes it wait.
     */
    @org.junit.jupiter.api.Test
    void webViewsOfAHeldReferenceAnswerFromTheLastFinishedState() throws Exception {
        assertTrue(run("map", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "false").success());
        assertEquals(iris("kitchen"), run("map", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        io.github.armor.core.view.ReferenceViews views = core.views();
        CompletableFuture<Response> writer = CompletableFuture.supplyAsync(() -> run("map", "TEST MOVE SLOWLY",
                "isIn", "robot1", "bedroom", "kitchen"));
        assertTrue(writerInside.await(10, TimeUnit.SECONDS));
        // Each would answer 211 after the 300 ms lock wait if it took the reference's lock.
        for (String request : List.of("{\"name\": \"overview\"}",
                "{\"name\": \"individuals\", \"reference\": \"map\", \"search\": \"kitchen\"}",
                "{\"name\": \"graph\", \"reference\": \"map\"}",
                "{\"name\": \"classes\", \"reference\": \"map\"}")) {
            com.google.gson.JsonObject answer = views.answer(com.google.gson.JsonParser.parseString(request)
                    .getAsJsonObject());
            assertFalse(answer.has("error"), () -> request + " waited for the writer: " + answer);
        }
        com.google.gson.JsonObject graph = views.answer(com.google.gson.JsonParser.parseString(
                "{\"name\": \"graph\", \"reference\": \"map\"}").getAsJsonObject());
        assertFalse(graph.get("inferred_links").getAsBoolean(), "a held reference's graph is its published state's");
        com.google.gson.JsonObject page = views.answer(com.google.gson.JsonParser.parseString(
                "{\"name\": \"individuals\", \"reference\": \"map\", \"search\": \"kitchen\"}")
                .getAsJsonObject());
        assertTrue(page.toString().contains("OccupiedRoom"), "the kitchen as the last finished state has it: " + page);
        assertFalse(writer.isDone());
        letWriterGo.countDown();
        assertTrue(writer.get(10, TimeUnit.SECONDS).success());
    }

    /**
     * A client reads its own writes. The writer holds the reference; on its thread (re-entering
     * the reference, as a directive run inside a held reference does) client "mover" adds two
     * robots, and that change is acknowledged. Readers' state is offered only when the outermost
     * holder lets go, so the published state is older than mover's change: mover's question must
     * wait for the writer and then see its robots, never be answered from that state.
     */
    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void aClientThatChangedTheReferenceIsNeverAnsweredFromAStateBeforeItsChange(String reasoner) throws Exception {
        // Its readers wait up to 30 s for the reference, so that waiting is never mistaken for a timeout.
        try (ArmorCore patient = new ArmorCore(new CoreConfig(true, "HERMIT", List.of(CoreFixture.ONTOLOGIES), false,
                30_000, 0, 0, CoreConfig.Durability.NONE), withSlowWriter())) {
            askTheMoverWhileTheWriterHolds(patient, reasoner);
        }
    }

    private void askTheMoverWhileTheWriterHolds(ArmorCore patient, String reasoner) throws Exception {
        assertTrue(patient.execute(Directive.of("test", "map", "LOAD", "FILE", "", ROBOTICS, "", "false", reasoner,
                "false")).success());
        CompletableFuture<Boolean> moverChanged = new CompletableFuture<>();
        whileHeld = () -> moverChanged.complete(patient.executeList(List.of(
                Directive.of("mover", "map", "ADD", "IND", "CLASS", "robot2", "Robot"),
                Directive.of("mover", "map", "ADD", "IND", "CLASS", "robot3", "Robot"))).success());
        CompletableFuture<Response> writer = CompletableFuture.supplyAsync(() -> patient.execute(Directive.of("test",
                "map", "TEST", "MOVE", "SLOWLY", "isIn", "robot1", "bedroom", "kitchen")));
        assertTrue(writerInside.await(10, TimeUnit.SECONDS));
        assertTrue(moverChanged.get(), "mover's change was acknowledged while the writer held the reference");
        Response stale = patient.execute(Directive.of("other", "map", "QUERY", "IND", "CLASS", "Robot"));
        assertEquals(iris("robot1"), stale.queriedObjects(), "the setting up: another client is answered at once"
                + " from the state published before mover's change: " + stale.errorDescription());

        CompletableFuture<Response> own = new CompletableFuture<>();
        Thread asker = new Thread(() -> own.complete(patient.execute(Directive.of("mover", "map", "QUERY", "IND",
                "CLASS", "Robot"))));
        asker.start();
        // Either mover's question is answered (from the old state: the failure this test is for) or it parks on the lock.
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!own.isDone() && asker.getState() != Thread.State.TIMED_WAITING && System.nanoTime() < deadline) {
            Thread.sleep(5);
        }
        assertFalse(own.isDone(), () -> "mover was answered from a state before its change: "
                + own.join().queriedObjects() + " " + own.join().errorDescription());
        letWriterGo.countDown();
        assertTrue(writer.get(10, TimeUnit.SECONDS).success());
        Response answer = own.get(10, TimeUnit.SECONDS);
        assertTrue(answer.success(), () -> answer.exitCode() + " " + answer.errorDescription());
        assertEquals(iris("robot1", "robot2", "robot3"), answer.queriedObjects());
        assertEquals("", answer.errorDescription(), "answered under the lock, after the writer, not from a state");
    }

    @ParameterizedTest
    @ValueSource(strings = {"true", "false"})
    void withoutAPublishedStateReadersWaitAsBefore(String bufferedReasoner) throws Exception {
        // A buffered reasoner (and ELK) keeps no published state: the query waits and times out.
        String reasoner = bufferedReasoner.equals("true") ? "HERMIT" : "ELK";
        assertTrue(run("map", "LOAD FILE", ROBOTICS, "", "false", reasoner, bufferedReasoner).success());
        CompletableFuture<Response> writer = CompletableFuture.supplyAsync(() -> run("map", "TEST MOVE SLOWLY",
                "isIn", "robot1", "bedroom", "kitchen"));
        assertTrue(writerInside.await(10, TimeUnit.SECONDS));
        assertFails(run("map", "QUERY IND CLASS", "Robot"), 211);
        letWriterGo.countDown();
        assertTrue(writer.get(10, TimeUnit.SECONDS).success());
    }

    private static long revision(Response response) {
        Matcher matcher = REVISION.matcher(response.errorDescription());
        assertTrue(matcher.find(), "no revision in '" + response.errorDescription() + "'");
        return Long.parseLong(matcher.group(1));
    }
}
