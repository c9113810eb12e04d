// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import java.util.List;

/**
 * One COMMAND PRIMARY SECONDARY combination: what it targets, whether the mount guards it, and
 * the arguments it takes (named, for error messages and for the commands reference).
 */
public record CommandSpec(
        String key,
        Target target,
        boolean mountChecked,
        List<String> required,
        List<String> optional,
        boolean variadic,
        Handler handler) {

    /** What the reference name of a directive must name. */
    public enum Target {
        /** Works without a reference (GET ALL REFS, LOG). */
        NONE,
        /** Creates the reference (LOAD, CREATE). */
        NEW,
        /** An existing reference. */
        EXISTING
    }

    @FunctionalInterface
    public interface Handler {
        Response run(CommandContext context);
    }

    /** Checks the argument count, naming what was expected. */
    public void checkArity(int given) {
        int min = required.size();
        int max = variadic ? Integer.MAX_VALUE : min + optional.size();
        if (given < min || given > max) {
            String expected = variadic ? "at least " + min
                    : optional.isEmpty() ? String.valueOf(min) : min + " to " + max;
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, key + " takes " + expected + " argument(s) "
                    + signature() + ", got " + given);
        }
    }

    public String signature() {
        StringBuilder text = new StringBuilder("(");
        text.append(String.join(", ", required));
        for (String name : optional) {
            text.append(text.length() > 1 ? ", " : "").append('[').append(name).append(']');
        }
        if (variadic) {
            text.append(", ...");
        }
        return text.append(')').toString();
    }
}
