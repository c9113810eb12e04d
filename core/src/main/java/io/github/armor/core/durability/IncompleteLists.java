// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * An atomic list over several references is restored in all of them or in none. Its records are
 * appended to one journal after the other, so a crash between two appends leaves it in some
 * journals only; an acknowledged list has every record forced first, so a list missing from a
 * journal was never acknowledged (or that journal lost it to damage, which its restore reports).
 * Such a list is taken out of the references that hold it, with every record after it.
 */
final class IncompleteLists {
    private IncompleteLists() {}

    static List<StateStore.Restorable> takenOut(List<StateStore.Restorable> found) {
        Map<String, StateStore.Restorable> byName = new LinkedHashMap<>();
        found.forEach(r -> byName.put(r.name(), r));
        // Taking records out of one reference can leave a list of another incomplete: again until none is.
        boolean changed = true;
        while (changed) {
            changed = false;
            for (StateStore.Restorable restorable : byName.values()) {
                StateStore.Restorable cut = firstIncompleteTakenOut(restorable, byName);
                if (cut != null) {
                    byName.put(cut.name(), cut);
                    changed = true;
                    break;
                }
            }
        }
        return new ArrayList<>(byName.values());
    }

    /** The reference without its first incomplete list and what follows it, or null when it has none. */
    private static StateStore.Restorable firstIncompleteTakenOut(StateStore.Restorable restorable,
                                                                 Map<String, StateStore.Restorable> byName) {
        List<ReferenceStore.Replayed> records = restorable.store().replayed();
        for (int i = 0; i < records.size(); i++) {
            ListSpan list = records.get(i).list();
            if (list == null) {
                continue;
            }
            List<String> missing = new ArrayList<>();
            list.revisions().forEach((other, revision) -> {
                if (!other.equals(restorable.name()) && !holds(byName.get(other), list, revision)) {
                    missing.add(other);
                }
            });
            if (missing.isEmpty()) {
                continue;
            }
            // Lost by a crash before they were forced, unless those references' restores found damage.
            boolean inFlight = missing.stream().allMatch(other -> byName.get(other).problems().isEmpty());
            return StateStore.restorable(restorable.store().withoutRecordsFrom(restorable, i, inFlight,
                    "belongs to an atomic list over " + String.join(", ", list.revisions().keySet())
                            + " whose record in " + String.join(", ", missing) + " is missing"));
        }
        return null;
    }

    /**
     * Whether {@code other} holds its part of the list: its journals have the list's record, or
     * its checkpoint is past the revision the list gave it (a checkpoint is taken only once every
     * record of the list is on the disk). A reference not restored (dropped since, or reported
     * unrestorable) cannot say, and does not hold the others back.
     */
    private static boolean holds(StateStore.Restorable other, ListSpan list, long revision) {
        if (other == null) {
            return true;
        }
        return other.store().checkpointRevision() >= revision || other.store().replayed().stream()
                .anyMatch(r -> r.list() != null && r.list().id().equals(list.id()));
    }
}
