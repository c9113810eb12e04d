// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import java.util.concurrent.atomic.AtomicInteger;
import org.semanticweb.HermiT.ReasonerFactory;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;

/**
 * HermiT (named by class) whose reasoners, past the {@link #STALL_AFTER}-th made since the count
 * was reset, take {@link #STALL_MS} to start: an EXPLAIN makes one for every entailment check,
 * so a test counts the checks its first justification needs, then stalls the search right after
 * them and sees what the time limit answers.
 */
public class StallingChecksReasonerFactory extends ReasonerFactory {
    static final long STALL_MS = 10_000;
    static final AtomicInteger MADE = new AtomicInteger();
    static volatile int STALL_AFTER = Integer.MAX_VALUE;

    static void reset(int stallAfter) {
        MADE.set(0);
        STALL_AFTER = stallAfter;
    }

    @Override
    public OWLReasoner createReasoner(OWLOntology ontology, OWLReasonerConfiguration configuration) {
        if (MADE.incrementAndGet() > STALL_AFTER) {
            try {
                Thread.sleep(STALL_MS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        return super.createReasoner(ontology, configuration);
    }
}
