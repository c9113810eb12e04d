// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.pipeline;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.api.SizeLimits;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandSpec;
import io.github.armor.core.events.Subscriptions;
import io.github.armor.core.reference.Reference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Asks a subscription's query as a client's directive is asked (the same dispatcher, lock and
 * handler), but only a QUERY, without logging it and without counting it as its client's
 * activity (a standing query must not keep a mount lease alive).
 */
public final class StandingQueries implements Subscriptions.Evaluator {
    private static final Logger LOG = LoggerFactory.getLogger(StandingQueries.class);

    private final Pipeline.Stages stages;
    private final Pipeline pipeline;

    public StandingQueries(Pipeline.Stages stages, Pipeline pipeline) {
        this.stages = stages;
        this.pipeline = pipeline;
    }

    @Override
    public Directive standingForm(Directive query) {
        return stages.dispatcher().standingForm(query);
    }

    @Override
    public Subscriptions.Evaluation evaluate(Directive query, long unlessRevision, long expectRevision) {
        long[] revision = {-1};
        boolean[] postponed = {false};
        try {
            SizeLimits.check(query);
            CommandSpec spec = stages.dispatcher().resolveQuery(query);
            Reference target = stages.references().get(query.referenceName());
            CommandContext context = pipeline.context(spec, query, target);
            Response underLock = target.locked(stages.config().lockWaitMs(), reference -> {
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
            return new Subscriptions.Evaluation(revision[0], Response.failure(e, pipeline.consistencyOf(query)));
        } catch (RuntimeException | LinkageError | StackOverflowError e) {
            LOG.error("internal error on subscribed {}", query, e);
            return new Subscriptions.Evaluation(revision[0], Response.failure(new ArmorException(
                    ExitCode.INTERNAL_ERROR, "internal error on " + query.describe() + ": " + e),
                    pipeline.consistencyOf(query)));
        }
    }
}
