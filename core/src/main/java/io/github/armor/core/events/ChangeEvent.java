// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.events;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.DirectiveJson;
import java.util.List;

/**
 * One acknowledged change of a reference, as its frame says:
 * {@code {"event": "change", "reference", "revision", "client_name", "directives": [...],
 * "exit_code", "is_consistent", "stamp_ns"}}.
 *
 * <p>Revision 0 is the reference's creation (LOAD or CREATE, the directive that made it); each
 * later change is one more, a whole atomic list one revision per reference it changed; DROP is
 * the reference's last event (one more again). A failed or rolled-back directive makes none.
 *
 * @param reference   the reference's name
 * @param revision    the reference's revision after the change
 * @param clientName  the client that sent it (the first changing directive's, for a list)
 * @param directives  the directives that made the change, in order
 * @param exitCode    0: only acknowledged changes become events
 * @param consistent  the reference's consistency after the change
 * @param stampNs     when it was acknowledged, in nanoseconds since the Unix epoch
 */
public record ChangeEvent(String reference, long revision, String clientName, List<Directive> directives,
                          int exitCode, boolean consistent, long stampNs) implements CoreEvent {

    public ChangeEvent {
        directives = List.copyOf(directives);
    }

    /** An acknowledged change made now. */
    public static ChangeEvent now(String reference, long revision, List<Directive> directives, boolean consistent) {
        String client = directives.isEmpty() ? "" : directives.get(0).clientName();
        return new ChangeEvent(reference, revision, client, directives, 0, consistent,
                CoreEvent.nowNanos());
    }

    @Override
    public JsonObject toJson() {
        JsonObject json = CoreEvent.frame("change", reference, revision);
        json.addProperty("client_name", clientName);
        JsonArray array = new JsonArray();
        directives.forEach(d -> array.add(DirectiveJson.toJson(d)));
        json.add("directives", array);
        json.addProperty("exit_code", exitCode);
        json.addProperty("is_consistent", consistent);
        json.addProperty("stamp_ns", stampNs);
        return json;
    }
}
