// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import java.util.ArrayList;
import java.util.List;

/** A directive as a JSON object keyed by the armor_msgs field names (wire and journal alike). */
public final class DirectiveJson {
    private DirectiveJson() {}

    public static JsonObject toJson(Directive directive) {
        JsonObject json = new JsonObject();
        json.addProperty("client_name", directive.clientName());
        json.addProperty("reference_name", directive.referenceName());
        json.addProperty("command", directive.command());
        json.addProperty("primary_command_spec", directive.primarySpec());
        json.addProperty("secondary_command_spec", directive.secondarySpec());
        JsonArray args = new JsonArray();
        directive.args().forEach(args::add);
        json.add("args", args);
        return json;
    }

    public static Directive fromJson(JsonObject json) {
        List<String> args = new ArrayList<>();
        if (json.has("args") && json.get("args").isJsonArray()) {
            for (JsonElement arg : json.getAsJsonArray("args")) {
                args.add(arg.isJsonNull() ? "" : arg.getAsString());
            }
        }
        return new Directive(text(json, "client_name"), text(json, "reference_name"), text(json, "command"),
                text(json, "primary_command_spec"), text(json, "secondary_command_spec"), args);
    }

    private static String text(JsonObject json, String key) {
        JsonElement value = json.get(key);
        return value == null || value.isJsonNull() ? "" : value.getAsString();
    }
}
