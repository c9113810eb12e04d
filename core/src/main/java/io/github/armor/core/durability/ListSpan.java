// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import com.google.gson.JsonObject;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * An atomic list that changed several references, as each of their journal records names it:
 * an id no other list shares (across restarts too) and the revision the list gave each
 * reference. Each journal is atomic on its own; this is what lets a restore see that a crash
 * came between two of a list's records and apply the list in all of its references or none.
 */
record ListSpan(String id, Map<String, Long> revisions) {
    private static final SecureRandom IDS = new SecureRandom();

    ListSpan {
        revisions = Map.copyOf(revisions);
    }

    static ListSpan fresh(Map<String, Long> revisions) {
        byte[] id = new byte[12];
        IDS.nextBytes(id);
        return new ListSpan(HexFormat.of().formatHex(id), new LinkedHashMap<>(revisions));
    }

    JsonObject toJson() {
        JsonObject json = new JsonObject();
        json.addProperty("id", id);
        JsonObject refs = new JsonObject();
        revisions.forEach(refs::addProperty);
        json.add("revisions", refs);
        return json;
    }

    /** The span a journal record names, or null when it is a reference's own change. */
    static ListSpan fromRecord(JsonObject record) {
        if (!record.has("list")) {
            return null;
        }
        JsonObject json = record.getAsJsonObject("list");
        Map<String, Long> revisions = new LinkedHashMap<>();
        json.getAsJsonObject("revisions").entrySet().forEach(e -> revisions.put(e.getKey(), e.getValue().getAsLong()));
        return new ListSpan(json.get("id").getAsString(), revisions);
    }
}
