// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.bench;

import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

/**
 * The cost of durability, measured in-process side by side: the same acknowledged changes with
 * no journal, with a journal written to the page cache, and with a journal forced to disk per
 * acknowledgement. Run: {@code java -cp core/target/test-classes:core/target/classes:core/target/lib/*
 * io.github.armor.core.bench.JournalCostBench [changes]}.
 */
public final class JournalCostBench {
    private JournalCostBench() {}

    public static void main(String[] args) throws Exception {
        int changes = args.length > 0 ? Integer.parseInt(args[0]) : 2000;
        Path ontology = Path.of("ontologies", "robotics.owl").toAbsolutePath();
        System.out.println("| journal | changes/s | p50 us | p99 us | ratio to no journal |");
        System.out.println("|---|---|---|---|---|");
        double baseline = 0;
        for (String mode : List.of("none", "no fsync", "fsync", "none", "no fsync", "fsync")) {
            Path state = Files.createTempDirectory("armor-journal-bench");
            CoreConfig.Durability durability = mode.equals("none") ? CoreConfig.Durability.NONE
                    : new CoreConfig.Durability(state, false, mode.equals("fsync"), 1_000_000, 3600);
            try (ArmorCore core = new ArmorCore(new CoreConfig(true, "HERMIT", List.of(ontology.getParent()), false,
                    30_000, 0, 0, durability))) {
                core.restoreState();
                core.execute(Directive.of("bench", "map", "LOAD", "FILE", "", ontology.toString(), "", "false",
                        "HERMIT", "true"));
                long[] micros = new long[changes];
                long start = System.nanoTime();
                for (int i = 0; i < changes; i++) {
                    long t = System.nanoTime();
                    if (!core.execute(Directive.of("bench", "map", "ADD", "IND", "CLASS", "bot" + i, "Robot"))
                            .success()) {
                        throw new IllegalStateException("change " + i + " failed");
                    }
                    micros[i] = (System.nanoTime() - t) / 1000;
                }
                double perSecond = changes / ((System.nanoTime() - start) / 1e9);
                Arrays.sort(micros);
                if (mode.equals("none")) {
                    baseline = perSecond;
                }
                System.out.printf("| %s | %.0f | %d | %d | %.2f |%n", mode, perSecond, micros[changes / 2],
                        micros[(int) (changes * 0.99)], perSecond / baseline);
            }
        }
    }
}
