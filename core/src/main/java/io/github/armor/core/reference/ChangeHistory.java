// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.AcknowledgedChange;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A reference's latest acknowledged changes, so that a client whose answer never arrived (a
 * lost reply, a 216, a time-out) can learn whether its change was applied before it resends
 * one (GET REF CHANGES). Bounded by count and by text; the state directory keeps it across
 * restarts. Thread-safe.
 */
public final class ChangeHistory {
    // A client that waited out a 30 s time-out while 8 others sent ~100 changes/s must still
    // find its change: the load benchmark (bench/default_clients.py) saw 2,000-3,000 meanwhile.
    public static final int MAX_CHANGES = 10_000;
    public static final long MAX_TEXT = 8L << 20;
    /** What one GET REF CHANGES answers at most: a client pages through the rest. */
    public static final int PAGE_CHANGES = 1_000;
    public static final long PAGE_TEXT = 1L << 20;
    /** How an answer that leaves changes out says from where to go on (clients read the number after it). */
    public static final String MORE_AFTER = "more changes after revision ";

    private final ArrayDeque<AcknowledgedChange> changes = new ArrayDeque<>();
    // Each client's last change, kept however old: a client must read its own writes.
    private final Map<String, Long> lastRevisionByClient = new HashMap<>();
    private long text;

    /** Adds a change newer than every kept one (an older or repeated revision is ignored). */
    public synchronized void add(AcknowledgedChange change) {
        if (!changes.isEmpty() && change.revision() <= changes.peekLast().revision()) {
            return;
        }
        changes.addLast(change);
        change.directives().forEach(d -> lastRevisionByClient.put(d.clientName(), change.revision()));
        text += change.textLength();
        while (changes.size() > MAX_CHANGES || (text > MAX_TEXT && changes.size() > 1)) {
            text -= changes.removeFirst().textLength();
        }
    }

    public synchronized void addAll(Collection<AcknowledgedChange> earlier) {
        earlier.forEach(this::add);
    }

    /** The kept changes after {@code revision}, oldest first. */
    public synchronized List<AcknowledgedChange> since(long revision) {
        List<AcknowledgedChange> after = new ArrayList<>();
        for (AcknowledgedChange change : changes) {
            if (change.revision() > revision) {
                after.add(change);
            }
        }
        return after;
    }

    /** The revision of the last change {@code client} took part in, or -1 when it made none. */
    public synchronized long lastRevisionOf(String client) {
        return lastRevisionByClient.getOrDefault(client, -1L);
    }

    /** The revision of the oldest kept change, or -1 when none is kept. */
    public synchronized long oldestRevision() {
        return changes.isEmpty() ? -1 : changes.peekFirst().revision();
    }

    public synchronized List<AcknowledgedChange> all() {
        return new ArrayList<>(changes);
    }
}
