// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.events;

import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Standing queries: a client registers a query directive (any QUERY, QUERY SPARQL included) and
 * is told, as {@link AnswerEvent}s on the {@link EventFeed}, which answers appear and disappear
 * after each change of its reference, inferred answers included (the query is simply asked
 * again, so it answers what the reasoner concludes).
 *
 * <p>Off the directive path: a {@link ChangeEvent} only marks its reference's subscriptions for
 * evaluation. One worker per reference (from a shared pool) then asks each of them again,
 * taking the reference as any query does, one subscription at a time so that a directive waits
 * for at most one of them; changes that arrive meanwhile are coalesced into the next round, and
 * a subscription whose reference is still at the revision it last saw is not asked again.
 * Events of one subscription leave in the order of its evaluations.
 *
 * <p>Directives come first: the worker waits until the reference has had no change for
 * {@link #QUIET_MS} (a client sending changes back to back is not held up by the questions its
 * changes raise), and stops a round as soon as another change comes; a round overdue by
 * {@link #MAX_DELAY_MS} runs regardless (under a steady stream of changes, answers still follow,
 * each directive then waiting for at most one query).
 *
 * <p>An answer is a set: a SPARQL row that occurs twice is one answer. Threading: every public
 * method may be called from any thread.
 */
public final class Subscriptions implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(Subscriptions.class);
    /** Not a revision: the query is asked whatever the reference's revision. */
    public static final long ANY_REVISION = Long.MIN_VALUE;
    /** How long a reference must go without a change before its subscriptions are asked. */
    public static final long QUIET_MS = 10;
    /** How long changes may keep postponing the subscriptions of a reference. */
    public static final long MAX_DELAY_MS = 1000;
    // A time limit (the reference busy, the reasoner slow) is retried this often before it is announced.
    private static final int TIMEOUT_RETRIES = 3;
    private static final long RETRY_DELAY_MS = 500;
    // Reasoners recurse deeply on real ontologies, as in the core's request workers.
    private static final long WORKER_STACK_BYTES = 256L << 20;

    /** One evaluation of a subscribed query: the revision it holds at (-1 if unknown) and its response. */
    public record Evaluation(long revision, Response response) {
        /** Not asked: the reference changed again meanwhile (see {@link Evaluator#evaluate}). */
        public static final Evaluation POSTPONED = new Evaluation(ANY_REVISION, null);
    }

    /** Asks a query for a subscription (the core does, without logging it as a client's directive). */
    @FunctionalInterface
    public interface Evaluator {
        /**
         * The query's answer with the revision it holds at; null when its reference is still at
         * {@code unlessRevision}; {@link Evaluation#POSTPONED} when, once held, the reference is
         * no longer at {@code expectRevision} (a change came meanwhile: directives go first).
         * Either revision may be {@link #ANY_REVISION}. Failures are answered, never thrown.
         */
        Evaluation evaluate(Directive query, long unlessRevision, long expectRevision);

        /** The directive a subscription to {@code query} asks (a command may name another for that). */
        default Directive standingForm(Directive query) {
            return query;
        }
    }

    private final EventFeed feed;
    private final Evaluator evaluator;
    private final Map<String, Subscription> byId = new ConcurrentHashMap<>();
    private final Map<String, Watch> watches = new ConcurrentHashMap<>();
    private final Consumer<CoreEvent> onEvent = this::onEvent;
    private final AtomicInteger threads = new AtomicInteger();
    private final ExecutorService workers = Executors.newCachedThreadPool(work -> {
        Thread thread = new Thread(null, work, "armor-subscriptions-" + threads.incrementAndGet(),
                WORKER_STACK_BYTES);
        thread.setDaemon(true);
        return thread;
    });
    private final ScheduledExecutorService retries = Executors.newSingleThreadScheduledExecutor(work -> {
        Thread thread = new Thread(work, "armor-subscription-retries");
        thread.setDaemon(true);
        return thread;
    });

    public Subscriptions(EventFeed feed, Evaluator evaluator) {
        this.feed = feed;
        this.evaluator = evaluator;
    }

    /**
     * Registers (or, under an id already registered, replaces) a subscription and asks its query.
     * The first {@link AnswerEvent} is published before this returns: the whole answer, or, when
     * {@code known} is given (a client registering again after a core restart), what changed
     * since it. A query that fails registers nothing.
     *
     * @param id    the subscription's id, chosen by the client
     * @param query the query directive (asked in its {@linkplain Evaluator#standingForm standing form})
     * @param known the answer the client last had, or null for a new subscription
     * @return the first evaluation; its response says whether the subscription was registered
     */
    public Evaluation subscribe(String id, Directive query, List<String> known) {
        Directive asked = evaluator.standingForm(query);
        Subscription subscription = new Subscription(id, asked, known);
        Watch watch;
        synchronized (this) {
            if (byId.isEmpty()) {
                feed.addListener(onEvent);
            }
            Subscription replaced = byId.put(id, subscription);
            if (replaced != null) {
                detach(replaced);
            }
            watch = watches.computeIfAbsent(asked.referenceName(), Watch::new);
            watch.subscriptions.add(subscription);
        }
        watch.changed();
        Evaluation first;
        try {
            first = subscription.first.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            first = failure(ExitCode.TIMEOUT, "interrupted while asking the subscribed query");
        } catch (ExecutionException e) {
            first = failure(ExitCode.INTERNAL_ERROR, "subscribed query failed: " + e.getCause());
        }
        if (!registered(first.response())) {
            unsubscribe(id, subscription);
        }
        return first;
    }

    /** Ends a subscription; false when none has that id. No event of it follows. */
    public boolean unsubscribe(String id) {
        Subscription subscription = byId.get(id);
        return subscription != null && unsubscribe(id, subscription);
    }

    private synchronized boolean unsubscribe(String id, Subscription subscription) {
        if (!byId.remove(id, subscription)) {
            return false;
        }
        detach(subscription);
        if (byId.isEmpty()) {
            feed.removeListener(onEvent);
        }
        return true;
    }

    /** Called holding this object's monitor. */
    private void detach(Subscription subscription) {
        subscription.active = false;
        Watch watch = watches.get(subscription.query.referenceName());
        if (watch != null) {
            watch.subscriptions.remove(subscription);
            if (watch.subscriptions.isEmpty()) {
                watches.remove(watch.reference, watch);
            }
        }
    }

    /** How many subscriptions are registered. */
    public int count() {
        return byId.size();
    }

    @Override
    public void close() {
        feed.removeListener(onEvent);
        workers.shutdownNow();
        retries.shutdownNow();
    }

    private static boolean registered(Response first) {
        return first.success() && !first.timeout();
    }

    private static Evaluation failure(ExitCode code, String description) {
        return new Evaluation(-1, new Response(false, code == ExitCode.TIMEOUT, code.code(), description, false,
                List.of(), List.of()));
    }

    private void onEvent(CoreEvent event) {
        if (!(event instanceof ChangeEvent change)) {
            return;
        }
        Watch watch = watches.get(change.reference());
        if (watch == null) {
            return;
        }
        for (Subscription subscription : watch.subscriptions) {
            // A revision not above the last one seen is a reference loaded again under the same name.
            if (change.revision() <= subscription.revision) {
                subscription.force = true;
            }
        }
        watch.announced(change.revision());
    }

    /** One standing query and what its client was last told. */
    private static final class Subscription {
        final String id;
        final Directive query;
        final List<String> known;
        final CompletableFuture<Evaluation> first = new CompletableFuture<>();
        volatile boolean active = true;
        volatile boolean force;
        // Written only by the one worker evaluating its reference (hand-over through Watch.running).
        volatile long revision = ANY_REVISION;
        List<String> answer;
        int announcedFailure;
        int timeouts;

        Subscription(String id, Directive query, List<String> known) {
            this.id = id;
            this.query = query;
            this.known = known == null ? null : List.copyOf(known);
        }
    }

    /** The subscriptions of one reference and whether a worker is (or must be) evaluating them. */
    private final class Watch {
        final String reference;
        final List<Subscription> subscriptions = new CopyOnWriteArrayList<>();
        private final AtomicBoolean dirty = new AtomicBoolean();
        private final AtomicBoolean running = new AtomicBoolean();
        // The last change announced: its revision and when; and when the oldest unanswered one came.
        private volatile long announcedRevision = ANY_REVISION;
        private volatile long lastChangeNanos;
        private volatile long pendingSinceNanos;

        Watch(String reference) {
            this.reference = reference;
        }

        void announced(long revision) {
            long now = System.nanoTime();
            if (pendingSinceNanos == 0) {
                pendingSinceNanos = now;
            }
            lastChangeNanos = now;
            announcedRevision = revision;
            changed();
        }

        void changed() {
            dirty.set(true);
            if (running.compareAndSet(false, true)) {
                start();
            }
        }

        /** Nanoseconds until the reference has been quiet for QUIET_MS (0: it has). */
        long untilQuiet(long now) {
            return Math.max(0, lastChangeNanos + QUIET_MS * 1_000_000L - now);
        }

        /** Starts another round after {@code delayNanos}. */
        void postpone(long delayNanos) {
            try {
                retries.schedule(this::changed, Math.max(delayNanos, 1_000_000L), TimeUnit.NANOSECONDS);
            } catch (java.util.concurrent.RejectedExecutionException e) {
                // shutting down: nobody is waiting for answers any more
            }
        }

        /** Keeps the time the unanswered changes have waited since, for {@link #overdue}. */
        private void keepPending(long since) {
            long current = pendingSinceNanos;
            pendingSinceNanos = current == 0 ? since : Math.min(current, since);
        }

        private void start() {
            try {
                workers.execute(this::drain);
            } catch (java.util.concurrent.RejectedExecutionException e) {
                running.set(false);
                subscriptions.forEach(s -> s.first.complete(failure(ExitCode.CORE_UNAVAILABLE,
                        "the core is shutting down")));
            }
        }

        private void drain() {
            try {
                round:
                while (dirty.getAndSet(false)) {
                    long roundStart = System.nanoTime();
                    long pendingAtStart = pendingSinceNanos;
                    pendingSinceNanos = 0;
                    long waitingSince = pendingAtStart != 0 ? pendingAtStart : roundStart;
                    // New subscriptions first: their clients wait for the first answer.
                    List<Subscription> ordered = new ArrayList<>(subscriptions);
                    ordered.sort(java.util.Comparator.comparing(s -> s.first.isDone()));
                    for (Subscription subscription : ordered) {
                        if (!subscription.active) {
                            continue;
                        }
                        boolean first = !subscription.first.isDone();
                        long now = System.nanoTime();
                        boolean overdue = now - waitingSince >= MAX_DELAY_MS * 1_000_000L;
                        if (!first && !overdue && untilQuiet(now) > 0) {
                            keepPending(waitingSince);
                            postpone(untilQuiet(now));
                            break round;
                        }
                        long expected = first || overdue ? ANY_REVISION : announcedRevision;
                        if (!evaluate(this, subscription, expected)) {
                            keepPending(waitingSince);
                            postpone(QUIET_MS * 1_000_000L);
                            break round;
                        }
                    }
                }
            } finally {
                running.set(false);
                if (dirty.get() && running.compareAndSet(false, true)) {
                    start();
                }
            }
        }
    }

    /**
     * Asks one subscription again and announces what changed; false when it was postponed (the
     * reference changed again since {@code expectRevision}).
     */
    private boolean evaluate(Watch watch, Subscription s, long expectRevision) {
        boolean fresh = s.answer == null || s.force;
        Evaluation evaluation;
        try {
            evaluation = evaluator.evaluate(s.query, fresh ? ANY_REVISION : s.revision, expectRevision);
        } catch (RuntimeException e) {
            LOG.error("evaluating subscription {} failed", s.id, e);
            evaluation = failure(ExitCode.INTERNAL_ERROR, "evaluating the subscription failed: " + e);
        }
        if (evaluation == Evaluation.POSTPONED) {
            return false;
        }
        s.force = false;
        if (evaluation == null) {
            return true;
        }
        Response response = evaluation.response();
        if (!s.first.isDone()) {
            if (registered(response)) {
                List<String> now = answerOf(response);
                List<String> before = s.known == null ? List.of() : s.known;
                announce(s, evaluation.revision(), before, now, 0, "", s.known == null);
                s.answer = now;
                s.revision = evaluation.revision();
            }
            s.first.complete(evaluation);
            return true;
        }
        if (registered(response)) {
            s.timeouts = 0;
            // After a failure its subscriber heard of, the first answer again is news even when it is unchanged.
            boolean recovered = s.announcedFailure != 0;
            s.announcedFailure = 0;
            List<String> now = answerOf(response);
            announce(s, evaluation.revision(), s.answer, now, 0, "", recovered);
            s.answer = now;
            s.revision = evaluation.revision();
            return true;
        }
        int code = response.success() ? ExitCode.TIMEOUT.code() : response.exitCode();
        String description = response.success() ? "the query's time limit cut its answer short"
                : response.errorDescription();
        s.revision = ANY_REVISION;
        if (code == ExitCode.UNKNOWN_REFERENCE.code()) {
            // A dropped reference answers nothing: everything its client was told is gone.
            if (s.announcedFailure != code) {
                announce(s, -1, s.answer, List.of(), code, description, true);
                s.announcedFailure = code;
            }
            s.answer = List.of();
            return true;
        }
        if (code == ExitCode.TIMEOUT.code() && ++s.timeouts <= TIMEOUT_RETRIES) {
            s.force = true;
            watch.postpone(RETRY_DELAY_MS * 1_000_000L);
            return true;
        }
        if (s.announcedFailure != code) {
            announce(s, evaluation.revision(), List.of(), List.of(), code, description, true);
            s.announcedFailure = code;
        }
        return true;
    }

    /** Publishes what changed from {@code before} to {@code now}: when something did, or when told to anyway. */
    private void announce(Subscription s, long revision, List<String> before, List<String> now, int code,
                          String description, boolean always) {
        Set<String> beforeSet = new LinkedHashSet<>(before);
        Set<String> nowSet = new LinkedHashSet<>(now);
        List<String> added = new ArrayList<>();
        for (String answer : nowSet) {
            if (!beforeSet.contains(answer)) {
                added.add(answer);
            }
        }
        List<String> removed = new ArrayList<>();
        for (String answer : beforeSet) {
            if (!nowSet.contains(answer)) {
                removed.add(answer);
            }
        }
        if ((always || !added.isEmpty() || !removed.isEmpty()) && s.active) {
            feed.publish(AnswerEvent.now(s.id, s.query.referenceName(), revision, added, removed, code, description));
        }
    }

    private static List<String> answerOf(Response response) {
        return List.copyOf(new LinkedHashSet<>(response.queriedObjects()));
    }
}
