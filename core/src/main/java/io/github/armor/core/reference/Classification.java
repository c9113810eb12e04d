// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.reasoning.ClassifiedSchema;
import io.github.armor.core.reasoning.ModularReasoner;
import java.util.Locale;

/**
 * What a reference's classes cost: how many there are, and whether their hierarchy is kept
 * (classified once per schema: {@link ClassifiedSchema}), classified by this reference or taken
 * from an earlier classification of the same schema (another reference, the checkpoint's
 * sidecar), and how long classifying took. Said by LOAD and by the web view's overview.
 *
 * @param classes       named classes of the ontology, imports included
 * @param kept          whether the hierarchy is kept (a reasoner in modules keeps it; others classify when asked)
 * @param classifiedNow whether this reference classified it (not taken from an earlier classification)
 * @param nanos         how long classifying took, when it was done; how long it has run, while it runs
 * @param running       whether it is still being classified (in the background)
 */
public record Classification(int classes, boolean kept, boolean classifiedNow, long nanos, boolean running) {
    static Classification of(int classes, ModularReasoner reasoner) {
        long since = reasoner.classifyingSince();
        if (since >= 0) {
            return new Classification(classes, false, true, System.nanoTime() - since, true);
        }
        ClassifiedSchema schema = reasoner.classifiedSchema();
        return schema == null ? notKept(classes)
                : new Classification(classes, true, reasoner.classifiedHere(), schema.classificationNanos(), false);
    }

    static Classification notKept(int classes) {
        return new Classification(classes, false, false, 0, false);
    }

    public double seconds() {
        return nanos / 1e9;
    }

    /**
     * "677 classes, classified in 83 s", "..., hierarchy kept from an earlier classification (83 s)"
     * or "..., being classified in the background (12 s so far)".
     */
    public String describe() {
        String count = String.format(Locale.ROOT, "%,d class%s", classes, classes == 1 ? "" : "es");
        String time = nanos >= 10_000_000_000L ? String.format(Locale.ROOT, "%.0f s", seconds())
                : nanos >= 1_000_000_000L ? String.format(Locale.ROOT, "%.1f s", seconds())
                : String.format(Locale.ROOT, "%d ms", nanos / 1_000_000);
        if (running) {
            return count + ", being classified in the background (" + time + " so far, class questions wait for it)";
        }
        if (!kept) {
            return count;
        }
        return classifiedNow ? count + ", classified in " + time
                : count + ", hierarchy kept from an earlier classification (" + time + ")";
    }
}
