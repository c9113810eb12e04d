// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonPrimitive;
import io.github.armor.core.api.Setting;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/** The settings the node hands over at start, checked against {@link Setting}: known keys, right types. */
final class SettingsJson {
    private SettingsJson() {}

    /**
     * Every setting's value: the given one, or its default when absent.
     *
     * @throws IllegalArgumentException naming an unknown key or a value of the wrong type
     */
    static Map<Setting, Object> parse(JsonObject json) {
        Map<Setting, Object> values = new EnumMap<>(Setting.class);
        for (Setting setting : Setting.values()) {
            values.put(setting, setting.defaultValue());
        }
        for (Map.Entry<String, JsonElement> entry : json.entrySet()) {
            Setting setting = Setting.byKey(entry.getKey()).orElseThrow(() -> new IllegalArgumentException(
                    "unknown setting '" + entry.getKey() + "'; the core knows " + Arrays.stream(Setting.values())
                            .map(Setting::key).toList()));
            values.put(setting, value(setting, entry.getValue()));
        }
        return values;
    }

    private static Object value(Setting setting, JsonElement json) {
        try {
            switch (setting.type()) {
                case BOOLEAN:
                    if (json.isJsonPrimitive() && json.getAsJsonPrimitive().isBoolean()) {
                        return json.getAsBoolean();
                    }
                    break;
                case INTEGER:
                    if (isNumber(json) && json.getAsDouble() == Math.rint(json.getAsDouble())) {
                        return json.getAsLong();
                    }
                    break;
                case DOUBLE:
                    if (isNumber(json)) {
                        return json.getAsDouble();
                    }
                    break;
                case STRING:
                    if (json.isJsonPrimitive() && json.getAsJsonPrimitive().isString()) {
                        return json.getAsString();
                    }
                    break;
                case STRING_ARRAY:
                    if (json.isJsonArray()) {
                        List<String> items = new ArrayList<>();
                        for (JsonElement item : json.getAsJsonArray()) {
                            if (!item.isJsonPrimitive() || !item.getAsJsonPrimitive().isString()) {
                                throw new IllegalArgumentException("not a string: " + item);
                            }
                            items.add(item.getAsString());
                        }
                        return List.copyOf(items);
                    }
                    break;
                default:
                    break;
            }
        } catch (IllegalArgumentException | UnsupportedOperationException e) {
            // reported below with the expected type
        }
        throw new IllegalArgumentException("setting '" + setting.key() + "' must be of type "
                + setting.type().catalogueName() + ", got " + json);
    }

    private static boolean isNumber(JsonElement json) {
        return json instanceof JsonPrimitive primitive && primitive.isNumber();
    }
}
