// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.events;

import com.google.gson.JsonObject;
import java.time.Instant;

/**
 * Something the core tells its clients without being asked: a change of a reference or a new
 * answer of a subscription. On the socket it is a frame without an {@code id} whose
 * {@code "event"} key names the kind.
 */
public interface CoreEvent {
    /** The reference the event is about. */
    String reference();

    /** The frame sent to clients. */
    JsonObject toJson();

    /** The start of every event's frame: its kind, the reference and the revision it is about. */
    static JsonObject frame(String event, String reference, long revision) {
        JsonObject json = new JsonObject();
        json.addProperty("event", event);
        json.addProperty("reference", reference);
        json.addProperty("revision", revision);
        return json;
    }

    /** The wall-clock time now, in nanoseconds since the epoch: when an event happened. */
    static long nowNanos() {
        Instant now = Instant.now();
        return now.getEpochSecond() * 1_000_000_000L + now.getNano();
    }
}
