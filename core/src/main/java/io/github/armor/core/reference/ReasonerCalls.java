// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs reasoner calls so that a directive answers within its reasoner time limit whatever the
 * reasoner does when interrupted.
 *
 * <p>A directive's reasoner work shares one budget ({@link #withBudget}): every call it makes
 * (flush, consistency, classification, a query, each inference generator of SAVE INFERENCE or
 * SPARQL) must end before the same deadline. A call runs on a worker thread while the directive
 * thread waits for it until the deadline; then the reasoner is interrupted and the directive
 * thread waits at most {@link #MARGIN_MS} more. Whatever happens next, the call has
 * {@link Overran}: a reasoner that stops with an exception, one that swallows the interruption
 * and returns a partial answer (JFact's classification does), and one that ignores it and runs
 * on. The last is abandoned: the directive answers at once, and the call keeps its own reasoner
 * object and its thread until it ends. Its caller must never use that reasoner again.
 *
 * <p>An abandoned call still reads the ontology while later directives change it. The OWL API's
 * axiom indexes synchronise each access, so such reads cannot corrupt the ontology; whatever the
 * abandoned call computes from a changing ontology is thrown away.
 */
public final class ReasonerCalls {
    /** How long a directive waits for an interrupted reasoner to stop before abandoning it. */
    public static final long MARGIN_MS = 1_000;
    private static final Logger LOG = LoggerFactory.getLogger(ReasonerCalls.class);
    // Reasoners recurse deeply on real ontologies: the same stack as the core's directive threads.
    private static final long STACK_BYTES = 256L << 20;
    private static final long NO_DEADLINE = Long.MAX_VALUE;
    private static final AtomicInteger THREADS = new AtomicInteger();
    private static final AtomicInteger ABANDONED_RUNNING = new AtomicInteger();
    private static final ExecutorService WORKERS = Executors.newCachedThreadPool(work -> {
        Thread thread = new Thread(null, work, "armor-reasoner-call-" + THREADS.incrementAndGet(), STACK_BYTES);
        thread.setDaemon(true);
        return thread;
    });
    private static final ThreadLocal<Long> BUDGET_DEADLINE = new ThreadLocal<>();
    private static final ThreadLocal<Boolean> ON_WORKER = ThreadLocal.withInitial(() -> false);

    private ReasonerCalls() {}

    /** A reasoner call that did not end in time; its reasoner must not be used again. */
    public static final class Overran extends RuntimeException {
        private final boolean started;
        private final boolean abandoned;

        Overran(boolean started, boolean abandoned, Throwable cause) {
            super(!started ? "no time left for the reasoner" : abandoned
                    ? "the reasoner ignored its interruption; abandoned while it runs on"
                    : "interrupted by the time limit", cause);
            this.started = started;
            this.abandoned = abandoned;
        }

        /** Whether the reasoner was running (and interrupted): if not, it is as good as before. */
        public boolean started() {
            return started;
        }

        /** Whether the call still runs in the background, with its reasoner. */
        public boolean abandoned() {
            return abandoned;
        }
    }

    /**
     * Runs {@code work} with one budget of {@code limitMs} for every reasoner call it makes
     * ({@code limitMs <= 0}: none). Inside another budget, the outer one holds.
     */
    public static <T> T withBudget(long limitMs, Supplier<T> work) {
        if (limitMs <= 0 || BUDGET_DEADLINE.get() != null) {
            return work.get();
        }
        BUDGET_DEADLINE.set(System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(limitMs));
        try {
            return work.get();
        } finally {
            BUDGET_DEADLINE.remove();
        }
    }

    /** The deadline of a call: the budget's, if one is running, else {@code limitMs} from now (0: none). */
    public static long deadline(long limitMs) {
        Long budget = BUDGET_DEADLINE.get();
        if (budget != null) {
            return budget;
        }
        return limitMs <= 0 ? NO_DEADLINE : System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(limitMs);
    }

    /**
     * Runs {@code work}, a call on {@code reasoner} (null while the reasoner is being made), so
     * that it answers by {@code deadlineNanos} (a {@link System#nanoTime()} value) plus the margin.
     * A reasoner a call abandoned is disposed in the background; so is one a call abandoned while
     * making it, once made.
     *
     * @throws Overran when the deadline passed first
     */
    public static <T> T run(OWLReasoner reasoner, long deadlineNanos, Supplier<T> work) {
        if (deadlineNanos == NO_DEADLINE || ON_WORKER.get()) {
            return work.get();
        }
        long left = deadlineNanos - System.nanoTime();
        if (left <= 0) {
            throw new Overran(false, false, null);
        }
        long start = System.nanoTime();
        CompletableFuture<T> call = CompletableFuture.supplyAsync(() -> {
            ON_WORKER.set(true);
            try {
                return work.get();
            } finally {
                ON_WORKER.set(false);
            }
        }, WORKERS);
        try {
            return call.get(left, TimeUnit.NANOSECONDS);
        } catch (TimeoutException e) {
            // The deadline: whatever the reasoner answers from now on is not a complete answer.
            interrupt(reasoner);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            interrupt(reasoner);
        } catch (ExecutionException e) {
            throw rethrown(e.getCause());
        }
        try {
            call.get(MARGIN_MS, TimeUnit.MILLISECONDS);
            throw new Overran(true, false, null);
        } catch (ExecutionException e) {
            throw new Overran(true, false, e.getCause());
        } catch (TimeoutException | InterruptedException e) {
            if (e instanceof InterruptedException) {
                Thread.currentThread().interrupt();
            }
            abandon(reasoner, call, start);
            throw new Overran(true, true, null);
        }
    }

    /** Disposes a reasoner no directive will use again, without making the caller wait for it. */
    public static void disposeInBackground(OWLReasoner reasoner) {
        if (reasoner != null) {
            WORKERS.execute(() -> dispose(reasoner));
        }
    }

    private static void interrupt(OWLReasoner reasoner) {
        if (reasoner == null) {
            return;
        }
        try {
            reasoner.interrupt();
        } catch (RuntimeException e) {
            LOG.debug("interrupting {} failed", reasoner.getReasonerName(), e);
        }
    }

    private static <T> void abandon(OWLReasoner reasoner, CompletableFuture<T> call, long start) {
        int running = ABANDONED_RUNNING.incrementAndGet();
        LOG.warn("a reasoner call ignored its interruption and is abandoned: it runs on in the background until it"
                + " ends ({} abandoned call(s) running)", running);
        disposeInBackground(reasoner);
        call.whenComplete((result, failure) -> {
            ABANDONED_RUNNING.decrementAndGet();
            LOG.info("an abandoned reasoner call ended after {} ms", (System.nanoTime() - start) / 1_000_000);
            if (result instanceof OWLReasoner made) {
                dispose(made);
            }
        });
    }

    private static void dispose(OWLReasoner reasoner) {
        try {
            reasoner.dispose();
        } catch (RuntimeException | LinkageError e) {
            // a reasoner stopped half-way may not dispose cleanly; it is dropped either way
        }
    }

    private static RuntimeException rethrown(Throwable cause) {
        if (cause instanceof RuntimeException runtime) {
            return runtime;
        }
        if (cause instanceof Error error) {
            throw error;
        }
        return new IllegalStateException(cause);
    }
}
