// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.Optional;
import org.semanticweb.owlapi.reasoner.OWLReasoner;

/**
 * What a reference shows to readers that do not wait for it: the last state of its modular
 * reasoner that a writer finished with, with the reference's revision it reflects. The writer
 * offers the state when it lets the reference go, so a reader never sees the middle of an atomic
 * list.
 */
public final class PublishedStates {
    /** A state and the revision of the reference (its acknowledged changes) it reflects. */
    public record Published(long revision, InferredState state) {}

    private volatile Published current;

    /**
     * Makes the reasoner's state visible (writer only). A reasoner that keeps no state (one that
     * reasons on the whole ontology, or not ARMOR's modular one) withdraws the last one: readers
     * then wait for the reference as before. A modular reasoner not reasoned on yet keeps the
     * last one visible.
     */
    public void offer(OWLReasoner reasoner, long revision) {
        if (!(reasoner instanceof ModularReasoner modular) || !modular.handlesRemovals()) {
            current = null;
            return;
        }
        InferredState state = modular.state();
        Published shown = current;
        if (state != null && (shown == null || shown.state() != state || shown.revision() != revision)) {
            current = new Published(revision, state);
        }
    }

    /** The last state offered, if any. */
    public Optional<Published> current() {
        return Optional.ofNullable(current);
    }
}
