// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import io.github.armor.core.answers.Rendering;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.Response;
import io.github.armor.core.api.SizeLimits;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.durability.StateStore;
import io.github.armor.core.events.ChangeEvent;
import io.github.armor.core.events.EventFeed;
import io.github.armor.core.events.Subscriptions;
import io.github.armor.core.log.DirectiveLog;
import io.github.armor.core.pipeline.Admission;
import io.github.armor.core.pipeline.Dispatcher;
import io.github.armor.core.pipeline.Pipeline;
import io.github.armor.core.pipeline.Restoration;
import io.github.armor.core.pipeline.StandingQueries;
import io.github.armor.core.reference.ReferenceRegistry;
import io.github.armor.core.view.RecentDirectives;
import io.github.armor.core.view.ReferenceViews;
import java.util.List;

/**
 * The knowledge core's single entry point: a directive (or an atomic list of them) in, ARMOR's
 * response out. Every failure becomes an exit code here; nothing a client sends escapes as an
 * exception. Thread-safe: directives on different references run in parallel.
 *
 * <p>Every acknowledged change is also published on {@link #events()} with the reference's new
 * revision (see {@link ChangeEvent} for what makes one), while the directive still holds the
 * reference, so each reference's events leave in revision order.
 *
 * <p>A facade: the work is done by the stages of {@link Pipeline} (the {@link Dispatcher},
 * {@link Admission}, the unit of work), shared by clients' directives, standing queries
 * ({@link StandingQueries}) and the replay of the journals at start ({@link Restoration}).
 */
public final class ArmorCore implements AutoCloseable {
    private final Pipeline.Stages stages;
    private final Pipeline pipeline;
    private final Subscriptions subscriptions;

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
        this.stages = new Pipeline.Stages(config, new Dispatcher(commands), new Admission(config),
                new ReferenceRegistry(), new Rendering(config.fullEntityIri()), new DirectiveLog(System.err),
                new RecentDirectives(), state, new EventFeed());
        this.pipeline = Pipeline.live(stages);
        this.subscriptions = new Subscriptions(stages.events(), new StandingQueries(stages, pipeline));
    }

    /**
     * Brings back every reference kept in the state directory: its last checkpoint, then its
     * journal replayed through the ordinary dispatch. Call once, before serving.
     */
    public void restoreState() {
        Restoration.restore(stages);
    }

    /** Finishes writing state and releases the state directory; the core answers nothing afterwards. */
    @Override
    public void close() {
        subscriptions.close();
        stages.events().close();
        if (stages.state() != null) {
            stages.state().close();
        }
    }

    /** Where acknowledged changes are announced: {@link ChangeEvent}s, and subscriptions' answers. */
    public EventFeed events() {
        return stages.events();
    }

    /** Standing queries whose answers' changes are published on {@link #events()}. */
    public Subscriptions subscriptions() {
        return subscriptions;
    }

    public Response execute(Directive directive) {
        try {
            SizeLimits.check(directive);
        } catch (ArmorException e) {
            return Response.failure(e, pipeline.consistencyOf(directive));
        }
        return pipeline.run(directive);
    }

    /**
     * Runs directives in order. When one fails, the changes the earlier ones made are undone and
     * the later ones are not run; both answer {@link ExitCode#ROLLED_BACK}.
     */
    public ListResponse executeList(List<Directive> directives) {
        try {
            SizeLimits.checkList(directives);
        } catch (ArmorException e) {
            return pipeline.refused(directives, e);
        }
        return pipeline.runList(directives);
    }

    /** The web page's read-only views of this core's references (view/ReferenceViews). */
    public ReferenceViews views() {
        return new ReferenceViews(stages.references(), stages.config(), stages.recentDirectives(),
                stages.admission()::leaseLeftMs);
    }
}
