// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import java.util.ArrayList;
import java.util.List;

/**
 * One acknowledged change of a reference: the revision it made and its directives (one for a
 * single directive, several for an atomic list). The journal, the change history and
 * {@code GET REF CHANGES} all write it as {@code {"revision": N, "directives": [...]}}.
 */
public record AcknowledgedChange(long revision, List<Directive> directives) {
    public AcknowledgedChange {
        directives = List.copyOf(directives);
    }

    public JsonObject toJson() {
        JsonArray array = new JsonArray();
        directives.forEach(d -> array.add(DirectiveJson.toJson(d)));
        JsonObject json = new JsonObject();
        json.addProperty("revision", revision);
        json.add("directives", array);
        return json;
    }

    /** Reads {@link #toJson()}'s form, or a bare array of directives (journals written before revisions). */
    public static AcknowledgedChange fromJson(JsonElement json, long revisionIfUnnamed) {
        long revision = revisionIfUnnamed;
        JsonArray array;
        if (json.isJsonObject()) {
            revision = json.getAsJsonObject().get("revision").getAsLong();
            array = json.getAsJsonObject().getAsJsonArray("directives");
        } else {
            array = json.getAsJsonArray();
        }
        List<Directive> directives = new ArrayList<>();
        for (JsonElement d : array) {
            directives.add(DirectiveJson.fromJson(d.getAsJsonObject()));
        }
        return new AcknowledgedChange(revision, directives);
    }

    /** How much text it holds, to bound the history by size as well as by count. */
    public long textLength() {
        long length = 0;
        for (Directive d : directives) {
            length += d.clientName().length() + d.command().length() + d.primarySpec().length()
                    + d.secondarySpec().length();
            for (String arg : d.args()) {
                length += arg.length();
            }
        }
        return length;
    }
}
