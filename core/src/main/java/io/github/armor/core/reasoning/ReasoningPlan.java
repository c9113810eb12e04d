// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.Locale;

/**
 * How a reference's ontology is reasoned on, said once for LOAD's answer, the node's log and the
 * web view: in modules (with how many, the largest, and the hub of individuals the schema names)
 * or on the whole ontology, and why.
 *
 * @param modular     whether the ABox is reasoned on in modules
 * @param because     why the whole ontology is reasoned on (empty when modular or not yet known)
 * @param modules     how many modules (0 when not modular)
 * @param largest     individuals in the largest module
 * @param hub         individuals in the hub (0: the schema names none)
 */
public record ReasoningPlan(boolean modular, String because, int modules, int largest, int hub) {
    /** Before the first reasoning. */
    public static final ReasoningPlan NOT_YET = new ReasoningPlan(false, "", 0, 0, 0);

    static ReasoningPlan modules(int modules, int largest, int hub) {
        return new ReasoningPlan(true, "", modules, largest, hub);
    }

    public static ReasoningPlan whole(String because) {
        return new ReasoningPlan(false, because, 0, 0, 0);
    }

    /** Whether the whole ontology is reasoned on (and {@link #because()} says why). */
    public boolean whole() {
        return !modular && !because.isEmpty();
    }

    /** One line for people: "in modules: 2,001 (largest 7 individuals)" or "on the whole ontology: SWRL rules". */
    public String describe() {
        if (modular) {
            return String.format(Locale.ROOT, "in modules: %,d (largest %,d individual%s%s)", modules, largest,
                    largest == 1 ? "" : "s", hub > 0 ? String.format(Locale.ROOT,
                            "; %,d in the hub of individuals the schema names", hub) : "");
        }
        return because.isEmpty() ? "not reasoned on yet" : "on the whole ontology: " + because;
    }
}
