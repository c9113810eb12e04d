// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandSpec.Handler;
import java.util.Optional;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs a plugin's command so that it can neither take the core down nor keep a reference.
 *
 * <p>The handler runs on a thread of its own while the directive's thread holds the reference
 * (its lock, its transaction) and waits at most {@code plugin_timeout_ms}. Whatever the plugin
 * throws becomes an answer: its own {@link ArmorException} keeps its exit code, anything else
 * (a RuntimeException, an Error, a stack overflow) is 220 naming the plugin. A plugin that
 * overruns is interrupted; one that ignores the interrupt is stopped ({@link Thread#stop()},
 * which Java 17 still honours). Only once its thread has ended does the directive answer 211,
 * so the rollback that follows (of the directive, or of its whole list) never races with it.
 * A thread that survives even that is beyond the core's control: the core exits, and the node
 * starts a new one from the journals, as after a crash, so no change acknowledged is lost and
 * none half-made is kept.
 */
final class PluginGuard {
    private static final Logger LOG = LoggerFactory.getLogger(PluginGuard.class);
    // As the core's workers: reasoners called from a plugin recurse deeply too.
    private static final long STACK_BYTES = 256L << 20;
    /** How long a plugin's thread gets to end after the interrupt, and again after being stopped. */
    static final long GRACE_MS = 2_000;
    /** Exit status of a core that could not stop a plugin's thread (the node restarts it). */
    static final int UNSTOPPABLE_PLUGIN_EXIT = 70;
    private static final AtomicInteger THREADS = new AtomicInteger();

    private PluginGuard() {}

    /** The handler a plugin registered, run under the guard. */
    static Handler guard(String key, String origin, Handler handler) {
        ClassLoader loader = handler instanceof PluginTable.Adapted adapted ? adapted.loader()
                : handler.getClass().getClassLoader();
        return context -> run(key, origin, handler, loader, context);
    }

    /** An answer source a plugin registered, run under the guard (no answer: null inside it). */
    static AnswerSource guard(String key, String origin, AnswerSource source) {
        Handler asHandler = context -> source.answer(context).orElse(null);
        ClassLoader loader = source instanceof PluginStateSource adapted ? adapted.loader()
                : source.getClass().getClassLoader();
        return context -> Optional.ofNullable(run(key, origin, asHandler, loader, context));
    }

    private static Response run(String key, String origin, Handler handler, ClassLoader loader,
                                CommandContext context) {
        long limitMs = context.config().safeguards().pluginTimeoutMs();
        FutureTask<Response> task = new FutureTask<>(() -> handler.run(context));
        Thread thread = new Thread(null, task, "armor-plugin-" + THREADS.incrementAndGet(), STACK_BYTES);
        thread.setDaemon(true);
        // A plugin looking up its own resources or services finds them through its jar's loader.
        thread.setContextClassLoader(loader);
        thread.start();
        try {
            return limitMs > 0 ? task.get(limitMs, TimeUnit.MILLISECONDS) : task.get();
        } catch (ExecutionException e) {
            throw failure(key, origin, e.getCause());
        } catch (TimeoutException e) {
            stop(thread, task, key, origin);
            throw new ArmorException(ExitCode.TIMEOUT, key + " (plugin " + origin + ") exceeded plugin_timeout_ms="
                    + limitMs + " and was stopped; what it changed is undone");
        } catch (InterruptedException e) {
            stop(thread, task, key, origin);
            Thread.currentThread().interrupt();
            throw new ArmorException(ExitCode.TIMEOUT, key + " (plugin " + origin + ") was interrupted and stopped;"
                    + " what it changed is undone");
        }
    }

    private static ArmorException failure(String key, String origin, Throwable cause) {
        if (cause instanceof ArmorException armor) {
            return armor;
        }
        LOG.error("{} (plugin {}) failed", key, origin, cause);
        String what = cause instanceof StackOverflowError ? "overflowed its stack" : "failed: " + cause;
        return new ArmorException(ExitCode.INTERNAL_ERROR, key + " (plugin " + origin + ") " + what
                + "; what it changed is undone", cause);
    }

    @SuppressWarnings("deprecation")
    private static void stop(Thread thread, FutureTask<Response> task, String key, String origin) {
        task.cancel(true);
        if (ended(thread)) {
            return;
        }
        LOG.warn("{} (plugin {}) ignored the interrupt at its time limit; stopping its thread", key, origin);
        try {
            thread.stop();
        } catch (UnsupportedOperationException e) {
            // Java 20 and later refuse to stop a thread: only the last resort is left.
        }
        if (ended(thread)) {
            return;
        }
        LOG.error("{} (plugin {}) cannot be stopped and may still be changing its reference; the core exits so"
                + " that the node starts a new one from the journals (acknowledged changes are kept)", key, origin);
        Runtime.getRuntime().halt(UNSTOPPABLE_PLUGIN_EXIT);
    }

    private static boolean ended(Thread thread) {
        try {
            thread.join(GRACE_MS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return !thread.isAlive();
    }
}
