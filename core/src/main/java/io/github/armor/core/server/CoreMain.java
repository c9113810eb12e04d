// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.command.Catalogue;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Setting;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.reference.ReasonerRegistry;
import io.github.armor.core.reference.WritablePaths;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * Starts the core process: {@code java -jar armor-core.jar SOCKET_PATH CONFIG_JSON}. Restores
 * the references kept in the state directory, then prints one "ready" line on stdout once the
 * socket accepts connections, and exits when stdin closes, so the core never outlives the node
 * that started it. {@code java -jar armor-core.jar --catalogue [CONFIG_JSON]} prints the
 * catalogue (commands, exit codes, settings; with the commands of plugin_dirs' jars) and exits.
 */
public final class CoreMain {
    /** Exit status for a command line or configuration the core refuses. */
    static final int USAGE = 2;

    private CoreMain() {}

    /** The line on stdout that tells the node why the core could not start (instead of the ready line). */
    static final String CANNOT_START = "ARMOR core cannot start: ";

    public static void main(String[] args) throws IOException {
        ProcessLog.install();
        boolean catalogue = args.length >= 1 && args[0].equals("--catalogue");
        if (!(catalogue && args.length <= 2) && args.length != 2) {
            System.err.println("usage: java -jar armor-core.jar SOCKET_PATH CONFIG_JSON\n"
                    + "       java -jar armor-core.jar --catalogue [CONFIG_JSON]");
            System.exit(USAGE);
        }
        Map<Setting, Object> settings;
        CommandTable commands;
        try {
            settings = SettingsJson.parse(args.length == 2 ? JsonParser.parseString(args[1]).getAsJsonObject()
                    : new JsonObject());
            @SuppressWarnings("unchecked")
            ClassLoader plugins = Plugins.classLoader((List<String>) settings.get(Setting.PLUGIN_DIRS));
            ReasonerRegistry.useClassLoader(plugins);
            commands = CommandTable.load(plugins);
        } catch (RuntimeException e) {
            // The node reports this line as the reason the core did not start.
            System.out.println(CANNOT_START + e.getMessage());
            System.out.flush();
            System.exit(USAGE);
            return;
        }
        if (catalogue) {
            System.out.println(Catalogue.text(commands));
            return;
        }
        CoreConfig config = CoreConfig.fromSettings(settings);
        List<String> unwritable = WritablePaths.of(config).prepare();
        if (!unwritable.isEmpty()) {
            System.out.println(CANNOT_START + String.join("; ", unwritable));
            System.out.flush();
            System.exit(USAGE);
        }
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
        ArmorCore core = new ArmorCore(config, commands);
        try {
            core.restoreState();
        } catch (RuntimeException e) {
            // One line the node reports as the reason; the trace only for those who asked for DEBUG.
            System.out.println(CANNOT_START + e.getMessage());
            System.out.flush();
            org.slf4j.LoggerFactory.getLogger(CoreMain.class).debug("start failed", e);
            System.exit(3);
        }
        new CoreServer(core, Catalogue.json(commands)).serve(Path.of(args[0]), () -> {
            System.out.println("ARMOR core ready on " + args[0]);
            System.out.flush();
        });
    }
}
