// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Starts the core process: {@code java -jar armor-core.jar SOCKET_PATH CONFIG_JSON}. Restores
 * the references kept in the state directory, then prints one "ready" line on stdout once the
 * socket accepts connections, and exits when stdin closes, so the core never outlives the node
 * that started it.
 */
public final class CoreMain {
    private CoreMain() {}

    /** The line on stdout that tells the node why the core could not start (instead of the ready line). */
    static final String CANNOT_START = "ARMOR core cannot start: ";

    public static void main(String[] args) throws IOException {
        ProcessLog.install();
        if (args.length != 2) {
            System.err.println("usage: java -jar armor-core.jar SOCKET_PATH CONFIG_JSON");
            System.exit(2);
        }
        CoreConfig config = config(JsonParser.parseString(args[1]).getAsJsonObject());
        NetworkGuard.install(config);
        Thread watchParent = new Thread(() -> {
            try {
                while (System.in.read() >= 0) {
                    // the node never writes; reading only detects that it has gone
                }
            } catch (IOException e) {
                // treated as the node having gone
            }
            Runtime.getRuntime().halt(0);
        }, "armor-parent-watch");
        watchParent.setDaemon(true);
        watchParent.start();
        ArmorCore core = new ArmorCore(config);
        try {
            core.restoreState();
        } catch (RuntimeException e) {
            // One line the node reports as the reason; the trace only for those who asked for DEBUG.
            System.out.println(CANNOT_START + e.getMessage());
            System.out.flush();
            org.slf4j.LoggerFactory.getLogger(CoreMain.class).debug("start failed", e);
            System.exit(3);
        }
        new CoreServer(core).serve(Path.of(args[0]), () -> {
            System.out.println("ARMOR core ready on " + args[0]);
            System.out.flush();
        });
    }

    static CoreConfig config(JsonObject json) {
        List<Path> dirs = new ArrayList<>();
        JsonArray allowed = json.has("allowed_dirs") ? json.getAsJsonArray("allowed_dirs") : new JsonArray();
        allowed.forEach(d -> dirs.add(Path.of(d.getAsString())));
        return new CoreConfig(
                !json.has("full_entity_iri") || json.get("full_entity_iri").getAsBoolean(),
                json.has("default_reasoner") ? json.get("default_reasoner").getAsString() : "PELLET",
                dirs,
                json.has("web_loading") && json.get("web_loading").getAsBoolean(),
                json.has("lock_wait_ms") ? json.get("lock_wait_ms").getAsLong() : 30_000,
                json.has("reasoner_timeout_ms") ? json.get("reasoner_timeout_ms").getAsLong() : 0,
                json.has("mount_lease_s") ? json.get("mount_lease_s").getAsLong() : 0,
                durability(json),
                new CoreConfig.Safeguards(
                        json.has("sparql_timeout_ms") ? json.get("sparql_timeout_ms").getAsLong() : 30_000,
                        json.has("sparql_federated") && json.get("sparql_federated").getAsBoolean(),
                        json.has("ignore_missing_imports") && json.get("ignore_missing_imports").getAsBoolean(),
                        json.has("strict_names") && json.get("strict_names").getAsBoolean()));
    }

    private static CoreConfig.Durability durability(JsonObject json) {
        String stateDir = json.has("state_dir") ? json.get("state_dir").getAsString() : "";
        if (stateDir.isBlank()) {
            return CoreConfig.Durability.NONE;
        }
        return new CoreConfig.Durability(Path.of(stateDir),
                !json.has("restore_state") || json.get("restore_state").getAsBoolean(),
                !json.has("journal_fsync") || json.get("journal_fsync").getAsBoolean(),
                json.has("checkpoint_every_changes") ? json.get("checkpoint_every_changes").getAsInt() : 1000,
                json.has("checkpoint_every_s") ? json.get("checkpoint_every_s").getAsLong() : 60);
    }
}
