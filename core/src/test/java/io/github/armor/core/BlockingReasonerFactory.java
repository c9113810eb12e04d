// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.reasoner.BufferingMode;
import org.semanticweb.owlapi.reasoner.InferenceType;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;
import org.semanticweb.owlapi.reasoner.ReasonerInterruptedException;
import org.semanticweb.owlapi.reasoner.structural.StructuralReasoner;
import org.semanticweb.owlapi.reasoner.structural.StructuralReasonerFactory;

/**
 * A reasoner (named by class, as the contract allows) whose REASON takes exactly as long as a
 * test says, or until it is interrupted: time limits and waits become testable without
 * depending on how fast a real reasoner is on this machine.
 */
public class BlockingReasonerFactory extends StructuralReasonerFactory {
    /** How long precomputeInferences blocks; tests set it. */
    static final AtomicLong BLOCK_MS = new AtomicLong(0);

    @Override
    public OWLReasoner createReasoner(OWLOntology ontology, OWLReasonerConfiguration config) {
        return new BlockingReasoner(ontology, config, BufferingMode.BUFFERING);
    }

    @Override
    public OWLReasoner createNonBufferingReasoner(OWLOntology ontology, OWLReasonerConfiguration config) {
        return new BlockingReasoner(ontology, config, BufferingMode.NON_BUFFERING);
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
            long deadline = System.nanoTime() + BLOCK_MS.get() * 1_000_000L;
            while (System.nanoTime() < deadline) {
                if (interrupted) {
                    throw new ReasonerInterruptedException("interrupted by the time limit");
                }
                try {
                    Thread.sleep(5);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new ReasonerInterruptedException(e);
                }
            }
            super.precomputeInferences(types);
        }

        @Override
        public void interrupt() {
            interrupted = true;
        }
    }
}
