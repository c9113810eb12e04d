// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.reference.EntityResolver;
import io.github.armor.core.api.Response;
import java.nio.file.Path;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** The "did you mean" distance: exact up to its limit, and bounded work for hostile names. */
class NameSuggestionTest {
    @TempDir
    Path scratch;

    /** Every cell of the table, as a textbook computes it: the oracle. */
    private static int fullDistance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            for (int j = 0; j <= b.length(); j++) {
                d[i][j] = i == 0 ? j : j == 0 ? i : Math.min(
                        d[i - 1][j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1),
                        Math.min(d[i - 1][j], d[i][j - 1]) + 1);
            }
        }
        return d[a.length()][b.length()];
    }

    private static String word(Random random, int length) {
        StringBuilder text = new StringBuilder();
        for (int k = 0; k < length; k++) {
            text.append((char) ('a' + random.nextInt(3)));
        }
        return text.toString();
    }

    @Test
    void equalsTheFullTableUpToItsLimitAndSaysOverBeyondIt() {
        long seed = System.nanoTime();
        Random random = new Random(seed);
        for (int run = 0; run < 20_000; run++) {
            String a = word(random, random.nextInt(12));
            String b = random.nextBoolean() ? word(random, random.nextInt(12)) : a.substring(0, a.length() / 2)
                    + word(random, random.nextInt(3)) + a.substring(a.length() / 2);
            int limit = random.nextInt(10) == 0 ? Integer.MAX_VALUE : random.nextInt(5);
            int full = fullDistance(a, b);
            int banded = EntityResolver.editDistance(a, b, limit);
            String what = "seed " + seed + ": '" + a + "' '" + b + "' limit " + limit;
            if (full <= limit) {
                assertEquals(full, banded, what);
            } else {
                assertEquals(limit + 1, banded, what);
            }
        }
    }

    /**
     * A client's 100,000-character name near another such name the reference holds: before the
     * distance kept to the diagonal band, the check that a name is new took 10^10 steps (70-80 s
     * per directive in the fuzz run, the reference held all along). The limit here is a hang
     * guard of many times the work now done, not a speed target.
     */
    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS)
    void aHugeNameNearAnotherIsAnsweredWithoutScanningTheirSquare() {
        String known = "x".repeat(300_000);
        assertEquals(1, EntityResolver.editDistance(known, known + "y", 3));
        assertEquals(4, EntityResolver.editDistance(known, "y".repeat(4) + known.substring(4), 3));
        CoreFixture f = new CoreFixture(scratch);
        f.loadRobotics("map", "HERMIT", false);
        f.ok("map", "ADD IND CLASS", known, "Robot");
        Response near = f.ok("map", "ADD IND CLASS", known + "y", "Robot");
        assertTrue(near.errorDescription().startsWith("new to the reference: individual '"),
                near.errorDescription().substring(0, 80));
        assertTrue(near.errorDescription().endsWith("(did you mean " + known + "?)"),
                "no suggestion of the known name");
    }
}
