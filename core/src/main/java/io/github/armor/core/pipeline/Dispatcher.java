// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.pipeline;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.AnswerSource;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandKind;
import io.github.armor.core.command.CommandSpec;
import io.github.armor.core.command.CommandSuggestions;
import io.github.armor.core.command.CommandTable;
import java.util.Optional;

/**
 * The command a directive names, found once for directives and subscriptions alike: the lookup,
 * the reference name its target needs, the argument count, and the sources that may answer it
 * without waiting. It knows commands only by what their registrations say.
 */
public final class Dispatcher {
    private final CommandTable commands;

    public Dispatcher(CommandTable commands) {
        this.commands = commands;
    }

    public CommandTable commands() {
        return commands;
    }

    /** The command of a client's directive, checked; otherwise the exit code that refuses it. */
    CommandSpec resolve(Directive directive) {
        CommandSpec spec = commands.find(directive.key()).orElse(null);
        if (directive.referenceName().isEmpty() && (spec == null || spec.target() != CommandKind.Target.NONE)) {
            throw new ArmorException(ExitCode.NO_REFERENCE_NAME, "no reference name given"
                    + (directive.command().isEmpty() ? "" : " for " + directive.describe()));
        }
        if (directive.command().isEmpty()) {
            throw new ArmorException(ExitCode.NO_COMMAND, "no command given");
        }
        if (spec == null) {
            throw new ArmorException(ExitCode.UNKNOWN_COMMAND, "unknown command '" + directive.describe()
                    + "' (read as " + directive.key() + "); closest: " + String.join("; ",
                    CommandSuggestions.closest(commands.catalogue(), directive.key(), directive.args().size())));
        }
        spec.checkArity(directive.args());
        return spec;
    }

    /** The command a subscription asks: a QUERY, checked as a directive's is. */
    CommandSpec resolveQuery(Directive query) {
        CommandSpec spec = commands.find(query.key()).orElse(null);
        if (spec == null || spec.kind() != CommandKind.QUERY) {
            throw new ArmorException(ExitCode.UNKNOWN_COMMAND, "only a query (a QUERY command) can be"
                    + " subscribed to; " + query.describe() + (spec == null ? " is not a command"
                    : " is a " + spec.kind().catalogueName()));
        }
        return resolve(query);
    }

    /**
     * The directive a subscription to {@code query} asks: the command its registration names
     * ({@link CommandTable.Builder#subscribedAs}), in the client's spelling where the words agree.
     */
    public Directive standingForm(Directive query) {
        CommandSpec spec = commands.find(query.key()).orElse(null);
        if (spec == null || spec.subscribedAs().isEmpty() || spec.subscribedAs().equals(spec.key())) {
            return query;
        }
        String[] asked = spec.subscribedAs().split(" ");
        String[] written = {query.command(), query.primarySpec(), query.secondarySpec()};
        for (int i = 0; i < asked.length; i++) {
            asked[i] = asked[i].equals("-") ? "" : written[i].equalsIgnoreCase(asked[i]) ? written[i] : asked[i];
        }
        return new Directive(query.clientName(), query.referenceName(), asked[0], asked[1], asked[2], query.args());
    }

    /**
     * A question's answer without waiting for its reference, which another directive holds: the
     * first its registered sources give, or empty (the handler answers, holding the reference).
     */
    Optional<Response> answerWhileBusy(CommandSpec spec, CommandContext context) {
        if (spec.kind() != CommandKind.QUERY) {
            return Optional.empty();
        }
        for (AnswerSource source : spec.whileBusy()) {
            Optional<Response> answer = source.answer(context);
            if (answer.isPresent()) {
                return answer;
            }
        }
        return Optional.empty();
    }
}
