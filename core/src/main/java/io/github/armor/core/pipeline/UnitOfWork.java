// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.pipeline;

import io.github.armor.core.api.AcknowledgedChange;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.Directive;
import io.github.armor.core.durability.StateStore;
import io.github.armor.core.events.ChangeEvent;
import io.github.armor.core.events.EventFeed;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.reference.ReferenceRegistry;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What one directive, or one atomic list of them, changes, made all or none: the references it
 * enrols (a transaction each), what it must journal, then the journal record, the
 * acknowledgement and the events. A single directive completes while it still holds its
 * reference; a list holds every reference it touches until it completes or rolls back.
 */
final class UnitOfWork {
    private static final Logger LOG = LoggerFactory.getLogger(UnitOfWork.class);

    private final boolean single;
    private final ReferenceRegistry references;
    private final StateStore state;
    private final EventFeed events;
    private final long lockWaitMs;
    private final Set<Reference> held = new LinkedHashSet<>();
    private final Set<Reference> enrolled = new LinkedHashSet<>();
    private final List<Reference> created = new ArrayList<>();
    private final Set<Integer> changedBy = new LinkedHashSet<>();
    private final Map<Reference, List<Directive>> toJournal = new LinkedHashMap<>();
    private final List<ChangeEvent> creations = new ArrayList<>();
    private int position;

    private UnitOfWork(boolean single, ReferenceRegistry references, StateStore state, EventFeed events,
                       long lockWaitMs) {
        this.single = single;
        this.references = references;
        this.state = state;
        this.events = events;
        this.lockWaitMs = lockWaitMs;
    }

    /** The work of one directive on its own. */
    static UnitOfWork single(ReferenceRegistry references, StateStore state, EventFeed events) {
        return new UnitOfWork(true, references, state, events, 0);
    }

    /** The work of an atomic list; {@link #releaseAll} must follow, whatever happens. */
    static UnitOfWork list(ReferenceRegistry references, StateStore state, EventFeed events, long lockWaitMs) {
        return new UnitOfWork(false, references, state, events, lockWaitMs);
    }

    boolean single() {
        return single;
    }

    /** The list's directive now running. */
    void at(int index) {
        position = index;
    }

    /** Whether the directive at {@code index} changed something the list's rollback undoes. */
    boolean changedBy(int index) {
        return changedBy.contains(index);
    }

    /** Inside a list, keeps the reference until the list ends, so no other directive interleaves. */
    Reference hold(Reference reference) {
        if (!single && held.add(reference)) {
            try {
                reference.acquire(lockWaitMs);
            } catch (ArmorException e) {
                held.remove(reference);
                throw e;
            }
        }
        return reference;
    }

    /** Opens the reference's transaction, so that a failure undoes what follows. */
    void enrol(Reference reference) {
        if (enrolled.add(reference)) {
            reference.beginTransaction();
        }
    }

    /** The running directive changed what a rollback undoes. */
    void changed() {
        changedBy.add(position);
    }

    /** The running directive must be journaled, as part of its reference's next revision. */
    void journalLater(Reference reference, Directive directive) {
        toJournal.computeIfAbsent(reference, r -> new ArrayList<>()).add(directive);
    }

    /**
     * A creating directive made or loaded {@code made}; {@code creation} (null: none) announces
     * a new reference, at once for a single directive, after the commit for a list.
     */
    void created(Reference made, boolean isNew, ChangeEvent creation) {
        if (single) {
            if (creation != null) {
                events.publish(creation);
            }
            return;
        }
        if (creation != null) {
            creations.add(creation);
        }
        hold(made);
        if (isNew) {
            created.add(made);
            changed();
        }
    }

    /**
     * Journals, acknowledges and announces the work, then closes its transactions: one journal
     * record per reference (the work is one revision of each reference it changed). On failure
     * nothing was acknowledged and the caller rolls back.
     */
    void complete() {
        Map<Reference, AcknowledgedChange> changes = new LinkedHashMap<>();
        toJournal.forEach((reference, directives) -> changes.put(reference,
                new AcknowledgedChange(reference.revision() + 1, directives)));
        if (state != null) {
            state.recordAll(changes);
        }
        changes.forEach((reference, change) -> {
            reference.acknowledge(change);
            if (state != null) {
                state.checkpointIfDue(reference);
            }
        });
        enrolled.forEach(Reference::commitTransaction);
        // While the work still holds its references: its creations, then its changes.
        creations.forEach(events::publish);
        toJournal.forEach((reference, directives) -> events.publish(ChangeEvent.now(reference.name(),
                reference.revision(), directives, reference.isConsistent())));
    }

    /** Undoes everything the work changed: transactions in reverse, created references removed. */
    void rollback() {
        List<Reference> undo = new ArrayList<>(enrolled);
        Collections.reverse(undo);
        for (Reference reference : undo) {
            if (!created.contains(reference)) {
                reference.rollbackTransaction();
            }
        }
        for (Reference reference : created) {
            references.remove(reference);
            if (state != null) {
                try {
                    state.dropped(reference);
                } catch (ArmorException e) {
                    LOG.error("the state of '{}', made by a list that failed, stays: {}", reference.name(),
                            e.getMessage());
                }
            }
        }
    }

    void releaseAll() {
        held.forEach(Reference::release);
        held.clear();
    }
}
