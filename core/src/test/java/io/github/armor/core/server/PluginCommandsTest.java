// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandGroup;
import io.github.armor.core.command.CommandSpec;
import io.github.armor.core.command.CommandTable;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A plugin's command runs exactly like a built-in one (lock, mount check, journal, rollback,
 * exit codes), and one that throws or loops answers within its time limit, undoing what it
 * changed, while the core and the reference stay usable.
 */
class PluginCommandsTest {
    private static final Path ONTOLOGIES = Path.of("..", "ontologies").toAbsolutePath().normalize();
    private static final String ROBOTICS = ONTOLOGIES.resolve("robotics.owl").toString();
    private static final String NS = "http://www.example.org/robotics#";
    private static final long LIMIT_MS = 800;

    /** Test commands: each adds "ind a cls" first, then does what its name says. */
    static final String SOURCE = """
            package example;
            import io.github.armor.core.api.ArmorException;
            import io.github.armor.core.api.ExitCode;
            import io.github.armor.core.api.Response;
            import io.github.armor.core.command.CommandContext;
            import io.github.armor.core.command.CommandGroup;
            import io.github.armor.core.command.CommandTable;
            import java.util.List;
            import org.semanticweb.owlapi.model.AddAxiom;
            public final class MarkCommands implements CommandGroup {
                public static volatile long spins;
                private static void mark(CommandContext c) {
                    c.change(List.of(new AddAxiom(c.reference().ontology(),
                            c.factory().getOWLClassAssertionAxiom(c.owlClass(1), c.individual(0)))));
                }
                public void register(CommandTable table) {
                    table.command("ADD MARK IND").args("ind", "class").summary("asserts the class")
                            .manipulation(c -> { mark(c); return c.ok(); });
                    table.command("ADD MARK FAILING").args("ind", "class").summary("asserts, then throws")
                            .manipulation(c -> { mark(c); throw new IllegalStateException("plugin bug"); });
                    table.command("ADD MARK ERROR").args("ind", "class").summary("asserts, then an Error")
                            .manipulation(c -> { mark(c); throw new AssertionError("plugin assertion"); });
                    table.command("ADD MARK REFUSED").args("ind", "class").summary("asserts, then refuses")
                            .manipulation(c -> { mark(c);
                                throw new ArmorException(ExitCode.BAD_DATA_TYPE, "refused by the plugin"); });
                    table.command("ADD MARK LOOPING").args("ind", "class").summary("asserts, then spins")
                            .manipulation(c -> { mark(c); while (true) { spins++; } });
                    table.command("ADD MARK SLEEPING").args("ind", "class", "ms").summary("asserts, then sleeps")
                            .manipulation(c -> { mark(c);
                                try { Thread.sleep(Long.parseLong(c.arg(2))); }
                                catch (InterruptedException e) { throw new IllegalStateException(e); }
                                return c.ok(); });
                    table.command("QUERY MARK REASONING").summary("brings the reasoner up to date")
                            .query(c -> { c.reference().reason(); return c.ok(); });
                    table.command("QUERY MARK SLEEPING").args("ms").summary("holds the reference a while")
                            .query(c -> {
                                try { Thread.sleep(Long.parseLong(c.arg(0))); }
                                catch (InterruptedException e) { return c.ok(List.of("interrupted")); }
                                return c.ok(List.of("slept"));
                            });
                }
            }
            """;
    static final String BROKEN = """
            package example;
            public final class BrokenCommands implements io.github.armor.core.command.CommandGroup {
                public void register(io.github.armor.core.command.CommandTable table) {
                    table.command("QUERY BROKEN").summary("never registered").query(c -> c.ok());
                    throw new IllegalStateException("cannot register");
                }
            }
            """;
    static final String CLASHING = """
            package example;
            public final class ClashingCommands implements io.github.armor.core.command.CommandGroup {
                public void register(io.github.armor.core.command.CommandTable table) {
                    table.command("QUERY CLASH").summary("would be left out with its group").query(c -> c.ok());
                    table.command("QUERY IND CLASS").args("class").summary("takes a built-in key").query(c -> c.ok());
                }
            }
            """;

    @TempDir
    static Path built;

    @TempDir
    Path scratch;

    private static ClassLoader pluginLoader;
    private static CommandTable table;
    private final List<ArmorCore> cores = new ArrayList<>();

    @BeforeAll
    static void buildPlugins() throws Exception {
        Path plugins = Files.createDirectories(built.resolve("plugins"));
        PluginJars.build(built.resolve("build"), plugins.resolve("marks.jar"),
                Map.of("example.MarkCommands", SOURCE, "example.BrokenCommands", BROKEN,
                        "example.ClashingCommands", CLASHING),
                Map.of(CommandGroup.class.getName(),
                        "example.BrokenCommands\nexample.MarkCommands\nexample.ClashingCommands"),
                CommandGroup.class, org.semanticweb.owlapi.model.OWLAxiom.class);
        pluginLoader = Plugins.classLoader(List.of(plugins.toString()));
        table = CommandTable.load(pluginLoader);
    }

    @AfterEach
    void closeCores() {
        cores.forEach(ArmorCore::close);
    }

    private ArmorCore core(long lockWaitMs, Path stateDir) {
        return core(lockWaitMs, stateDir, 0, "HERMIT");
    }

    private ArmorCore core(long lockWaitMs, Path stateDir, long reasonerTimeoutMs, String reasoner) {
        return core(lockWaitMs, stateDir, reasonerTimeoutMs, reasoner, LIMIT_MS);
    }

    private ArmorCore core(long lockWaitMs, Path stateDir, long reasonerTimeoutMs, String reasoner, long pluginLimitMs) {
        CoreConfig.Durability durability = stateDir == null ? CoreConfig.Durability.NONE
                : new CoreConfig.Durability(stateDir, true, true, 1000, 3600);
        cores.forEach(ArmorCore::close);
        ArmorCore core = new ArmorCore(new CoreConfig(true, "HERMIT", List.of(ONTOLOGIES, scratch), false, lockWaitMs,
                reasonerTimeoutMs, 0, durability, new CoreConfig.Safeguards(30_000, false, false, false, pluginLimitMs)),
                table);
        core.restoreState();
        cores.add(core);
        ok(core, "c", "map", "LOAD FILE", ROBOTICS, "", "false", reasoner, "false");
        return core;
    }

    private static Response run(ArmorCore core, String client, String reference, String words, String... args) {
        String[] parts = (words + " - -").split("\\s+");
        return core.execute(Directive.of(client, reference, parts[0], parts[1], parts[2], args));
    }

    private static Response ok(ArmorCore core, String client, String reference, String words, String... args) {
        Response response = run(core, client, reference, words, args);
        assertTrue(response.success(), () -> words + ": " + response.exitCode() + " " + response.errorDescription());
        return response;
    }

    private static List<String> robots(ArmorCore core) {
        return ok(core, "c", "map", "QUERY IND CLASS", "Robot").queriedObjects();
    }

    private static String iri(String name) {
        return "<" + NS + name + ">";
    }

    @Test
    void pluginCommandsCarryTheirJarAsOriginAndBrokenGroupsAreLeftOutWhole() {
        CommandSpec mark = table.find("ADD MARK IND").orElseThrow();
        assertEquals("marks.jar", mark.origin());
        assertEquals("core", table.find("QUERY IND CLASS").orElseThrow().origin());
        assertTrue(table.find("QUERY BROKEN -").isEmpty());
        assertTrue(table.find("QUERY CLASH -").isEmpty());
        assertEquals(CommandTable.standard().catalogue().size() + 8, table.catalogue().size());
    }

    @Test
    void aPluginChangeIsRefusedUnderAnotherClientsMountAndUndoneWithItsList() {
        ArmorCore core = core(30_000, null);
        ok(core, "holder", "map", "MOUNT");
        Response refused = run(core, "other", "map", "ADD MARK IND", "robot2", "Robot");
        assertEquals(ExitCode.REFERENCE_MOUNTED.code(), refused.exitCode());
        ok(core, "holder", "map", "UNMOUNT");

        ListResponse list = core.executeList(List.of(
                Directive.of("c", "map", "ADD", "MARK", "IND", "robot2", "Robot"),
                Directive.of("c", "map", "QUERY", "NOSUCH", "")));
        assertFalse(list.success());
        assertEquals(ExitCode.ROLLED_BACK.code(), list.responses().get(0).exitCode());
        assertEquals(List.of(iri("robot1")), robots(core));

        ok(core, "c", "map", "ADD MARK IND", "robot2", "Robot");
        assertEquals(List.of(iri("robot1"), iri("robot2")), robots(core));
    }

    @Test
    void aPluginChangeIsJournaledAndSurvivesARestart() {
        Path state = scratch.resolve("state");
        ok(core(30_000, state), "c", "map", "ADD MARK IND", "robot2", "Robot");
        assertEquals(List.of(iri("robot1"), iri("robot2")), robots(core(30_000, state)));
    }

    @Test
    void whatAPluginThrowsBecomesAnAnswerAndItsChangeIsUndone() {
        ArmorCore core = core(30_000, null);
        Response failed = run(core, "c", "map", "ADD MARK FAILING", "robot2", "Robot");
        assertEquals(ExitCode.INTERNAL_ERROR.code(), failed.exitCode());
        assertTrue(failed.errorDescription().contains("ADD MARK FAILING (plugin marks.jar) failed"),
                failed.errorDescription());
        assertTrue(failed.errorDescription().contains("plugin bug"), failed.errorDescription());
        Response error = run(core, "c", "map", "ADD MARK ERROR", "robot2", "Robot");
        assertEquals(ExitCode.INTERNAL_ERROR.code(), error.exitCode());
        assertTrue(error.errorDescription().contains("AssertionError"), error.errorDescription());
        Response refused = run(core, "c", "map", "ADD MARK REFUSED", "robot2", "Robot");
        assertEquals(ExitCode.BAD_DATA_TYPE.code(), refused.exitCode());
        assertEquals("refused by the plugin", refused.errorDescription());
        assertEquals(List.of(iri("robot1")), robots(core));
    }

    @Test
    void aLoopingPluginIsStoppedAtItsTimeLimitAndItsChangeUndone() {
        ArmorCore core = core(30_000, null);
        long start = System.nanoTime();
        Response looped = run(core, "c", "map", "ADD MARK LOOPING", "robot2", "Robot");
        long tookMs = (System.nanoTime() - start) / 1_000_000;
        assertEquals(ExitCode.TIMEOUT.code(), looped.exitCode(), looped.errorDescription());
        assertTrue(looped.timeout());
        assertTrue(looped.errorDescription().contains("plugin_timeout_ms=" + LIMIT_MS), looped.errorDescription());
        // Interrupt ignored: stopped after one grace period, answered before a second one ends.
        assertTrue(tookMs >= LIMIT_MS && tookMs < LIMIT_MS + 2 * 2_000 + 1_000, "took " + tookMs + " ms");
        long spins = spins();
        assertEquals(List.of(iri("robot1")), robots(core));
        assertEquals(spins, spins(), "the looping thread was stopped");
        ok(core, "c", "map", "ADD MARK IND", "robot2", "Robot");
        assertEquals(List.of(iri("robot1"), iri("robot2")), robots(core));
    }

    @Test
    void aLoopingPluginInAListIsStoppedAndTheWholeListUndone() {
        ArmorCore core = core(30_000, null);
        ListResponse list = core.executeList(List.of(
                Directive.of("c", "map", "ADD", "MARK", "IND", "robot2", "Robot"),
                Directive.of("c", "map", "ADD", "MARK", "LOOPING", "robot3", "Robot")));
        assertFalse(list.success());
        assertEquals(ExitCode.ROLLED_BACK.code(), list.responses().get(0).exitCode());
        assertEquals(ExitCode.TIMEOUT.code(), list.responses().get(1).exitCode());
        assertEquals(List.of(iri("robot1")), robots(core));
    }

    @Test
    void aPluginsReasonerCallsAreBoundByTheReasonerTimeLimit() throws Exception {
        java.lang.reflect.Field block = io.github.armor.core.BlockingReasonerFactory.class.getDeclaredField("BLOCK_MS");
        block.setAccessible(true);
        java.util.concurrent.atomic.AtomicLong blockMs = (java.util.concurrent.atomic.AtomicLong) block.get(null);
        // Limits far apart and each far above what the loaded map's reasoning takes: the LOAD of the set-up
        // (bound by the reasoner limit too) once ran past a limit of 200 ms on a machine under load.
        long pluginLimitMs = 20_000;
        ArmorCore core = core(30_000, null, 2_000, io.github.armor.core.BlockingReasonerFactory.class.getName(),
                pluginLimitMs);
        blockMs.set(60_000);
        try {
            long start = System.nanoTime();
            Response reasoned = run(core, "c", "map", "QUERY MARK REASONING");
            long tookMs = (System.nanoTime() - start) / 1_000_000;
            assertEquals(ExitCode.TIMEOUT.code(), reasoned.exitCode(), reasoned.errorDescription());
            assertTrue(reasoned.errorDescription().contains("exceeded the reasoner time limit of 2000 ms"),
                    reasoned.errorDescription());
            assertTrue(tookMs < pluginLimitMs, "took " + tookMs + " ms: the reasoner limit, not the plugin's, ended it");
        } finally {
            blockMs.set(0);
        }
        assertEquals(List.of(iri("robot1")), robots(core));
    }

    @Test
    void aSleepingPluginIsInterruptedAtItsTimeLimit() {
        ArmorCore core = core(30_000, null);
        long start = System.nanoTime();
        Response slept = run(core, "c", "map", "ADD MARK SLEEPING", "robot2", "Robot", "60000");
        long tookMs = (System.nanoTime() - start) / 1_000_000;
        assertEquals(ExitCode.TIMEOUT.code(), slept.exitCode(), slept.errorDescription());
        assertTrue(tookMs < LIMIT_MS + 2_000, "took " + tookMs + " ms");
        assertEquals(List.of(iri("robot1")), robots(core));
    }

    @Test
    void aPluginHoldsItsReferenceLikeABuiltInAndNoOther() throws Exception {
        ArmorCore core = core(200, null);
        ok(core, "c", "other", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "false");
        CompletableFuture<Response> holding = CompletableFuture.supplyAsync(
                () -> run(core, "c", "map", "QUERY MARK SLEEPING", "600"));
        Thread.sleep(150);
        // A question the last reasoned state cannot answer (QUERY IND CLASS it could, without waiting).
        Response waited = run(core, "c", "map", "QUERY OBJECTPROP IND", "isIn", "robot1");
        assertEquals(ExitCode.TIMEOUT.code(), waited.exitCode(), waited.errorDescription());
        assertTrue(waited.errorDescription().contains("stayed busy"), waited.errorDescription());
        assertEquals(List.of(iri("robot1")), ok(core, "c", "other", "QUERY IND CLASS", "Robot").queriedObjects());
        assertEquals(List.of("slept"), holding.get(10, TimeUnit.SECONDS).queriedObjects());
        assertEquals(List.of(iri("robot1")), robots(core));
    }

    private static long spins() {
        try {
            return pluginLoader.loadClass("example.MarkCommands").getField("spins").getLong(null);
        } catch (ReflectiveOperationException e) {
            throw new AssertionError(e);
        }
    }
}
