// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;
import java.util.ArrayList;
import java.util.List;

/**
 * A scene as a client sends it, checked: its elements and the two thresholds its relations are
 * tested with (docs/scenes.md). Elements travel as one argument: a JSON array of
 * {@code {"type": "CONE", "features": [x, y, z, ax, ay, az]}} (what programs send: no type can
 * smuggle in another element), or, typed by hand, {@code TYPE x y z [ax ay az]} separated by ';'
 * or line breaks.
 *
 * @param position metres: how far apart two centres must be along an axis to be right/behind/above,
 *                 and how close in the other two to lie along it
 * @param axis     unit-less: how nearly parallel or perpendicular two axes must be, and how close
 *                 (squared distance) a centre must be to an axis to be coaxial
 */
public record Scene(List<SceneElement> elements, double position, double axis) {
    /**
     * The most elements a scene may have. Relations grow with the square of the elements and the
     * reasoner's work faster still; a table top has a few dozen at most (docs/scenes.md).
     */
    public static final int MAX_ELEMENTS = 100;

    /** Parses and checks everything a scene request carries, before anything is changed. */
    public static Scene parse(String elements, String position, String axis) {
        double positionThreshold = threshold("position_threshold", position);
        double axisThreshold = threshold("axis_threshold", axis);
        List<RawElement> raw = elements.trim().startsWith("[") ? fromJson(elements) : fromText(elements);
        if (raw.isEmpty()) {
            throw new InvalidScene(InvalidScene.Kind.SHAPE, "the scene has no element (give at least one, "
                    + "each as TYPE x y z [ax ay az])");
        }
        if (raw.size() > MAX_ELEMENTS) {
            throw new InvalidScene(InvalidScene.Kind.TOO_LARGE, "the scene has " + raw.size()
                    + " elements; a scene may have at most " + MAX_ELEMENTS);
        }
        List<SceneElement> parsed = new ArrayList<>();
        for (int i = 0; i < raw.size(); i++) {
            parsed.add(element(i + 1, raw.get(i)));
        }
        return new Scene(List.copyOf(parsed), positionThreshold, axisThreshold);
    }

    /** A number in [0, 1]: the similarity above which a scene counts as known (learning_treshold). */
    public static double learningThreshold(String text) {
        double value = number(text, "learning_threshold");
        if (value < 0 || value > 1) {
            throw new InvalidScene(InvalidScene.Kind.VALUE, "learning_threshold must lie in [0, 1], got " + text.trim());
        }
        return value;
    }

    private static double threshold(String name, String text) {
        double value = number(text, name);
        if (value < 0) {
            throw new InvalidScene(InvalidScene.Kind.VALUE, name + " must not be negative, got " + text.trim());
        }
        return value;
    }

    /** An element as sent: its type's name and its features, not yet checked. */
    private record RawElement(String type, List<String> features) {}

    private static List<RawElement> fromText(String elements) {
        List<RawElement> raw = new ArrayList<>();
        for (String text : elements.split("[;\\n]")) {
            if (!text.isBlank()) {
                List<String> words = List.of(text.trim().split("[\\s,]+"));
                raw.add(new RawElement(words.get(0), words.subList(1, words.size())));
            }
        }
        return raw;
    }

    private static List<RawElement> fromJson(String elements) {
        JsonElement parsed;
        try {
            parsed = JsonParser.parseString(elements);
        } catch (JsonParseException e) {
            throw new InvalidScene(InvalidScene.Kind.SHAPE, "the elements are not a JSON array: " + e.getMessage());
        }
        List<RawElement> raw = new ArrayList<>();
        if (!parsed.isJsonArray()) {
            throw new InvalidScene(InvalidScene.Kind.SHAPE, "the elements are not a JSON array");
        }
        for (JsonElement item : parsed.getAsJsonArray()) {
            int place = raw.size() + 1;
            if (!item.isJsonObject() || !item.getAsJsonObject().has("type")
                    || !item.getAsJsonObject().get("type").isJsonPrimitive()
                    || !(item.getAsJsonObject().get("features") instanceof JsonArray features)) {
                throw new InvalidScene(InvalidScene.Kind.SHAPE, "element " + place
                        + " is not {\"type\": TYPE, \"features\": [numbers]}");
            }
            List<String> values = new ArrayList<>();
            for (JsonElement value : features) {
                values.add(value.isJsonPrimitive() ? value.getAsString() : value.toString());
            }
            raw.add(new RawElement(item.getAsJsonObject().get("type").getAsString(), values));
        }
        return raw;
    }

    private static SceneElement element(int place, RawElement raw) {
        Shape shape = Shape.named(raw.type()).orElseThrow(() -> new InvalidScene(InvalidScene.Kind.SHAPE,
                "element " + place + " has the unknown type '" + raw.type() + "' (known: SPHERE, PLANE, CONE, CYLINDER)"));
        String label = shape.name() + "#" + place;
        List<String> words = raw.features();
        int features = words.size();
        boolean centreOnly = features == 3;
        boolean withAxis = features == 6 && shape.orientable();
        if (!centreOnly && !withAxis) {
            throw new InvalidScene(InvalidScene.Kind.SHAPE, "element " + place + " (" + shape + ") has " + features
                    + " features; it takes 3 (centre x y z)" + (shape.orientable()
                    ? " or 6 (centre, then axis x y z)" : " (a sphere has no axis)"));
        }
        double[] values = new double[features];
        for (int i = 0; i < features; i++) {
            values[i] = number(words.get(i), "feature " + (i + 1) + " of element " + place + " (" + shape + ")");
        }
        double[] centre = {values[0], values[1], values[2]};
        double[] axis = null;
        if (withAxis) {
            axis = new double[] {values[3], values[4], values[5]};
            if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) {
                throw new InvalidScene(InvalidScene.Kind.VALUE, "the axis of element " + place + " (" + shape
                        + ") is (0, 0, 0); an axis needs a direction");
            }
        }
        return new SceneElement(label, shape, centre, axis);
    }

    private static double number(String text, String what) {
        double value;
        try {
            value = Double.parseDouble(text.trim());
        } catch (NumberFormatException e) {
            throw new InvalidScene(InvalidScene.Kind.VALUE, what + " is not a finite number: '" + text.trim() + "'");
        }
        if (!Double.isFinite(value)) {
            throw new InvalidScene(InvalidScene.Kind.VALUE, what + " is not a finite number: '" + text.trim() + "'");
        }
        return value;
    }
}
