// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.reasoner.BufferingMode;
import org.semanticweb.owlapi.reasoner.InferenceType;
import org.semanticweb.owlapi.reasoner.NodeSet;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;
import org.semanticweb.owlapi.reasoner.ReasonerInterruptedException;
import org.semanticweb.owlapi.reasoner.impl.OWLClassNodeSet;
import org.semanticweb.owlapi.reasoner.impl.OWLNamedIndividualNodeSet;
import org.semanticweb.owlapi.reasoner.structural.StructuralReasoner;
import org.semanticweb.owlapi.reasoner.structural.StructuralReasonerFactory;

/**
 * A reasoner (named by class, as the contract allows) whose REASON, queries or start take
 * exactly as long as a test says, or until it is interrupted, and that answers an interruption
 * as a test says: time limits and waits become testable without depending on how fast a real
 * reasoner is on this machine.
 */
public class BlockingReasonerFactory extends StructuralReasonerFactory {
    /** How long precomputeInferences blocks; tests set it. */
    static final AtomicLong BLOCK_MS = new AtomicLong(0);
    /** How long isConsistent and the queries (instances, types, sub/super/equivalent classes, values) block. */
    static final AtomicLong QUERY_BLOCK_MS = new AtomicLong(0);
    /** How long making a reasoner blocks (it cannot be interrupted: there is no reasoner yet). */
    static final AtomicLong START_BLOCK_MS = new AtomicLong(0);
    /** What a blocked call does when interrupted. */
    static final AtomicReference<OnInterrupt> ON_INTERRUPT = new AtomicReference<>(OnInterrupt.THROW);
    static final AtomicInteger MADE = new AtomicInteger();
    static final AtomicInteger DISPOSED = new AtomicInteger();

    /** How real reasoners answer OWLReasoner.interrupt(). */
    enum OnInterrupt {
        /** Stop with ReasonerInterruptedException (HermiT, Openllet, ELK). */
        THROW,
        /** Stop and return what was found so far, as if complete (JFact's classification). */
        RETURN_PARTIAL,
        /** Go on until done (a reasoner in a phase that never checks). */
        IGNORE
    }

    static void reset() {
        BLOCK_MS.set(0);
        QUERY_BLOCK_MS.set(0);
        START_BLOCK_MS.set(0);
        ON_INTERRUPT.set(OnInterrupt.THROW);
    }

    @Override
    public OWLReasoner createReasoner(OWLOntology ontology, OWLReasonerConfiguration config) {
        return made(new BlockingReasoner(ontology, config, BufferingMode.BUFFERING));
    }

    @Override
    public OWLReasoner createNonBufferingReasoner(OWLOntology ontology, OWLReasonerConfiguration config) {
        return made(new BlockingReasoner(ontology, config, BufferingMode.NON_BUFFERING));
    }

    private static OWLReasoner made(BlockingReasoner reasoner) {
        sleep(START_BLOCK_MS.get());
        MADE.incrementAndGet();
        return reasoner;
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    static final class BlockingReasoner extends StructuralReasoner {
        private volatile boolean interrupted;

        BlockingReasoner(OWLOntology ontology, OWLReasonerConfiguration config, BufferingMode mode) {
            super(ontology, config, mode);
        }

        @Override
        public Set<InferenceType> getPrecomputableInferenceTypes() {
            return Set.of(InferenceType.CLASS_HIERARCHY);
        }

        @Override
        public void precomputeInferences(InferenceType... types) {
            if (block(BLOCK_MS.get())) {
                super.precomputeInferences(types);
            }
        }

        @Override
        public boolean isConsistent() {
            return !block(QUERY_BLOCK_MS.get()) || super.isConsistent();
        }

        @Override
        public NodeSet<OWLNamedIndividual> getInstances(OWLClassExpression ce, boolean direct) {
            return block(QUERY_BLOCK_MS.get()) ? super.getInstances(ce, direct) : new OWLNamedIndividualNodeSet();
        }

        @Override
        public NodeSet<OWLClass> getSubClasses(OWLClassExpression ce, boolean direct) {
            return block(QUERY_BLOCK_MS.get()) ? super.getSubClasses(ce, direct) : new OWLClassNodeSet();
        }

        @Override
        public NodeSet<OWLClass> getTypes(OWLNamedIndividual ind, boolean direct) {
            return block(QUERY_BLOCK_MS.get()) ? super.getTypes(ind, direct) : new OWLClassNodeSet();
        }

        /** Blocks for {@code ms}; false when interrupted meanwhile and told to return a partial answer. */
        private boolean block(long ms) {
            long deadline = System.nanoTime() + ms * 1_000_000L;
            while (System.nanoTime() < deadline) {
                if (interrupted) {
                    switch (ON_INTERRUPT.get()) {
                        case THROW -> throw new ReasonerInterruptedException("interrupted by the time limit");
                        case RETURN_PARTIAL -> {
                            return false;
                        }
                        case IGNORE -> { }
                    }
                }
                try {
                    Thread.sleep(5);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new ReasonerInterruptedException(e);
                }
            }
            return true;
        }

        @Override
        public void interrupt() {
            interrupted = true;
        }

        @Override
        public void dispose() {
            DISPOSED.incrementAndGet();
            super.dispose();
        }
    }
}
