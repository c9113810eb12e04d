// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.pipeline;

import io.github.armor.core.answers.Rendering;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.Response;
import io.github.armor.core.api.SizeLimits;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandKind;
import io.github.armor.core.command.CommandSpec;
import io.github.armor.core.durability.StateStore;
import io.github.armor.core.events.ChangeEvent;
import io.github.armor.core.events.EventFeed;
import io.github.armor.core.log.DirectiveLog;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.reference.ReferenceRegistry;
import io.github.armor.core.view.RecentDirectives;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs directives through the core's stages: the dispatcher, admission, the reference's lock,
 * the handler, and the unit of work that makes the change all or none. Two run side by side:
 * the live one for clients, and the replaying one for journal records at start, which were
 * checked, journaled and announced when first acknowledged and so are not again.
 */
public final class Pipeline {
    private static final Logger LOG = LoggerFactory.getLogger(Pipeline.class);

    /** What every pipeline of one core shares. */
    public record Stages(CoreConfig config, Dispatcher dispatcher, Admission admission, ReferenceRegistry references,
                         Rendering rendering, DirectiveLog directiveLog, RecentDirectives recentDirectives,
                         StateStore state, EventFeed events) {}

    private final Stages stages;
    private final boolean replaying;

    private Pipeline(Stages stages, boolean replaying) {
        this.stages = stages;
        this.replaying = replaying;
    }

    /** The pipeline of clients' directives. */
    public static Pipeline live(Stages stages) {
        return new Pipeline(stages, false);
    }

    /** The pipeline that replays journal records at start. */
    public static Pipeline replaying(Stages stages) {
        return new Pipeline(stages, true);
    }

    /** One directive: every failure becomes its response. */
    public Response run(Directive directive) {
        return run(directive, UnitOfWork.single(stages.references(), stages.state(), stages.events()));
    }

    /**
     * Runs directives in order. When one fails, the changes the earlier ones made are undone and
     * the later ones are not run; both answer {@link ExitCode#ROLLED_BACK}.
     */
    public ListResponse runList(List<Directive> directives) {
        UnitOfWork list = UnitOfWork.list(stages.references(), stages.state(), stages.events(),
                stages.config().lockWaitMs());
        try {
            return runList(directives, list);
        } finally {
            list.releaseAll();
        }
    }

    private ListResponse runList(List<Directive> directives, UnitOfWork list) {
        List<Response> responses = new ArrayList<>();
        int failed = -1;
        long answered = 0;
        for (int i = 0; i < directives.size() && failed < 0; i++) {
            list.at(i);
            Response response = run(directives.get(i), list);
            try {
                answered = SizeLimits.addAnswer(answered, response);
            } catch (ArmorException e) {
                // No answer of it can reach the client: the whole list is refused, and undone.
                list.rollback();
                return refused(directives, e);
            }
            responses.add(response);
            if (!response.success()) {
                failed = i;
            }
        }
        if (failed < 0) {
            try {
                list.complete();
            } catch (ArmorException e) {
                list.rollback();
                // The list's own cause (not durable), not 212: none of its directives failed.
                return refused(directives, new ArmorException(e.exitCode(), e.getMessage()
                        + "; the whole list was undone"));
            }
            boolean consistent = responses.isEmpty() || responses.get(responses.size() - 1).isConsistent();
            return new ListResponse(true, consistent, responses);
        }
        list.rollback();
        String cause = "directive " + failed + " (" + directives.get(failed).describe() + ") failed: "
                + responses.get(failed).errorDescription();
        for (int i = 0; i < failed; i++) {
            if (list.changedBy(i)) {
                responses.set(i, rolledBack("undone because " + cause, directives.get(i)));
            }
        }
        for (int i = failed + 1; i < directives.size(); i++) {
            responses.add(rolledBack("not run because " + cause, directives.get(i)));
        }
        return new ListResponse(false, responses.get(failed).isConsistent(), responses);
    }

    /** Every directive of a list answering the same refusal. */
    public ListResponse refused(List<Directive> directives, ArmorException e) {
        return new ListResponse(false, false, directives.stream().map(d -> Response.failure(e, consistencyOf(d)))
                .toList());
    }

    private Response rolledBack(String description, Directive directive) {
        return Response.failure(new ArmorException(ExitCode.ROLLED_BACK, description), consistencyOf(directive));
    }

    private Response run(Directive directive, UnitOfWork unit) {
        long start = System.nanoTime();
        Response response;
        try {
            response = dispatch(directive, unit);
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
        stages.directiveLog().record(directive, response);
        if (!replaying) {
            stages.recentDirectives().record(directive, response, System.nanoTime() - start);
        }
        return response;
    }

    private Response dispatch(Directive directive, UnitOfWork unit) {
        stages.admission().heard(directive);
        CommandSpec spec = stages.dispatcher().resolve(directive);
        return switch (spec.target()) {
            case NONE -> spec.handler().run(context(spec, directive, null));
            case NEW -> create(spec, directive, unit);
            case EXISTING -> onReference(spec, directive, unit);
        };
    }

    private Response onReference(CommandSpec spec, Directive directive, UnitOfWork unit) {
        Reference target = stages.references().get(directive.referenceName());
        CommandContext context = context(spec, directive, target);
        // A question on a reference a writer holds may be answered from its last reasoned state, not queued.
        if (unit.single() && target.isBusy()) {
            Optional<Response> early = stages.dispatcher().answerWhileBusy(spec, context);
            if (early.isPresent()) {
                return early.get();
            }
        }
        Response underLock = unit.hold(target).locked(stages.config().lockWaitMs(), reference -> {
            stages.admission().releaseExpired(reference);
            boolean dropping = spec.kind() == CommandKind.DROPPING;
            if (!replaying && dropping && stages.state() != null) {
                // Before the reference goes: a DROP the disk does not take is refused.
                stages.state().dropped(reference);
            }
            if (spec.mountChecked()) {
                if (!replaying) {
                    // A replayed record was acknowledged: it passed this check when it was made.
                    stages.admission().check(reference, directive);
                }
                unit.enrol(reference);
            }
            Response response = runUndoable(spec, context, reference, unit);
            if (!replaying && dropping) {
                // A DROP is final even inside a list (no rollback brings a reference back).
                stages.events().publish(ChangeEvent.now(reference.name(), reference.revision() + 1,
                        List.of(directive), reference.isConsistent()));
            }
            return response;
        });
        // A read that left work for after the release (SPARQL on its private copy) does it now.
        return context.finishAfterRelease(underLock);
    }

    /**
     * Runs a directive so that a failure changes nothing: on its own, its unit of work completes
     * (journal record first) or is undone before the reference is released; in a list, the
     * list's unit does so at its end.
     */
    private Response runUndoable(CommandSpec spec, CommandContext context, Reference reference, UnitOfWork unit) {
        String holderBefore = reference.mountedBy();
        try {
            Response response = spec.handler().run(context);
            if (spec.mountChecked()) {
                unit.changed();
            }
            // Replayed directives were journaled when first acknowledged: they must not be again.
            if (!replaying && spec.kind().journaled()) {
                unit.journalLater(reference, context.directive());
            }
            if (unit.single()) {
                unit.complete();
            }
            return response;
        } catch (RuntimeException | StackOverflowError e) {
            if (unit.single()) {
                unit.rollback();
            }
            // A MOUNT or UNMOUNT the journal refused is undone too.
            reference.setMountedBy(holderBefore);
            throw e;
        }
    }

    private Response create(CommandSpec spec, Directive directive, UnitOfWork unit) {
        boolean existed = stages.references().find(directive.referenceName()).isPresent();
        Response response = spec.handler().run(context(spec, directive, null));
        Reference made = stages.references().find(directive.referenceName()).orElse(null);
        if (made == null) {
            return response;
        }
        boolean isNew = !existed;
        if (stages.state() != null && !replaying && isNew) {
            try {
                stages.state().created(made);
            } catch (ArmorException e) {
                stages.references().remove(made);
                throw e;
            }
        }
        ChangeEvent creation = !replaying && isNew
                ? ChangeEvent.now(made.name(), made.revision(), List.of(directive), made.isConsistent()) : null;
        unit.created(made, isNew, creation);
        return response;
    }

    /** What a handler sees of a directive and its reference (null: none). */
    CommandContext context(CommandSpec spec, Directive directive, Reference reference) {
        StateStore state = stages.state();
        return new CommandContext(directive, spec.kind(), reference, stages.references(), stages.config(), stages.rendering(),
                stages.directiveLog(), replaying, stages.dispatcher().commands(), state == null ? List::of
                : state::damage);
    }

    /** Whether the directive's reference is consistent (false: it has none). */
    public boolean consistencyOf(Directive directive) {
        return stages.references().find(directive.referenceName()).map(Reference::isConsistent).orElse(false);
    }
}
