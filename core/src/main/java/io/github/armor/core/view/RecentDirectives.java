// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.view;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Set;

/**
 * The last directives the core answered (whoever sent them), for the web view's "recent
 * directives": client, reference, command, arguments, exit code and latency. A bounded ring, so
 * a core answering thousands of directives a second keeps a constant, small amount of memory.
 */
public final class RecentDirectives {
    static final int CAPACITY = 1_000;
    private static final int SHOWN_ARGUMENTS = 6;
    private static final int SHOWN_ARGUMENT_CHARS = 120;

    /** One answered directive, its arguments already cut to what the page shows. */
    record Entry(long atEpochMs, String client, String reference, String command, List<String> args,
                 int exitCode, boolean success, double latencyMs) {}

    private final ArrayDeque<Entry> entries = new ArrayDeque<>(CAPACITY);

    /** Notes a directive and its response; {@code latencyNanos} from its arrival to its answer. */
    public void record(Directive directive, Response response, long latencyNanos) {
        List<String> args = new ArrayList<>();
        for (String arg : directive.args()) {
            if (args.size() == SHOWN_ARGUMENTS) {
                args.add("... (" + directive.args().size() + " arguments)");
                break;
            }
            args.add(arg.length() <= SHOWN_ARGUMENT_CHARS ? arg : arg.substring(0, SHOWN_ARGUMENT_CHARS) + "...");
        }
        Entry entry = new Entry(System.currentTimeMillis(), directive.clientName(), directive.referenceName(),
                directive.describe(), List.copyOf(args), response.exitCode(), response.success(),
                latencyNanos / 1e6);
        synchronized (entries) {
            if (entries.size() == CAPACITY) {
                entries.removeFirst();
            }
            entries.addLast(entry);
        }
    }

    /**
     * Newest first: at most {@code limit} directives on {@code reference} (every reference when
     * empty), leaving out those of the clients in {@code excludedClients}.
     */
    JsonObject view(String reference, int limit, Set<String> excludedClients) {
        List<Entry> chosen = new ArrayList<>();
        synchronized (entries) {
            Iterator<Entry> newestFirst = entries.descendingIterator();
            while (newestFirst.hasNext() && chosen.size() < limit) {
                Entry entry = newestFirst.next();
                if ((reference.isEmpty() || reference.equals(entry.reference()))
                        && !excludedClients.contains(entry.client())) {
                    chosen.add(entry);
                }
            }
        }
        JsonArray items = new JsonArray();
        for (Entry entry : chosen) {
            JsonObject item = new JsonObject();
            item.addProperty("at_ms", entry.atEpochMs());
            item.addProperty("client", entry.client());
            item.addProperty("reference", entry.reference());
            item.addProperty("command", entry.command());
            JsonArray args = new JsonArray();
            entry.args().forEach(args::add);
            item.add("args", args);
            item.addProperty("exit_code", entry.exitCode());
            item.addProperty("success", entry.success());
            item.addProperty("latency_ms", Math.round(entry.latencyMs() * 1000) / 1000.0);
            items.add(item);
        }
        JsonObject view = new JsonObject();
        view.add("directives", items);
        return view;
    }
}
