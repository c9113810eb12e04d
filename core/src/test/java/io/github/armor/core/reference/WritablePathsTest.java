// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What may be written (issue 27): only inside write_dirs, never what no setting can open. */
class WritablePathsTest {
    @TempDir
    Path scratch;

    private WritablePaths rule(Path writeDir, Path stateDir, Path installation) {
        CoreConfig config = new CoreConfig(true, "HERMIT", List.of(scratch), false, 30_000, 0, 0,
                new CoreConfig.Durability(stateDir, false, false, 1000, 60), CoreConfig.Safeguards.DEFAULT,
                new CoreConfig.Writing(List.of(writeDir), List.of(installation), List.of()));
        return WritablePaths.of(config);
    }

    private static int refused(WritablePaths rule, Path path) {
        return assertThrows(ArmorException.class, () -> rule.check(path.toString())).exitCode().code();
    }

    @Test
    void onlyInsideWriteDirsAndNeverWhereNoSettingReaches() throws IOException {
        Path files = scratch.resolve("files");
        Path state = files.resolve("state");
        Path code = files.resolve("code");
        WritablePaths rule = rule(files, state, code);
        assertEquals(List.of(), rule.prepare());
        assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(files)));
        assertEquals(files.resolve("maps/a.owl"), rule.check(files.resolve("maps/a.owl").toString()));
        assertEquals(213, refused(rule, files.resolve(".bashrc")));
        assertEquals(213, refused(rule, files.resolve(".venv/lib/x.pth")));
        assertEquals(213, refused(rule, state.resolve("refs/map/meta.json")));
        assertEquals(213, refused(rule, code.resolve("module.py")));
        assertEquals(213, refused(rule, scratch.resolve("beside.owl")));
        assertEquals(213, refused(rule, Path.of("/tmp/x.owl")));
        assertEquals(213, refused(rule, Path.of(System.getProperty("user.home"), "x.owl")));
        assertEquals(213, refused(rule, Path.of(System.getProperty("java.home"), "lib", "x.owl")));
        // /tmp as a write folder: its own files never, a folder inside it yes.
        WritablePaths temporary = rule(Path.of("/tmp"), state, code);
        assertEquals(213, refused(temporary, Path.of("/tmp/x.owl")));
        assertEquals(scratch.resolve("sub/x.owl"), temporary.check(scratch.resolve("sub/x.owl").toString()));
        // A link inside the write folder is judged where it leads.
        Files.createSymbolicLink(files.resolve("to_state"), state);
        assertEquals(213, refused(rule, files.resolve("to_state/x")));
    }

    @Test
    void aWriteFolderNothingCanBeWrittenInStopsTheStart() {
        Path hidden = scratch.resolve(".ros").resolve("armor");
        List<String> problems = rule(hidden, scratch.resolve("state"), scratch.resolve("code")).prepare();
        assertEquals(1, problems.size(), problems.toString());
        assertTrue(problems.get(0).contains(".ros"), problems.get(0));
        assertFalse(Files.exists(hidden));
    }

    @Test
    void aLinkSwappedInAfterTheCheckLeadsNowhere() throws IOException {
        Path files = scratch.resolve("files");
        Path elsewhere = Files.createDirectories(scratch.resolve("elsewhere"));
        WritablePaths rule = rule(files, scratch.resolve("state"), scratch.resolve("code"));
        rule.prepare();
        Path checked = rule.check(files.resolve("maps/today/a.owl").toString());
        rule.write(checked, out -> out.write("first".getBytes(StandardCharsets.UTF_8)));
        assertEquals("first", Files.readString(checked));
        // The race: between the check and the write, a folder on the way becomes a link.
        Path again = rule.check(files.resolve("maps/today/a.owl").toString());
        Path today = files.resolve("maps/today");
        Files.move(today, scratch.resolve("moved"));
        Files.createSymbolicLink(today, elsewhere);
        ArmorException refused = assertThrows(ArmorException.class,
                () -> rule.write(again, out -> out.write("second".getBytes(StandardCharsets.UTF_8))));
        assertEquals(213, refused.exitCode().code(), refused.getMessage());
        try (var left = Files.list(elsewhere)) {
            assertEquals(0, left.count(), "something was written through the link");
        }
    }
}
