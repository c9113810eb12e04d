// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.pipeline.Dispatcher;
import io.github.armor.core.spi.FaceAnswer;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.semanticweb.owlapi.model.EntityType;

/**
 * A plugin registers, through the SPI alone, what the built-in queries have: an answer from the
 * last published state while a writer holds the reference (whileBusy), the form a subscription
 * asks (subscribedAs) and a face.
 */
class PluginStateAnswersTest {
    private static final Path ONTOLOGIES = Path.of("..", "ontologies").toAbsolutePath().normalize();
    private static final String KITCHEN = "<http://www.example.org/robotics#kitchen>";

    private final CountDownLatch writerInside = new CountDownLatch(1);
    private final CompletableFuture<Void> letWriterGo = new CompletableFuture<>();
    private final CommandTable table = tableWithPlugin();
    private final ArmorCore core = new ArmorCore(new CoreConfig(true, "HERMIT", List.of(ONTOLOGIES), false,
            300, 0, 0, CoreConfig.Durability.NONE), table);

    @AfterEach
    void close() {
        letWriterGo.complete(null);
        core.close();
    }

    /** The standard commands, a writer that holds the reference until told, and a plugin's group seen through the SPI. */
    private CommandTable tableWithPlugin() {
        CommandTable commands = CommandTable.standard();
        commands.command("TEST HOLD").summary("keeps the reference").manipulation(c -> {
            writerInside.countDown();
            letWriterGo.completeOnTimeout(null, 10, TimeUnit.SECONDS).join();
            return c.ok();
        });
        io.github.armor.core.spi.CommandTable plugin = new PluginTable(commands);
        plugin.command("QUERY ROOMS OCCUPIED").summary("the rooms someone is in")
                .face("occupied_rooms", FaceAnswer.ENTITIES)
                .whileBusy(state -> state.known(EntityType.CLASS, "OccupiedRoom")
                        .map(room -> state.render(state.instances(room).stream())))
                .query(c -> c.ok(c.render(c.knowledge().instances(
                        c.knowledge().entity(EntityType.CLASS, "OccupiedRoom"), false).stream())));
        plugin.command("QUERY ROOMS SENTENCES").args("class").summary("a sentence per instance")
                .subscribedAs("QUERY IND CLASS")
                .query(c -> c.ok(c.knowledge().instances(c.owlClass(0), false).stream()
                        .map(room -> "someone is in " + room.getIRI().getShortForm()).sorted().toList()));
        return commands;
    }

    private Response run(String words, String... args) {
        String[] parts = (words + " - -").split("\\s+");
        return core.execute(Directive.of("test", "map", parts[0], parts[1], parts[2], args));
    }

    private void load() {
        assertTrue(run("LOAD FILE", ONTOLOGIES.resolve("robotics.owl").toString(), "", "false", "HERMIT", "false")
                .success());
        assertEquals(List.of(KITCHEN), run("QUERY ROOMS OCCUPIED").queriedObjects());
    }

    @Test
    void aPluginQueryIsAnsweredFromThePublishedStateWhileAWriterHoldsTheReference() throws Exception {
        load();
        CompletableFuture<Response> writer = CompletableFuture.supplyAsync(() -> run("TEST HOLD"));
        assertTrue(writerInside.await(10, TimeUnit.SECONDS));
        // Waiting would give 211 after the 300 ms lock wait: the writer holds on for 10 s.
        Response occupied = run("QUERY ROOMS OCCUPIED");
        assertTrue(occupied.success(), occupied.errorDescription());
        assertEquals(List.of(KITCHEN), occupied.queriedObjects());
        assertTrue(occupied.errorDescription().startsWith("answered from reasoned state revision"),
                occupied.errorDescription());
        // Without a source the plugin's other query waits for the reference, and gives up.
        assertEquals(211, run("QUERY ROOMS SENTENCES", "OccupiedRoom").exitCode());
        assertFalse(writer.isDone());
        letWriterGo.complete(null);
        assertTrue(writer.get(10, TimeUnit.SECONDS).success());
        assertEquals("", run("QUERY ROOMS OCCUPIED").errorDescription(), "a free reference answers the ordinary way");
    }

    @Test
    void aSubscriptionToAPluginQueryAsksTheFormItsRegistrationNames() {
        Dispatcher dispatcher = new Dispatcher(table);
        Directive standing = dispatcher.standingForm(Directive.of("test", "map", "query", "rooms", "sentences",
                "OccupiedRoom"));
        assertEquals("QUERY IND CLASS", standing.key());
        assertEquals(List.of("OccupiedRoom"), standing.args());
        load();
        Response first = core.subscriptions().subscribe("rooms", Directive.of("test", "map", "QUERY", "ROOMS",
                "SENTENCES", "OccupiedRoom"), null).response();
        assertTrue(first.success(), first.errorDescription());
        assertEquals(List.of(KITCHEN), first.queriedObjects());
    }

    @Test
    void aPluginFaceIsInTheCatalogue() {
        assertEquals(Optional.of(new Face("occupied_rooms", Face.Answer.ENTITIES, List.of())),
                table.face("QUERY ROOMS OCCUPIED"));
    }
}
