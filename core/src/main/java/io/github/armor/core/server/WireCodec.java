// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.DirectiveJson;
import io.github.armor.core.api.Response;
import java.util.ArrayList;
import java.util.List;

/**
 * Directives and responses as JSON objects whose keys are the ROS message field names, so the
 * node copies them field by field without knowing what they mean.
 */
final class WireCodec {
    private WireCodec() {}

    static Directive directive(JsonObject json) {
        return DirectiveJson.fromJson(json);
    }

    static List<Directive> directives(JsonArray array) {
        List<Directive> result = new ArrayList<>();
        for (JsonElement element : array) {
            result.add(directive(element.getAsJsonObject()));
        }
        return result;
    }

    static JsonObject response(Response response) {
        JsonObject json = new JsonObject();
        json.addProperty("success", response.success());
        json.addProperty("timeout", response.timeout());
        json.addProperty("exit_code", response.exitCode());
        json.addProperty("error_description", response.errorDescription());
        json.addProperty("is_consistent", response.isConsistent());
        JsonArray objects = new JsonArray();
        response.queriedObjects().forEach(objects::add);
        json.add("queried_objects", objects);
        JsonArray items = new JsonArray();
        for (Response.QueryItem item : response.sparqlQueriedObjects()) {
            JsonObject pair = new JsonObject();
            pair.addProperty("key", item.key());
            pair.addProperty("value", item.value());
            items.add(pair);
        }
        json.add("sparql_queried_objects", items);
        return json;
    }

    static JsonObject listResponse(ListResponse list) {
        JsonObject json = new JsonObject();
        json.addProperty("success", list.success());
        json.addProperty("is_consistent", list.isConsistent());
        JsonArray responses = new JsonArray();
        list.responses().forEach(r -> responses.add(response(r)));
        json.add("armor_responses", responses);
        return json;
    }
}
