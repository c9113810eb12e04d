// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandSpec;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.command.DirectiveLog;
import io.github.armor.core.command.Rendering;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.reference.ReferenceRegistry;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The knowledge core's single entry point: a directive (or an atomic list of them) in, ARMOR's
 * response out. Every failure becomes an exit code here; nothing a client sends escapes as an
 * exception. Thread-safe: directives on different references run in parallel.
 */
public final class ArmorCore {
    private static final Logger LOG = LoggerFactory.getLogger(ArmorCore.class);

    private final CoreConfig config;
    private final CommandTable commands = CommandTable.standard();
    private final ReferenceRegistry references = new ReferenceRegistry();
    private final Rendering rendering;
    private final DirectiveLog directiveLog = new DirectiveLog(System.err);
    private final Map<String, Long> lastHeardFrom = new ConcurrentHashMap<>();

    public ArmorCore(CoreConfig config) {
        this.config = config;
        this.rendering = new Rendering(config.fullEntityIri());
    }

    /** The answer of a list: one response per directive, in order. */
    public record ListResponse(boolean success, boolean isConsistent, List<Response> responses) {}

    public CommandTable commands() {
        return commands;
    }

    public Response execute(Directive directive) {
        return run(directive, null);
    }

    /**
     * Runs directives in order. When one fails, the changes the earlier ones made are undone and
     * the later ones are not run; both answer {@link ExitCode#ROLLED_BACK}.
     */
    public ListResponse executeList(List<Directive> directives) {
        ListState state = new ListState();
        try {
            return runList(directives, state);
        } finally {
            state.releaseAll();
        }
    }

    private ListResponse runList(List<Directive> directives, ListState state) {
        List<Response> responses = new ArrayList<>();
        int failed = -1;
        for (int i = 0; i < directives.size() && failed < 0; i++) {
            state.position = i;
            Response response = run(directives.get(i), state);
            responses.add(response);
            if (!response.success()) {
                failed = i;
            }
        }
        if (failed < 0) {
            state.commit();
            boolean consistent = responses.isEmpty() || responses.get(responses.size() - 1).isConsistent();
            return new ListResponse(true, consistent, responses);
        }
        state.rollback();
        String cause = "directive " + failed + " (" + directives.get(failed).describe() + ") failed: "
                + responses.get(failed).errorDescription();
        for (int i = 0; i < failed; i++) {
            if (state.changedBy.contains(i)) {
                responses.set(i, rolledBack("undone because " + cause, directives.get(i)));
            }
        }
        for (int i = failed + 1; i < directives.size(); i++) {
            responses.add(rolledBack("not run because " + cause, directives.get(i)));
        }
        return new ListResponse(false, responses.get(failed).isConsistent(), responses);
    }

    private Response rolledBack(String description, Directive directive) {
        boolean consistent = references.find(directive.referenceName()).map(Reference::isConsistent).orElse(false);
        return Response.failure(new ArmorException(ExitCode.ROLLED_BACK, description), consistent);
    }

    private Response run(Directive directive, ListState list) {
        Response response;
        try {
            response = dispatch(directive, list);
        } catch (ArmorException e) {
            response = Response.failure(e, consistencyOf(directive));
        } catch (StackOverflowError e) {
            response = Response.failure(new ArmorException(ExitCode.REASONER_FAILED,
                    "stack overflow while answering " + directive.describe() + " (ontology too deep for the reasoner)"),
                    consistencyOf(directive));
        } catch (RuntimeException | LinkageError e) {
            LOG.error("internal error on {}", directive, e);
            response = Response.failure(new ArmorException(ExitCode.INTERNAL_ERROR,
                    "internal error on " + directive.describe() + ": " + e), consistencyOf(directive));
        }
        directiveLog.record(directive, response);
        return response;
    }

    private Response dispatch(Directive directive, ListState list) {
        if (!directive.clientName().isEmpty()) {
            lastHeardFrom.put(directive.clientName(), System.nanoTime());
        }
        CommandSpec spec = commands.find(directive.key()).orElse(null);
        if (directive.referenceName().isEmpty() && (spec == null || spec.target() != CommandSpec.Target.NONE)) {
            throw new ArmorException(ExitCode.NO_REFERENCE_NAME, "no reference name given"
                    + (directive.command().isEmpty() ? "" : " for " + directive.describe()));
        }
        if (directive.command().isEmpty()) {
            throw new ArmorException(ExitCode.NO_COMMAND, "no command given");
        }
        if (spec == null) {
            throw new ArmorException(ExitCode.UNKNOWN_COMMAND, "unknown command '" + directive.describe()
                    + "' (read as " + directive.key() + ")");
        }
        spec.checkArity(directive.args().size());
        return switch (spec.target()) {
            case NONE -> spec.handler().run(context(directive, null));
            case NEW -> create(spec, directive, list);
            case EXISTING -> holdFor(list, references.get(directive.referenceName())).locked(config.lockWaitMs(),
                    reference -> {
                releaseExpiredMount(reference);
                if (spec.mountChecked()) {
                    checkMount(reference, directive);
                    if (list != null) {
                        list.enrol(reference);
                    }
                }
                Response response = spec.handler().run(context(directive, reference));
                if (list != null && spec.mountChecked()) {
                    list.changedBy.add(list.position);
                }
                return response;
            });
        };
    }

    private Response create(CommandSpec spec, Directive directive, ListState list) {
        boolean existed = references.find(directive.referenceName()).isPresent();
        Response response = spec.handler().run(context(directive, null));
        if (list != null) {
            references.find(directive.referenceName()).ifPresent(reference -> {
                holdFor(list, reference);
                if (!existed) {
                    list.created.add(reference);
                    list.changedBy.add(list.position);
                }
            });
        }
        return response;
    }

    /** Inside a list, keeps the reference until the list ends, so no other directive interleaves. */
    private Reference holdFor(ListState list, Reference reference) {
        if (list != null && list.held.add(reference)) {
            try {
                reference.acquire(config.lockWaitMs());
            } catch (ArmorException e) {
                list.held.remove(reference);
                throw e;
            }
        }
        return reference;
    }

    private CommandContext context(Directive directive, Reference reference) {
        return new CommandContext(directive, reference, references, config, rendering, directiveLog);
    }

    private void checkMount(Reference reference, Directive directive) {
        String holder = reference.mountedBy();
        if (!holder.isEmpty() && !holder.equals(directive.clientName())) {
            throw new ArmorException(ExitCode.REFERENCE_MOUNTED, "reference '" + reference.name()
                    + "' is mounted by client '" + holder + "'; " + directive.describe() + " refused, nothing changed");
        }
    }

    private void releaseExpiredMount(Reference reference) {
        String holder = reference.mountedBy();
        if (holder.isEmpty() || config.mountLeaseS() <= 0) {
            return;
        }
        Long heard = lastHeardFrom.get(holder);
        if (heard == null || System.nanoTime() - heard > config.mountLeaseS() * 1_000_000_000L) {
            LOG.info("mount of '{}' by '{}' expired after {} s of silence", reference.name(), holder,
                    config.mountLeaseS());
            reference.setMountedBy("");
        }
    }

    private boolean consistencyOf(Directive directive) {
        return references.find(directive.referenceName()).map(Reference::isConsistent).orElse(false);
    }

    /** What an atomic list has touched so far, to undo it if a later directive fails. */
    private final class ListState {
        final Set<Reference> held = new LinkedHashSet<>();
        final Set<Reference> enrolled = new LinkedHashSet<>();
        final List<Reference> created = new ArrayList<>();
        final Set<Integer> changedBy = new LinkedHashSet<>();
        int position;

        void enrol(Reference reference) {
            if (enrolled.add(reference)) {
                reference.beginTransaction();
            }
        }

        void commit() {
            enrolled.forEach(Reference::commitTransaction);
        }

        void rollback() {
            List<Reference> undo = new ArrayList<>(enrolled);
            java.util.Collections.reverse(undo);
            for (Reference reference : undo) {
                if (!created.contains(reference)) {
                    reference.rollbackTransaction();
                }
            }
            created.forEach(references::remove);
        }

        void releaseAll() {
            held.forEach(Reference::release);
            held.clear();
        }
    }
}
