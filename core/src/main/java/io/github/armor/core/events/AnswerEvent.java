// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.events;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.List;

/**
 * What changed in a subscription's answer, as its frame says: {@code {"event": "answer",
 * "subscription", "reference", "revision", "added": [...], "removed": [...], "exit_code",
 * "error_description", "stamp_ns"}}.
 *
 * <p>A subscription's first event holds its whole answer in {@code added} (or, when it was
 * registered again with the answer its client already knew, the difference from that). Later
 * events say which answers appeared and disappeared since the previous one; the answer holds at
 * {@code revision} of the reference. An evaluation that fails (the reference became inconsistent,
 * a time limit) is announced once, with its code and description and no change; a dropped
 * reference answers nothing, so its event removes every answer, with code 206.
 *
 * @param subscription     the subscription's id, as its client chose it
 * @param reference        the reference it queries
 * @param revision         the reference's revision the answer holds at (-1: the reference is gone)
 * @param added            answers that appeared, in the order the query gives them
 * @param removed          answers that disappeared, in the order the previous answer gave them
 * @param exitCode         0, or why this evaluation failed
 * @param errorDescription why it failed, or empty
 * @param stampNs          when the evaluation ended, in nanoseconds since the Unix epoch
 */
public record AnswerEvent(String subscription, String reference, long revision, List<String> added,
                          List<String> removed, int exitCode, String errorDescription, long stampNs)
        implements CoreEvent {

    public AnswerEvent {
        added = List.copyOf(added);
        removed = List.copyOf(removed);
    }

    static AnswerEvent now(String subscription, String reference, long revision, List<String> added,
                           List<String> removed, int exitCode, String errorDescription) {
        return new AnswerEvent(subscription, reference, revision, added, removed, exitCode, errorDescription,
                CoreEvent.nowNanos());
    }

    @Override
    public JsonObject toJson() {
        JsonObject json = CoreEvent.frame("answer", reference, revision);
        json.addProperty("subscription", subscription);
        json.add("added", strings(added));
        json.add("removed", strings(removed));
        json.addProperty("exit_code", exitCode);
        json.addProperty("error_description", errorDescription);
        json.addProperty("stamp_ns", stampNs);
        return json;
    }

    private static JsonArray strings(List<String> values) {
        JsonArray array = new JsonArray();
        values.forEach(array::add);
        return array;
    }
}
