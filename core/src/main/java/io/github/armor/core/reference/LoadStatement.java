// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * What LOAD tells a client about a reference beyond success, part by part (what the reasoner
 * will not use, how the ontology is reasoned on, ...): one place to add a part, rendered as one
 * line; empty parts are left out.
 */
public final class LoadStatement {
    private final Map<String, String> parts = new LinkedHashMap<>();

    /** Adds (or replaces) a part; an empty text leaves it out. */
    public LoadStatement with(String part, String text) {
        if (text != null && !text.isEmpty()) {
            parts.put(part, text);
        } else {
            parts.remove(part);
        }
        return this;
    }

    /** The parts by name, in the order they were added. */
    public Map<String, String> parts() {
        return Map.copyOf(parts);
    }

    /** The parts in one line, "; " between them. */
    public String text() {
        return String.join("; ", parts.values());
    }
}
