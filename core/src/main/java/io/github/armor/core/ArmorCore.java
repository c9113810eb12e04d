// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import io.github.armor.core.api.AcknowledgedChange;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.api.SizeLimits;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandKind;
import io.github.armor.core.command.CommandSpec;
import io.github.armor.core.command.CommandSuggestions;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.command.DirectiveLog;
import io.github.armor.core.command.Rendering;
import io.github.armor.core.command.StateQueries;
import io.github.armor.core.durability.StateStore;
import io.github.armor.core.events.ChangeEvent;
import io.github.armor.core.events.EventFeed;
import io.github.armor.core.events.Subscriptions;
import io.github.armor.core.reference.OntologyFiles;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.reference.ReferenceRegistry;
import io.github.armor.core.view.RecentDirectives;
import io.github.armor.core.view.ReferenceViews;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The knowledge core's single entry point: a directive (or an atomic list of them) in, ARMOR's
 * response out. Every failure becomes an exit code here; nothing a client sends escapes as an
 * exception. Thread-safe: directives on different references run in parallel.
 *
 * <p>Every acknowledged change is also published on {@link #events()} with the reference's new
 * revision (see {@link ChangeEvent} for what makes one), while the directive still holds the
 * reference, so each reference's events leave in revision order.
 */
public final class ArmorCore implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ArmorCore.class);

    private final CoreConfig config;
    private final CommandTable commands;
    private final ReferenceRegistry references = new ReferenceRegistry();
    private final Rendering rendering;
    private final DirectiveLog directiveLog = new DirectiveLog(System.err);
    private final RecentDirectives recentDirectives = new RecentDirectives();
    private final Map<String, Long> lastHeardFrom = new ConcurrentHashMap<>();
    private final StateStore state;
    private final EventFeed events = new EventFeed();
    private final Subscriptions subscriptions = new Subscriptions(events, this::askSubscribed);
    // Replayed directives were journaled when first acknowledged: they must not be again.
    private final ThreadLocal<Boolean> replaying = ThreadLocal.withInitial(() -> false);

    /** A core answering the commands of its own jar. */
    public ArmorCore(CoreConfig config) {
        this(config, CommandTable.standard());
    }

    /** A core answering the commands of {@code commands} (the built-in groups plus plugins'). */
    public ArmorCore(CoreConfig config, CommandTable commands) {
        this(config, commands, config.durability().stateDir() == null ? null : new StateStore(config.durability()));
    }

    /** A core keeping its references in {@code state} (null: kept nowhere). */
    public ArmorCore(CoreConfig config, CommandTable commands, StateStore state) {
        this.config = config;
        this.commands = commands;
        this.rendering = new Rendering(config.fullEntityIri());
        this.state = state;
    }

    /**
     * Brings back every reference kept in the state directory: its last checkpoint, then its
     * journal replayed through the ordinary dispatch. Call once, before serving.
     */
    public void restoreState() {
        if (state == null) {
            return;
        }
        for (StateStore.Restorable restorable : state.recoverAll(new OntologyFiles(config))) {
            long start = System.nanoTime();
            try {
                Reference reference = Reference.open(restorable.name(), restorable.ontology(), restorable.settings(),
                        config.reasonerTimeoutMs());
                reference.setMountedBy(restorable.mountedBy());
                references.register(reference);
                List<String> failures = new ArrayList<>();
                restorable.records().forEach(record -> failures.addAll(replay(record)));
                reference.setRevision(restorable.revision());
                reference.changeHistory().addAll(restorable.history());
                reference.synchroniseReasoner();
                state.adopt(restorable, restorable.revision(), failures);
                LOG.info("restored reference '{}' from the state directory {}: {} axioms, {} individuals,"
                        + " {} journal record(s) of earlier sessions replayed, in {} ms", restorable.name(),
                        config.durability().stateDir(), reference.ontology().getAxiomCount(),
                        reference.ontology().getIndividualsInSignature().size(), restorable.records().size(),
                        (System.nanoTime() - start) / 1_000_000);
            } catch (RuntimeException e) {
                LOG.error("could not restore reference '{}'", restorable.name(), e);
                references.find(restorable.name()).ifPresent(references::remove);
                state.notRestored(restorable, "restoring it failed: " + e);
            }
        }
    }

    /** Replays one journal record; what failed, described (a restored state that differs must say so). */
    private List<String> replay(AcknowledgedChange record) {
        List<String> failures = new ArrayList<>();
        replaying.set(true);
        try {
            for (Directive directive : record.directives()) {
                Response response = run(directive, null);
                if (!response.success()) {
                    failures.add("replaying revision " + record.revision() + " (" + directive.describe()
                            + ") failed: " + response.exitCode() + " " + response.errorDescription());
                }
            }
        } finally {
            replaying.set(false);
        }
        return failures;
    }

    /** Finishes writing state and releases the state directory; the core answers nothing afterwards. */
    @Override
    public void close() {
        subscriptions.close();
        events.close();
        if (state != null) {
            state.close();
        }
    }

    /** Where acknowledged changes are announced: {@link ChangeEvent}s, and subscriptions' answers. */
    public EventFeed events() {
        return events;
    }

    /** Standing queries whose answers' changes are published on {@link #events()}. */
    public Subscriptions subscriptions() {
        return subscriptions;
    }

    /**
     * Asks a subscription's query ({@link Subscriptions.Evaluator}) as {@link #execute} would, but
     * only a QUERY, without logging it and without counting it as its client's activity (a standing
     * query must not keep a mount lease alive).
     */
    private Subscriptions.Evaluation askSubscribed(Directive query, long unlessRevision, long expectRevision) {
        long[] revision = {-1};
        boolean[] postponed = {false};
        try {
            SizeLimits.check(query);
            CommandSpec spec = commands.find(query.key()).orElse(null);
            if (spec == null || spec.kind() != CommandKind.QUERY) {
                throw new ArmorException(ExitCode.UNKNOWN_COMMAND, "only a query (a QUERY command) can be"
                        + " subscribed to; " + query.describe() + (spec == null ? " is not a command"
                        : " is a " + spec.kind().catalogueName()));
            }
            if (query.referenceName().isEmpty()) {
                throw new ArmorException(ExitCode.NO_REFERENCE_NAME, "no reference name given for "
                        + query.describe());
            }
            spec.checkArity(query.args());
            Reference target = references.get(query.referenceName());
            CommandContext context = context(query, target);
            Response underLock = target.locked(config.lockWaitMs(), reference -> {
                revision[0] = reference.revision();
                postponed[0] = expectRevision != Subscriptions.ANY_REVISION && revision[0] != expectRevision;
                return revision[0] == unlessRevision || postponed[0] ? null : spec.handler().run(context);
            });
            if (postponed[0]) {
                return Subscriptions.Evaluation.POSTPONED;
            }
            return underLock == null ? null
                    : new Subscriptions.Evaluation(revision[0], context.finishAfterRelease(underLock));
        } catch (ArmorException e) {
            return new Subscriptions.Evaluation(revision[0], Response.failure(e, consistencyOf(query)));
        } catch (RuntimeException | LinkageError | StackOverflowError e) {
            LOG.error("internal error on subscribed {}", query, e);
            return new Subscriptions.Evaluation(revision[0], Response.failure(new ArmorException(
                    ExitCode.INTERNAL_ERROR, "internal error on " + query.describe() + ": " + e),
                    consistencyOf(query)));
        }
    }

    /**
     * Directives whose effect must survive a restart (by kind: changes and mounting), when not
     * replayed: each acknowledged one is journaled (with a state directory) and makes a revision.
     */
    private boolean makesRevision(CommandSpec spec) {
        return !replaying.get() && spec.kind().journaled();
    }

    /** The answer of a list: one response per directive, in order. */
    public record ListResponse(boolean success, boolean isConsistent, List<Response> responses) {}

    public Response execute(Directive directive) {
        try {
            SizeLimits.check(directive);
        } catch (ArmorException e) {
            return Response.failure(e, consistencyOf(directive));
        }
        return run(directive, null);
    }

    /**
     * Runs directives in order. When one fails, the changes the earlier ones made are undone and
     * the later ones are not run; both answer {@link ExitCode#ROLLED_BACK}.
     */
    public ListResponse executeList(List<Directive> directives) {
        try {
            SizeLimits.checkList(directives);
        } catch (ArmorException e) {
            return new ListResponse(false, false, directives.stream()
                    .map(d -> Response.failure(e, consistencyOf(d))).toList());
        }
        ListState list = new ListState();
        try {
            return runList(directives, list);
        } finally {
            list.releaseAll();
        }
    }

    private ListResponse runList(List<Directive> directives, ListState list) {
        List<Response> responses = new ArrayList<>();
        int failed = -1;
        long answered = 0;
        for (int i = 0; i < directives.size() && failed < 0; i++) {
            list.position = i;
            Response response = run(directives.get(i), list);
            try {
                answered = SizeLimits.addAnswer(answered, response);
            } catch (ArmorException e) {
                // No answer of it can reach the client: the whole list is refused, and undone.
                list.rollback();
                return new ListResponse(false, false, directives.stream()
                        .map(d -> Response.failure(e, consistencyOf(d))).toList());
            }
            responses.add(response);
            if (!response.success()) {
                failed = i;
            }
        }
        if (failed < 0) {
            try {
                list.journal();
            } catch (ArmorException e) {
                list.rollback();
                List<Response> undone = new ArrayList<>();
                for (Directive directive : directives) {
                    // The list's own cause (not durable), not 212: none of its directives failed.
                    undone.add(Response.failure(new ArmorException(e.exitCode(), e.getMessage() + "; the whole list"
                            + " was undone"), consistencyOf(directive)));
                }
                return new ListResponse(false, false, undone);
            }
            list.commit();
            list.announce();
            boolean consistent = responses.isEmpty() || responses.get(responses.size() - 1).isConsistent();
            return new ListResponse(true, consistent, responses);
        }
        list.rollback();
        String cause = "directive " + failed + " (" + directives.get(failed).describe() + ") failed: "
                + responses.get(failed).errorDescription();
        for (int i = 0; i < failed; i++) {
            if (list.changedBy.contains(i)) {
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
        long start = System.nanoTime();
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
        if (!replaying.get()) {
            recentDirectives.record(directive, response, System.nanoTime() - start);
        }
        return response;
    }

    private Response dispatch(Directive directive, ListState list) {
        if (!directive.clientName().isEmpty()) {
            lastHeardFrom.put(directive.clientName(), System.nanoTime());
        }
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
        return switch (spec.target()) {
            case NONE -> spec.handler().run(context(directive, null));
            case NEW -> create(spec, directive, list);
            case EXISTING -> {
                Reference target = references.get(directive.referenceName());
                // A question on a reference a writer holds is answered from its last reasoned state, not queued.
                if (list == null && spec.kind() == CommandKind.QUERY && target.isBusy()) {
                    Optional<Response> fromState = StateQueries.answer(directive, target, rendering);
                    if (fromState.isPresent()) {
                        yield fromState.get();
                    }
                }
                CommandContext context = context(directive, target);
                Response underLock = holdFor(list, target).locked(config.lockWaitMs(), reference -> {
                    releaseExpiredMount(reference);
                    if (!replaying.get() && spec.kind() == CommandKind.DROPPING && state != null) {
                        // Before the reference goes: a DROP the disk does not take is refused.
                        state.dropped(reference);
                    }
                    if (spec.mountChecked()) {
                        if (!replaying.get()) {
                            // A replayed record was acknowledged: it passed this check when it was made.
                            checkMount(reference, directive);
                        }
                        if (list != null) {
                            list.enrol(reference);
                        }
                    }
                    Response response = runUndoable(spec, context, reference, list);
                    if (list != null && spec.mountChecked()) {
                        list.changedBy.add(list.position);
                    }
                    if (list != null && makesRevision(spec)) {
                        list.toJournal.computeIfAbsent(reference, r -> new ArrayList<>()).add(directive);
                    }
                    if (!replaying.get() && spec.kind() == CommandKind.DROPPING) {
                        // A DROP is final even inside a list (no rollback brings a reference back).
                        events.publish(ChangeEvent.now(reference.name(), reference.revision() + 1, List.of(directive),
                                reference.isConsistent()));
                    }
                    return response;
                });
                // A read that left work for after the release (SPARQL on its private copy) does it now.
                yield context.finishAfterRelease(underLock);
            }
        };
    }

    /**
     * Runs a directive so that a failure changes nothing: a change that throws half-way is undone,
     * and outside a list an acknowledged change is journaled first (undone if that fails).
     */
    private Response runUndoable(CommandSpec spec, CommandContext context, Reference reference, ListState list) {
        Directive directive = context.directive();
        boolean single = list == null && spec.mountChecked();
        String holderBefore = reference.mountedBy();
        if (single) {
            reference.beginTransaction();
        }
        try {
            Response response = spec.handler().run(context);
            if (list == null && makesRevision(spec)) {
                AcknowledgedChange change = new AcknowledgedChange(reference.revision() + 1, List.of(directive));
                if (state != null) {
                    state.record(reference, change);
                }
                reference.acknowledge(change);
                if (state != null) {
                    state.checkpointIfDue(reference);
                }
                events.publish(ChangeEvent.now(reference.name(), change.revision(), change.directives(),
                        reference.isConsistent()));
            }
            return response;
        } catch (RuntimeException | StackOverflowError e) {
            if (single) {
                reference.rollbackTransaction();
            }
            // A MOUNT or UNMOUNT the journal refused is undone too.
            reference.setMountedBy(holderBefore);
            throw e;
        } finally {
            if (single) {
                reference.commitTransaction();
            }
        }
    }

    private Response create(CommandSpec spec, Directive directive, ListState list) {
        boolean existed = references.find(directive.referenceName()).isPresent();
        Response response = spec.handler().run(context(directive, null));
        Reference made = references.find(directive.referenceName()).orElse(null);
        if (state != null && !replaying.get() && !existed && made != null) {
            try {
                state.created(made);
            } catch (ArmorException e) {
                references.remove(made);
                throw e;
            }
        }
        if (!replaying.get() && !existed && made != null) {
            ChangeEvent creation = ChangeEvent.now(made.name(), made.revision(), List.of(directive),
                    made.isConsistent());
            if (list == null) {
                events.publish(creation);
            } else {
                list.creations.add(creation);
            }
        }
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
        return new CommandContext(directive, reference, references, config, rendering, directiveLog, replaying.get(),
                commands, state == null ? List::of : state::damage);
    }

    private void checkMount(Reference reference, Directive directive) {
        String holder = reference.mountedBy();
        if (!holder.isEmpty() && !holder.equals(directive.clientName())) {
            throw new ArmorException(ExitCode.REFERENCE_MOUNTED, "reference '" + reference.name()
                    + "' is mounted by client '" + holder + "'; " + directive.describe() + " refused, nothing changed");
        }
    }

    /** The web page's read-only views of this core's references (view/ReferenceViews). */
    public ReferenceViews views() {
        return new ReferenceViews(references, config, recentDirectives, this::mountLeaseLeftMs);
    }

    /** How long the mount of {@code holder} has left before it expires, in ms; negative: mounts never expire. */
    private long mountLeaseLeftMs(String holder) {
        if (config.mountLeaseS() <= 0) {
            return -1;
        }
        Long heard = lastHeardFrom.get(holder);
        long silentMs = heard == null ? Long.MAX_VALUE : (System.nanoTime() - heard) / 1_000_000;
        return Math.max(0, config.mountLeaseS() * 1000 - silentMs);
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
        final Map<Reference, List<Directive>> toJournal = new java.util.LinkedHashMap<>();
        final List<ChangeEvent> creations = new ArrayList<>();
        int position;

        /**
         * One journal record per reference for the whole list, before it is acknowledged: the
         * list is one revision of each reference it changed.
         */
        void journal() {
            Map<Reference, AcknowledgedChange> changes = new java.util.LinkedHashMap<>();
            toJournal.forEach((reference, directives) -> changes.put(reference,
                    new AcknowledgedChange(reference.revision() + 1, directives)));
            if (ArmorCore.this.state != null) {
                ArmorCore.this.state.recordAll(changes);
            }
            changes.forEach((reference, change) -> {
                reference.acknowledge(change);
                if (ArmorCore.this.state != null) {
                    ArmorCore.this.state.checkpointIfDue(reference);
                }
            });
        }

        /** After the commit, while the list still holds its references: its creations, then its changes. */
        void announce() {
            creations.forEach(events::publish);
            toJournal.forEach((reference, directives) -> events.publish(ChangeEvent.now(reference.name(),
                    reference.revision(), directives, reference.isConsistent())));
        }

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
            for (Reference reference : created) {
                references.remove(reference);
                if (ArmorCore.this.state != null) {
                    try {
                        ArmorCore.this.state.dropped(reference);
                    } catch (ArmorException e) {
                        LOG.error("the state of '{}', made by a list that failed, stays: {}", reference.name(),
                                e.getMessage());
                    }
                }
            }
        }

        void releaseAll() {
            held.forEach(Reference::release);
            held.clear();
        }
    }
}
