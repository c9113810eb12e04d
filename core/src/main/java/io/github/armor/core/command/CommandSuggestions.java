// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.reference.EntityResolver;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;

/**
 * The registered combinations closest to one the core does not know, for the 205 answer: a
 * misspelt spec ({@code QUERY IND CLASSS}) should lead to the command meant, not to a guess.
 * Closeness is the edit distance between the written keys; a combination that takes the
 * directive's number of arguments ranks before one that does not.
 */
public final class CommandSuggestions {
    private static final int SHOWN = 3;

    private CommandSuggestions() {}

    /** Up to three combinations, closest first, each written with its arguments. */
    public static List<String> closest(Collection<CommandSpec> specs, String key, int argumentCount) {
        record Scored(CommandSpec spec, int score) {}
        List<Scored> ranked = specs.stream()
                .map(spec -> new Scored(spec, EntityResolver.editDistance(key, spec.key(), Integer.MAX_VALUE) * 2
                        + (accepts(spec, argumentCount) ? 0 : 1)))
                .sorted(Comparator.comparingInt(Scored::score).thenComparing(s -> s.spec().key()))
                .toList();
        if (ranked.isEmpty()) {
            return List.of();
        }
        int best = ranked.get(0).score();
        return ranked.stream().filter(s -> s.score() <= best + 4).limit(SHOWN)
                .map(s -> s.spec().key().replace(" -", "") + " " + s.spec().signature()).toList();
    }

    private static boolean accepts(CommandSpec spec, int count) {
        return count >= spec.required().size()
                && (spec.variadic() || count <= spec.required().size() + spec.optional().size());
    }
}
