// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import java.util.List;

/**
 * One COMMAND PRIMARY SECONDARY combination: its kind, the arguments it takes (named, for error
 * messages and the catalogue), what it does in one line, and the code that answers it.
 *
 * @param key                 the dispatch key, {@code "QUERY IND CLASS"}, {@code "DROP - -"}
 * @param aliases             other keys answered the same way ({@code "ADD MIN CARDINALITY"})
 * @param emptySurplusIgnored empty strings after the last argument are accepted and ignored: ROS 1
 *                            ARMOR read only the arguments it named, so old clients send
 *                            {@code ['']} to REASON or MOUNT as a dummy
 * @param origin              where it comes from: {@code "core"}, or the file name of the plugin jar
 * @param whileBusy           what answers it while another directive holds its reference, in order
 *                            (none: it waits for the reference)
 * @param subscribedAs        the key a subscription to it asks instead (its answer as one line per
 *                            item), or empty: itself
 */
public record CommandSpec(
        String key,
        List<String> aliases,
        CommandKind kind,
        List<String> required,
        List<String> optional,
        boolean variadic,
        boolean emptySurplusIgnored,
        String summary,
        String origin,
        Handler handler,
        List<AnswerSource> whileBusy,
        String subscribedAs) {

    @FunctionalInterface
    public interface Handler {
        Response run(CommandContext context);
    }

    public CommandSpec {
        aliases = List.copyOf(aliases);
        required = List.copyOf(required);
        optional = List.copyOf(optional);
        whileBusy = List.copyOf(whileBusy);
    }

    public CommandKind.Target target() {
        return kind.target();
    }

    public boolean mountChecked() {
        return kind.mountChecked();
    }

    /**
     * Checks the argument count, naming what was expected. Surplus arguments are refused unless
     * they are all empty strings and the command ignores those ({@link #emptySurplusIgnored}).
     */
    public void checkArity(List<String> args) {
        int given = args.size();
        int min = required.size();
        int max = variadic ? Integer.MAX_VALUE : min + optional.size();
        if (given > max && emptySurplusIgnored && args.subList(max, given).stream().allMatch(String::isEmpty)) {
            return;
        }
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
