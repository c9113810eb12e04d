// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.BooleanSupplier;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.reasoner.ReasonerInterruptedException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Classifications of schemas under way, on threads of their own: an upper ontology's classes take
 * a reasoner minutes (SOMA's, with HermiT), longer than a LOAD should wait, and nothing but class
 * questions needs them. One classification per schema digest, shared by every reasoner that
 * wants it (a reference's reasoner made again after a time limit joins the one running); it is
 * stopped when the last of them lets it go (DROP). The reasoner works on a copy of the schema,
 * never on a reference's ontology, so it runs beside the directives on that reference.
 */
final class Classifications {
    private static final Logger LOG = LoggerFactory.getLogger(Classifications.class);
    private static final Map<String, Job> RUNNING = new HashMap<>();

    private Classifications() {}

    /** One schema's classification: its result when done, and who still wants it. */
    static final class Job {
        final ClassifiedSchema.Input input;
        final CompletableFuture<ClassifiedSchema> result = new CompletableFuture<>();
        final long startedNanos = System.nanoTime();
        private volatile OWLReasoner reasoner;
        private int interested;

        private Job(ClassifiedSchema.Input input) {
            this.input = input;
        }

        /** The classification if it is done (null while it runs, or when it failed). */
        ClassifiedSchema now() {
            return result.isDone() && !result.isCompletedExceptionally() ? result.join() : null;
        }

        boolean running() {
            return !result.isDone();
        }

        /**
         * Waits for the classification; {@code stop} ends the wait early (the directive waiting
         * overran its time limit), leaving the classification to go on.
         *
         * @return the classification, or null when it failed
         * @throws ReasonerInterruptedException when {@code stop} said so first
         */
        ClassifiedSchema await(BooleanSupplier stop) {
            while (true) {
                try {
                    return result.get(50, TimeUnit.MILLISECONDS);
                } catch (TimeoutException e) {
                    if (stop.getAsBoolean() || Thread.currentThread().isInterrupted()) {
                        throw new ReasonerInterruptedException("stopped waiting for the classification");
                    }
                } catch (ExecutionException e) {
                    return null;
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new ReasonerInterruptedException(e);
                }
            }
        }
    }

    /**
     * The classification of {@code input}: a finished job when it is kept already, the one
     * running for the same schema, or a new one started with a reasoner from {@code factory}.
     */
    static synchronized Job of(ClassifiedSchema.Input input, OWLReasonerFactory factory,
                               OWLReasonerConfiguration configuration) {
        ClassifiedSchema kept = ClassifiedSchema.known(input);
        if (kept != null) {
            Job done = new Job(input);
            done.result.complete(kept);
            return done;
        }
        Job job = RUNNING.get(input.digest());
        if (job == null) {
            job = new Job(input);
            RUNNING.put(input.digest(), job);
            Job started = job;
            Thread thread = new Thread(null, () -> classify(started, factory, configuration),
                    "armor-classification", 256L << 20);
            thread.setDaemon(true);
            thread.start();
        }
        job.interested++;
        return job;
    }

    /** Lets a classification go: the last one to do so stops it if it still runs. */
    static synchronized void release(Job job) {
        if (job == null || RUNNING.get(job.input.digest()) != job || --job.interested > 0) {
            return;
        }
        RUNNING.remove(job.input.digest());
        OWLReasoner running = job.reasoner;
        if (running != null) {
            running.interrupt();
        }
        job.result.cancel(false);
    }

    private static void classify(Job job, OWLReasonerFactory factory, OWLReasonerConfiguration configuration) {
        OWLOntologyManager scratch = OWLManager.createOWLOntologyManager();
        try {
            OWLOntology alone = scratch.createOntology(job.input.axioms().stream());
            job.reasoner = factory.createReasoner(alone, configuration);
            if (job.result.isDone()) {
                return;
            }
            job.result.complete(ClassifiedSchema.classify(job.input, job.reasoner));
        } catch (OWLOntologyCreationException | RuntimeException | LinkageError e) {
            if (!job.result.isCancelled()) {
                LOG.warn("classifying a schema of {} axioms failed: {}", job.input.axioms().size(), e.toString());
            }
            job.result.completeExceptionally(e);
        } finally {
            synchronized (Classifications.class) {
                RUNNING.remove(job.input.digest(), job);
            }
            OWLReasoner used = job.reasoner;
            if (used != null) {
                used.dispose();
            }
        }
    }
}
