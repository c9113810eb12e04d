// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.view;

import com.google.gson.JsonObject;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reference.ReferenceRegistry;
import java.util.HashSet;
import java.util.function.ToLongFunction;

/**
 * The read-only views of the web page, for what no ARMOR directive answers: the core's socket op
 * {@code "view"} with {@code {"name": ..., parameters}}, answered with a JSON object, or with
 * {@code {"error": {"exit_code", "description"}}}. Each view reads its reference as a directive
 * does (see {@link ViewReads}) and changes nothing.
 *
 * <ul>
 *   <li>{@code overview}: every reference's summary ({@link Overview});
 *   <li>{@code reference} {reference}: one summary with the reference's properties;
 *   <li>{@code classes} {reference}: the class hierarchy ({@link ClassHierarchy});
 *   <li>{@code class} {reference, class, limit}: one class in detail;
 *   <li>{@code individuals} {reference, search, offset, limit}: a page of individuals ({@link IndividualsView});
 *   <li>{@code individual} {reference, individual}: one individual in detail;
 *   <li>{@code graph} {reference, properties (absent: all), class, focus, limit}: a property graph
 *       ({@link PropertyGraph});
 *   <li>{@code recent} {reference, limit, exclude_clients}: the last directives ({@link RecentDirectives}).
 * </ul>
 */
public final class ReferenceViews {
    static final int MAX_PAGE = 500;
    static final int MAX_GRAPH_NODES = 5_000;

    private final ViewReads reads;
    private final Overview overview;
    private final ClassHierarchy classes;
    private final IndividualsView individuals;
    private final PropertyGraph graph;
    private final RecentDirectives recent;

    /**
     * @param leaseLeftMs for a mount holder, how long its mount has left in ms (negative: no expiry)
     */
    public ReferenceViews(ReferenceRegistry references, CoreConfig config, RecentDirectives recent,
                          ToLongFunction<String> leaseLeftMs) {
        this.reads = new ViewReads(references, config.lockWaitMs());
        this.overview = new Overview(reads, leaseLeftMs);
        this.classes = new ClassHierarchy(reads);
        this.individuals = new IndividualsView(reads);
        this.graph = new PropertyGraph(reads);
        this.recent = recent;
    }

    /** The view a request names; a failure becomes {@code {"error": ...}}, never an exception. */
    public JsonObject answer(JsonObject request) {
        try {
            return view(request);
        } catch (ArmorException e) {
            JsonObject error = new JsonObject();
            error.addProperty("exit_code", e.exitCode().code());
            error.addProperty("description", e.getMessage());
            JsonObject reply = new JsonObject();
            reply.add("error", error);
            return reply;
        }
    }

    private JsonObject view(JsonObject request) {
        String name = ViewJson.text(request, "name");
        return switch (name) {
            case "overview" -> overview.all();
            case "reference" -> overview.one(ViewJson.text(request, "reference"));
            case "classes" -> classes.hierarchy(ViewJson.text(request, "reference"));
            case "class" -> classes.detail(ViewJson.text(request, "reference"), ViewJson.text(request, "class"),
                    ViewJson.number(request, "limit", 200, 1, MAX_PAGE));
            case "individuals" -> individuals.page(ViewJson.text(request, "reference"),
                    ViewJson.optionalText(request, "search", ""), ViewJson.number(request, "offset", 0, 0,
                            Integer.MAX_VALUE), ViewJson.number(request, "limit", 50, 1, MAX_PAGE));
            case "individual" -> individuals.detail(ViewJson.text(request, "reference"),
                    ViewJson.text(request, "individual"));
            case "graph" -> graph.graph(ViewJson.text(request, "reference"),
                    request.has("properties") ? ViewJson.texts(request, "properties") : null,
                    ViewJson.optionalText(request, "class", ""), ViewJson.optionalText(request, "focus", ""),
                    ViewJson.number(request, "limit", 300, 1, MAX_GRAPH_NODES));
            case "recent" -> recent.view(ViewJson.optionalText(request, "reference", ""),
                    ViewJson.number(request, "limit", 50, 1, RecentDirectives.CAPACITY),
                    new HashSet<>(ViewJson.texts(request, "exclude_clients")));
            default -> throw new ArmorException(ExitCode.UNKNOWN_COMMAND, "no view named '" + name
                    + "'; views: overview, reference, classes, class, individuals, individual, graph, recent");
        };
    }
}
