// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.List;
import java.util.regex.Pattern;

/**
 * The method a command has in the clients: {@code make catalogue} generates it in the Python
 * client (a typed module) and the C++ client from the catalogue, so a command registered with a
 * face needs no hand-written client code.
 *
 * @param method     the method's name, the same in Python and C++ ({@code instances})
 * @param answer     what it returns
 * @param parameters one per required argument, in order; a variadic command's one list
 */
public record Face(String method, Answer answer, List<Parameter> parameters) {
    private static final Pattern NAME = Pattern.compile("[a-z][a-z0-9_]*");

    /** What a generated method makes of the answer. */
    public enum Answer {
        /** Nothing: a change, whose answer is only success and consistency. */
        NONE,
        /** The queried objects as entity names (short names, or IRIs on request). */
        ENTITIES,
        /** The queried objects as typed values: literals converted, entities named. */
        VALUES,
        /** The queried objects as Manchester text, its IRIs written as short names. */
        EXPRESSIONS;

        String catalogueName() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /** A parameter: its name and whether it is text or a whole number. */
    public record Parameter(String name, boolean integer) {}

    public Face {
        parameters = List.copyOf(parameters);
    }

    /** A face from parameter specs written {@code "cls"} or {@code "count:int"}. */
    static Face of(String method, Answer answer, List<String> specs) {
        check(method);
        List<Parameter> parameters = specs.stream().map(spec -> {
            String[] parts = spec.split(":", 2);
            if (parts.length == 2 && !parts[1].equals("int")) {
                throw new IllegalArgumentException("face parameter " + spec + ": the only type is int");
            }
            return new Parameter(check(parts[0]), parts.length == 2);
        }).toList();
        return new Face(method, answer, parameters);
    }

    private static String check(String name) {
        if (!NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("not a method or parameter name: " + name);
        }
        return name;
    }

    /** Refuses a face that cannot be generated for this command. */
    void checkFits(String key, CommandKind kind, int required, boolean variadic) {
        boolean query = kind == CommandKind.QUERY;
        if (kind != CommandKind.MANIPULATION && !query) {
            throw new IllegalStateException(key + ": only queries and manipulations have a face");
        }
        if (query == (answer == Answer.NONE)) {
            throw new IllegalStateException(key + ": a query answers something, a manipulation nothing");
        }
        // A variadic command's face takes all its arguments as one list.
        if (variadic ? parameters.size() != 1 : parameters.size() != required) {
            throw new IllegalStateException(key + ": its face names " + parameters.size()
                    + " parameter(s) for " + (variadic ? "a list of arguments" : required + " argument(s)"));
        }
    }

    JsonObject json() {
        JsonObject face = new JsonObject();
        face.addProperty("method", method);
        face.addProperty("answer", answer.catalogueName());
        JsonArray list = new JsonArray();
        for (Parameter parameter : parameters) {
            JsonObject entry = new JsonObject();
            entry.addProperty("name", parameter.name());
            entry.addProperty("type", parameter.integer() ? "int" : "string");
            list.add(entry);
        }
        face.add("parameters", list);
        return face;
    }
}
