// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.pddl;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.spi.CommandGroup;
import io.github.armor.core.spi.CommandTable;
import io.github.armor.core.spi.Context;
import io.github.armor.core.spi.FaceAnswer;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The planner bridge's commands (docs/pddl.md): a PDDL problem generated from what a reference
 * knows, under a mapping given as a file inside allowed_dirs or as the text itself; SAVE writes
 * inside write_dirs only, as the core's SAVE.
 */
public final class PddlCommands implements CommandGroup {
    /** Larger mapping files are refused (a mapping is a few dozen lines). */
    static final long MAX_MAPPING_BYTES = 1 << 20;

    @Override
    public void register(CommandTable table) {
        table.command("QUERY PDDL PROBLEM").args("mapping path or text")
                .summary("a PDDL problem from the reference's asserted and inferred knowledge (docs/pddl.md)")
                .face("pddl_problem", FaceAnswer.EXPRESSIONS, "mapping")
                .query(c -> c.ok(List.of(problem(c).text())));
        table.command("SAVE PDDL PROBLEM").args("mapping path or text", "path")
                .summary("write that PDDL problem to a file inside write_dirs")
                .onReference(c -> {
                    Path target = c.paths().writable(c.arg(1));
                    String text = problem(c).text();
                    c.paths().write(target, out -> out.write(text.getBytes(StandardCharsets.UTF_8)));
                    return c.ok();
                });
    }

    private static PddlProblem problem(Context c) {
        return new ProblemGenerator(c.knowledge()).generate(Mapping.parse(mappingText(c, c.arg(0))));
    }

    /** The mapping itself (text holding a line break or starting with '{'), or the file it names. */
    static String mappingText(Context c, String argument) {
        String trimmed = argument.trim();
        if (trimmed.startsWith("{") || trimmed.contains("\n")) {
            return argument;
        }
        Path file = c.paths().readable(trimmed);
        try {
            if (!Files.isRegularFile(file)) {
                throw new ArmorException(ExitCode.LOAD_FAILED, "mapping file " + file + " does not exist");
            }
            if (Files.size(file) > MAX_MAPPING_BYTES) {
                throw new ArmorException(ExitCode.TOO_LARGE, "mapping file '" + trimmed + "' is larger than "
                        + MAX_MAPPING_BYTES + " bytes");
            }
            return Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "mapping file '" + trimmed + "' could not be read: "
                    + e.getMessage(), e);
        }
    }
}
