// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

import java.util.List;

/** One ARMOR answer, field for field as {@code armor_msgs/ArmorDirectiveRes}. */
public record Response(
        boolean success,
        boolean timeout,
        int exitCode,
        String errorDescription,
        boolean isConsistent,
        List<String> queriedObjects,
        List<QueryItem> sparqlQueriedObjects) {

    /** A key/value cell of a formatted SPARQL answer; an item with an empty key separates rows. */
    public record QueryItem(String key, String value) {}

    public static Response ok(boolean consistent, List<String> objects) {
        return new Response(true, false, 0, "", consistent, List.copyOf(objects), List.of());
    }

    public static Response okSparql(boolean consistent, List<QueryItem> items, boolean timedOut) {
        return new Response(true, timedOut, 0, "", consistent, List.of(), List.copyOf(items));
    }

    public static Response failure(ArmorException e, boolean consistent) {
        return new Response(false, e.isTimeout(), e.exitCode().code(), e.getMessage(), consistent,
                List.of(), List.of());
    }

    /** The same answer with a description; on a success it says what the client should know (warnings). */
    public Response withDescription(String description) {
        return new Response(success, timeout, exitCode, description, isConsistent, queriedObjects,
                sparqlQueriedObjects);
    }

    public Response withQueriedObjects(List<String> objects, boolean timedOut) {
        return new Response(success, timedOut, exitCode, errorDescription, isConsistent, List.copyOf(objects),
                sparqlQueriedObjects);
    }
}
