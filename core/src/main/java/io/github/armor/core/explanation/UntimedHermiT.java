// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.explanation;

import org.semanticweb.HermiT.Configuration;
import org.semanticweb.HermiT.ReasonerFactory;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;

/**
 * HermiT for the explanation library's entailment checks, without a time limit per check. The
 * library asks every check's reasoner for a limit (none: the longest time there is), and HermiT
 * starts a timer thread for any limit and hands each task to it and back: on a check of a few
 * axioms that cost more than the reasoning, and far more on a busy machine. The search's own
 * deadline still stops it between checks, as before.
 */
final class UntimedHermiT extends ReasonerFactory {
    private static final long NO_TIME_LIMIT = -1;

    @Override
    protected Configuration getProtegeConfiguration(OWLReasonerConfiguration configuration) {
        Configuration hermit = super.getProtegeConfiguration(configuration);
        hermit.individualTaskTimeout = NO_TIME_LIMIT;
        return hermit;
    }
}
