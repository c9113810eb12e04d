// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonPrimitive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Setting;
import java.util.Arrays;
import java.util.List;

/**
 * What the core offers, as JSON: every command (with its aliases, kind, arguments and summary),
 * every exit code and every setting. Printed by {@code --catalogue}, answered to the
 * {@code catalogue} socket operation and to the GET CATALOGUE directive (plugins' commands
 * included); the Python catalogue, the node's parameters and the documentation tables are
 * generated from it or checked against it.
 */
public final class Catalogue {
    /** Bumped when the shape of the JSON changes (not when commands are added). */
    public static final int FORMAT = 1;

    private Catalogue() {}

    public static JsonObject json(CommandTable table) {
        JsonObject catalogue = new JsonObject();
        catalogue.addProperty("format", FORMAT);
        JsonArray commands = new JsonArray();
        table.catalogue().forEach(spec -> commands.add(command(spec, table.face(spec.key()).orElse(null))));
        catalogue.add("commands", commands);
        JsonArray codes = new JsonArray();
        for (ExitCode code : ExitCode.values()) {
            JsonObject entry = new JsonObject();
            entry.addProperty("code", code.code());
            entry.addProperty("name", code.name());
            entry.addProperty("meaning", code.meaning());
            codes.add(entry);
        }
        catalogue.add("exit_codes", codes);
        JsonArray settings = new JsonArray();
        for (Setting setting : Setting.values()) {
            JsonObject entry = new JsonObject();
            entry.addProperty("key", setting.key());
            entry.addProperty("type", setting.type().catalogueName());
            entry.add("default", value(setting.defaultValue()));
            entry.addProperty("description", setting.description());
            entry.addProperty("read_only", !setting.live());
            settings.add(entry);
        }
        catalogue.add("settings", settings);
        return catalogue;
    }

    /** The catalogue as a person reads it (and as the generated files hold it). */
    public static String text(CommandTable table) {
        return new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create().toJson(json(table));
    }

    private static JsonObject command(CommandSpec spec, Face face) {
        JsonObject entry = new JsonObject();
        entry.addProperty("key", spec.key());
        entry.add("words", strings(Arrays.stream(spec.key().split(" ")).map(w -> w.equals("-") ? "" : w).toList()));
        entry.add("aliases", strings(spec.aliases()));
        entry.addProperty("kind", spec.kind().catalogueName());
        entry.addProperty("changes_ontology", spec.kind().changesOntology());
        JsonObject args = new JsonObject();
        args.add("required", strings(spec.required()));
        args.add("optional", strings(spec.optional()));
        args.addProperty("variadic", spec.variadic());
        entry.add("args", args);
        entry.addProperty("summary", spec.summary());
        entry.addProperty("origin", spec.origin());
        if (face != null) {
            entry.add("face", face.json());
        }
        return entry;
    }

    private static JsonArray strings(List<String> values) {
        JsonArray array = new JsonArray();
        values.forEach(array::add);
        return array;
    }

    private static JsonElement value(Object value) {
        if (value instanceof List<?> list) {
            return strings(list.stream().map(String::valueOf).toList());
        }
        if (value instanceof Boolean flag) {
            return new JsonPrimitive(flag);
        }
        if (value instanceof Number number) {
            return new JsonPrimitive(number);
        }
        return new JsonPrimitive(String.valueOf(value));
    }
}
