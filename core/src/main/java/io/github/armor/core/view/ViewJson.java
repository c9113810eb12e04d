// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.view;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import org.semanticweb.owlapi.model.OWLEntity;

/** The JSON of views: entities as {@code {"iri", "name"}}, and the checked parameters of a request. */
final class ViewJson {
    /** Entities in the order a person reads them: by short name, then by IRI. */
    static final Comparator<OWLEntity> BY_NAME = Comparator.comparing((OWLEntity e) -> e.getIRI().getShortForm())
            .thenComparing(e -> e.getIRI().toString());

    private ViewJson() {}

    static JsonObject entity(OWLEntity entity) {
        JsonObject json = new JsonObject();
        json.addProperty("iri", entity.getIRI().toString());
        json.addProperty("name", entity.getIRI().getShortForm());
        return json;
    }

    /** An entity and whether the ontology asserts it ({@code false}: only the reasoner infers it). */
    static JsonObject entity(OWLEntity entity, boolean asserted) {
        JsonObject json = entity(entity);
        json.addProperty("asserted", asserted);
        return json;
    }

    static JsonArray entities(Collection<? extends OWLEntity> entities) {
        JsonArray array = new JsonArray();
        entities.stream().sorted(BY_NAME).forEach(e -> array.add(entity(e)));
        return array;
    }

    static JsonArray strings(Collection<String> values) {
        JsonArray array = new JsonArray();
        values.forEach(array::add);
        return array;
    }

    /** A required string parameter. */
    static String text(JsonObject request, String key) {
        String value = optionalText(request, key, "");
        if (value.isBlank()) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "the view needs '" + key + "'");
        }
        return value;
    }

    static String optionalText(JsonObject request, String key, String absent) {
        JsonElement value = request.get(key);
        if (value == null || value.isJsonNull()) {
            return absent;
        }
        if (!value.isJsonPrimitive() || !value.getAsJsonPrimitive().isString()) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "'" + key + "' must be a string");
        }
        return value.getAsString();
    }

    /** An integer parameter within {@code [min, max]}, {@code absent} when not given. */
    static int number(JsonObject request, String key, int absent, int min, int max) {
        JsonElement value = request.get(key);
        if (value == null || value.isJsonNull()) {
            return absent;
        }
        long number;
        try {
            if (!value.isJsonPrimitive() || !value.getAsJsonPrimitive().isNumber()) {
                throw new NumberFormatException();
            }
            number = value.getAsBigDecimal().longValueExact();
        } catch (NumberFormatException | ArithmeticException e) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "'" + key + "' must be a whole number");
        }
        if (number < min || number > max) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "'" + key + "' must be between " + min + " and "
                    + max + ", got " + number);
        }
        return (int) number;
    }

    /** A list of strings parameter, empty when not given. */
    static List<String> texts(JsonObject request, String key) {
        JsonElement value = request.get(key);
        List<String> texts = new ArrayList<>();
        if (value == null || value.isJsonNull()) {
            return texts;
        }
        if (!value.isJsonArray()) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "'" + key + "' must be a list of strings");
        }
        for (JsonElement item : value.getAsJsonArray()) {
            if (!item.isJsonPrimitive() || !item.getAsJsonPrimitive().isString()) {
                throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "'" + key + "' must be a list of strings");
            }
            texts.add(item.getAsString());
        }
        return texts;
    }
}
