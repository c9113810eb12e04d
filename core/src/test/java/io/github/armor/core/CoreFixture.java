// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.nio.file.Path;
import java.util.List;

/** A core over the repository's test ontologies, with short helpers for directives. */
final class CoreFixture {
    static final Path ONTOLOGIES = Path.of("..", "ontologies").toAbsolutePath().normalize();
    static final Path TEST_ONTOLOGIES = Path.of("..", "tests", "ontologies").toAbsolutePath().normalize();
    static final String NS = "http://www.example.org/robotics#";

    final ArmorCore core;

    CoreFixture(Path... extraDirs) {
        Path[] dirs = new Path[extraDirs.length + 2];
        dirs[0] = ONTOLOGIES;
        dirs[1] = TEST_ONTOLOGIES;
        System.arraycopy(extraDirs, 0, dirs, 2, extraDirs.length);
        // The test's own folders are read and written; the shipped ontologies only read.
        core = new ArmorCore(CoreConfig.defaults(dirs).withWriting(CoreConfig.Writing.into(extraDirs)));
    }

    CoreFixture(CoreConfig config) {
        this(new ArmorCore(config));
    }

    CoreFixture(ArmorCore core) {
        this.core = core;
    }

    /** Runs "COMMAND PRIMARY SECONDARY" (specs may be omitted) on a reference as client "test". */
    Response run(String reference, String words, String... args) {
        return runAs("test", reference, words, args);
    }

    Response runAs(String client, String reference, String words, String... args) {
        String[] parts = (words + " - -").trim().split("\\s+");
        return core.execute(Directive.of(client, reference, parts[0], parts[1], parts[2], args));
    }

    Response ok(String reference, String words, String... args) {
        Response response = run(reference, words, args);
        assertTrue(response.success(), () -> words + " failed: " + response.exitCode() + " "
                + response.errorDescription());
        return response;
    }

    void loadRobotics(String reference, String reasoner, boolean bufferedReasoner) {
        ok(reference, "LOAD FILE", ONTOLOGIES.resolve("robotics.owl").toString(), "http://www.example.org/robotics",
                "false", reasoner, String.valueOf(bufferedReasoner));
    }

    /**
     * A core on a state directory as a restart makes one: the cores in {@code running} closed
     * first (they release the directory), its state restored (unless {@code restore} is false);
     * it joins {@code running}.
     */
    static ArmorCore restartOn(List<ArmorCore> running, Path stateDir, String reasoner, boolean restore,
                               boolean fsync, int checkpointEvery) {
        running.forEach(ArmorCore::close);
        ArmorCore core = new ArmorCore(new CoreConfig(true, reasoner, List.of(ONTOLOGIES), false, 30_000, 0, 0,
                new CoreConfig.Durability(stateDir, restore, fsync, checkpointEvery, 3600)));
        core.restoreState();
        running.add(core);
        return core;
    }

    static String iri(String name) {
        return "<" + NS + name + ">";
    }

    static List<String> iris(String... names) {
        return java.util.Arrays.stream(names).map(CoreFixture::iri).sorted().toList();
    }

    static void assertFails(Response response, int code) {
        assertEquals(code, response.exitCode(), () -> "expected exit code " + code + " but got "
                + response.exitCode() + " " + response.errorDescription());
        assertTrue(!response.success(), "a failing directive must answer success=false");
        assertTrue(!response.errorDescription().isBlank(), "a failure must be described");
    }
}
