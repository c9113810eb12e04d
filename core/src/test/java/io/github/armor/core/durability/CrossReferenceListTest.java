// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.ArmorCore;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An atomic list over two references comes back from the state directory in both or in neither,
 * whatever cut its records short: a power cut or a kill between its two journal appends, or
 * damage to one of its records. An acknowledged list stays whole when one of its references has
 * since been checkpointed (its record is then in that checkpoint, not in a journal).
 */
class CrossReferenceListTest {
    private static final int NO_CHECKPOINTS = 1000;

    @TempDir
    Path scratch;

    private static final List<Workload.Step> BEFORE = List.of(
            new Workload.Step(List.of(Workload.d("w", "map", "LOAD FILE", Workload.ROBOTICS, "", "false", "HERMIT",
                    "true"))),
            new Workload.Step(List.of(Workload.d("w", "other", "LOAD FILE", Workload.ROBOTICS, "", "false", "HERMIT",
                    "true"))),
            new Workload.Step(List.of(Workload.d("w", "map", "ADD IND CLASS", "r1", "Robot"))));
    private static final Workload.Step LIST = new Workload.Step(List.of(
            Workload.d("w", "map", "ADD IND CLASS", "r2", "Agent"),
            Workload.d("w", "other", "ADD IND CLASS", "r2", "Robot")));

    private static final List<Workload.Step> LATER = List.of(
            new Workload.Step(List.of(Workload.d("w", "map", "ADD IND CLASS", "r9", "Robot"))),
            new Workload.Step(List.of(Workload.d("w", "other", "ADD IND CLASS", "r9", "Robot"))));

    @Test
    void aPowerCutOrAKillAtAnyCallOfTheListRestoresAllOfItOrNone() throws IOException {
        Path count = scratch.resolve("count");
        SimulatedDisk counting = new SimulatedDisk(count);
        ArmorCore core = Workload.core(count, counting, NO_CHECKPOINTS);
        BEFORE.forEach(step -> assertTrue(Workload.run(core, step)));
        int first = counting.calls() + 1;
        assertTrue(Workload.run(core, LIST));
        int last = counting.calls();
        core.close();
        List<String> without = Workload.oracle(BEFORE);
        List<Workload.Step> withList = new ArrayList<>(BEFORE);
        withList.add(LIST);
        List<String> with = Workload.oracle(withList);
        int runs = 0;
        for (boolean powerCut : List.of(true, false)) {
            for (int k = first; k <= last; k++) {
                Path dir = scratch.resolve((powerCut ? "power-" : "kill-") + k);
                SimulatedDisk disk = new SimulatedDisk(dir).cutPowerAtCall(k);
                ArmorCore cut = Workload.core(dir, disk, NO_CHECKPOINTS);
                BEFORE.forEach(step -> assertTrue(Workload.run(cut, step)));
                boolean acknowledged = false;
                try {
                    acknowledged = Workload.run(cut, LIST);
                } catch (SimulatedDisk.PowerCut expected) {
                    // The list was in flight: it may come back whole or not at all.
                }
                cut.close();
                if (powerCut) {
                    disk.losePower();
                }
                ArmorCore restored = Workload.core(dir, Storage.FILES, NO_CHECKPOINTS);
                List<String> actual = Workload.digest(restored);
                String at = (powerCut ? "power cut at " : "kill at ") + counting.log().get(k - 1);
                assertTrue(actual.equals(with) || (!acknowledged && actual.equals(without)),
                        () -> at + ": restored " + actual + "\ninstead of all of the list " + with
                                + "\nor none of it " + without);
                assertEquals(List.of(), restored.execute(Workload.d("q", "", "GET STATE DAMAGE")).queriedObjects(),
                        at + ": a list in flight is not damage");
                // The journals cut at the restore take further changes, which the next restore keeps.
                List<Workload.Step> kept = new ArrayList<>(actual.equals(with) ? withList : BEFORE);
                for (Workload.Step later : LATER) {
                    assertTrue(Workload.run(restored, later), at + ": a change after the restore was refused");
                    kept.add(later);
                }
                restored.close();
                ArmorCore again = Workload.core(dir, Storage.FILES, NO_CHECKPOINTS);
                assertEquals(Workload.oracle(kept), Workload.digest(again), at + ": changes after the restore");
                again.close();
                runs++;
            }
        }
        System.out.println("cross-reference list: " + runs + " cuts over calls " + first + ".." + last
                + ", each restored all of the list or none");
    }

    @Test
    void anAcknowledgedListStaysWholeAfterOneOfItsReferencesIsCheckpointed() {
        Path dir = scratch.resolve("checkpointed");
        // A checkpoint every 2 changes: map's comes right after the list, other's never.
        ArmorCore core = Workload.core(dir, Storage.FILES, 2);
        List<Workload.Step> steps = new ArrayList<>(BEFORE);
        steps.add(LIST);
        steps.forEach(step -> assertTrue(Workload.run(core, step)));
        core.close();
        ArmorCore restored = Workload.core(dir, Storage.FILES, 2);
        assertEquals(Workload.oracle(steps), Workload.digest(restored));
        restored.close();
    }

    @Test
    void aListWhoseRecordIsDamagedInOneReferenceIsTakenOutOfTheOtherAndReported() throws IOException {
        Path dir = scratch.resolve("damaged");
        ArmorCore core = Workload.core(dir, Storage.FILES, NO_CHECKPOINTS);
        List<Workload.Step> steps = new ArrayList<>(BEFORE);
        steps.add(LIST);
        Workload.Step after = new Workload.Step(List.of(Workload.d("w", "map", "ADD IND CLASS", "r3", "Robot")));
        steps.add(after);
        steps.forEach(step -> assertTrue(Workload.run(core, step)));
        core.close();
        // other's only journal record is the list's: a flipped byte in its payload damages it.
        Path journal = dir.resolve("refs").resolve("other").resolve("journal-1.log");
        byte[] bytes = Files.readAllBytes(journal);
        bytes[bytes.length - 3] ^= 0x20;
        Files.write(journal, bytes);
        ArmorCore restored = Workload.core(dir, Storage.FILES, NO_CHECKPOINTS);
        List<String> actual = Workload.digest(restored);
        List<String> damage = restored.execute(Workload.d("q", "", "GET STATE DAMAGE")).queriedObjects();
        restored.close();
        // Up to before the list in both, and map's change after it goes with it: map is at a state it had.
        assertEquals(Workload.oracle(BEFORE), actual);
        assertTrue(damage.stream().anyMatch(d -> d.contains("\"reference\":\"other\"")), damage::toString);
        assertTrue(damage.stream().anyMatch(d -> d.contains("\"reference\":\"map\"")
                && d.contains("atomic list")), damage::toString);
        // The files now hold what was restored: a second restore finds the same and no new damage.
        ArmorCore again = Workload.core(dir, Storage.FILES, NO_CHECKPOINTS);
        assertEquals(actual, Workload.digest(again));
        again.close();
    }
}
