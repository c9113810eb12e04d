// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.command.CommandSpec.Handler;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.TreeMap;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** All commands the core answers, by dispatch key ({@code "QUERY IND CLASS"}, {@code "DROP - -"}). */
public final class CommandTable {
    /** The origin of the commands of the core's own jar. */
    public static final String BUILT_IN = "core";

    private static final Logger LOG = LoggerFactory.getLogger(CommandTable.class);
    // A broken services file can make ServiceLoader fail on every step: give up after this many.
    private static final int MAX_LOAD_ERRORS = 100;

    private final Map<String, CommandSpec> byKey = new TreeMap<>();
    private final Map<String, CommandSpec> commands = new LinkedHashMap<>();
    private final Map<String, Face> faces = new TreeMap<>();
    private final String origin;

    private CommandTable(String origin) {
        this.origin = origin;
    }

    /**
     * The table of every {@link CommandGroup} the class loader finds: the built-in ones, then
     * plugins'. A plugin's group that cannot be loaded or registered, or that registers a key
     * another group has, is left out whole (its jar named in an ERROR line); the core starts
     * without it. Plugins' commands run under {@link PluginGuard}.
     */
    public static CommandTable load(ClassLoader loader) {
        CommandTable table = new CommandTable(BUILT_IN);
        // The core's own groups (and plugins written before the SPI), then plugins' SPI groups.
        for (CommandGroup group : groups(CommandGroup.class, loader)) {
            table.add(group, group::register);
        }
        for (io.github.armor.core.spi.CommandGroup group : groups(io.github.armor.core.spi.CommandGroup.class,
                loader)) {
            table.add(group, staged -> group.register(new PluginTable(staged)));
        }
        return table;
    }

    /** The groups of one service type the class loader finds; one that cannot be loaded is left out. */
    private static <G> List<G> groups(Class<G> type, ClassLoader loader) {
        List<G> found = new ArrayList<>();
        Iterator<G> groups = ServiceLoader.load(type, loader).iterator();
        int errors = 0;
        while (errors < MAX_LOAD_ERRORS) {
            try {
                if (!groups.hasNext()) {
                    break;
                }
                found.add(groups.next());
            } catch (ServiceConfigurationError e) {
                errors++;
                LOG.error("a plugin's command group could not be loaded and is left out: {}", e.getMessage());
            }
        }
        return found;
    }

    private void add(Object group, Consumer<CommandTable> register) {
        if (sameSource(group.getClass(), CommandTable.class)) {
            register.accept(this);
        } else {
            addPlugin(group, register, jarOf(group.getClass()));
        }
    }

    /** The table of the core's own jar (and its class path). */
    public static CommandTable standard() {
        return load(CommandTable.class.getClassLoader());
    }

    private void addPlugin(Object group, Consumer<CommandTable> register, String jar) {
        CommandTable staged = new CommandTable(jar);
        try {
            register.accept(staged);
        } catch (VirtualMachineError e) {
            throw e;
        } catch (RuntimeException | Error e) {
            LOG.error("command group {} of plugin {} failed to register and is left out: {}",
                    group.getClass().getName(), jar, e.toString());
            return;
        }
        for (String key : staged.byKey.keySet()) {
            CommandSpec taken = byKey.get(key);
            if (taken != null) {
                LOG.error("command group {} of plugin {} is left out: it registers {}, which {} already has",
                        group.getClass().getName(), jar, key, taken.origin());
                return;
            }
        }
        byKey.putAll(staged.byKey);
        commands.putAll(staged.commands);
        faces.putAll(staged.faces);
        LOG.info("plugin {}: command group {} adds {}", jar, group.getClass().getName(),
                String.join(", ", staged.commands.keySet()));
    }

    /** Where a class was loaded from (a jar, a class directory), or null. */
    private static URL location(Class<?> type) {
        CodeSource source = type.getProtectionDomain().getCodeSource();
        return source == null ? null : source.getLocation();
    }

    private static boolean sameSource(Class<?> one, Class<?> other) {
        URL first = location(one);
        URL second = location(other);
        // Compared as text: URL.equals would resolve host names.
        return first == null ? second == null
                : second != null && first.toExternalForm().equals(second.toExternalForm());
    }

    /** The file name of the jar a plugin's class was loaded from. */
    private static String jarOf(Class<?> type) {
        URL location = location(type);
        if (location == null) {
            return type.getName();
        }
        try {
            return Objects.toString(Path.of(location.toURI()).getFileName(), location.toString());
        } catch (URISyntaxException | IllegalArgumentException e) {
            return location.toString();
        }
    }

    public Optional<CommandSpec> find(String key) {
        return Optional.ofNullable(byKey.get(key));
    }

    /** The client method a command was registered with ({@link Builder#face}), if any. */
    public Optional<Face> face(String key) {
        return Optional.ofNullable(faces.get(key));
    }

    /** Each command once (aliases inside it), in registration order: what the catalogue lists. */
    public List<CommandSpec> catalogue() {
        return List.copyOf(commands.values());
    }

    /** Starts registering the command written as "COMMAND [PRIMARY [SECONDARY]]". */
    public Builder command(String words) {
        return new Builder(normalise(words));
    }

    private static String normalise(String words) {
        List<String> parts = new ArrayList<>(List.of(words.trim().split("\\s+")));
        while (parts.size() < 3) {
            parts.add("-");
        }
        return String.join(" ", parts);
    }

    /** Collects one command's shape, then registers it with its handler under the kind it names. */
    public final class Builder {
        private final String key;
        private final List<String> aliases = new ArrayList<>();
        private List<String> required = List.of();
        private List<String> optional = List.of();
        private boolean variadic;
        private boolean emptySurplusIgnored;
        private String summary = "";
        private Face face;
        private final List<AnswerSource> whileBusy = new ArrayList<>();
        private String subscribedAs = "";

        private Builder(String key) {
            this.key = key;
        }

        public Builder alias(String words) {
            aliases.add(normalise(words));
            return this;
        }

        public Builder args(String... names) {
            required = List.of(names);
            return this;
        }

        public Builder optional(String... names) {
            optional = List.of(names);
            return this;
        }

        /** The last required argument may be repeated. */
        public Builder variadic() {
            variadic = true;
            return this;
        }

        /**
         * A command of ROS 1 ARMOR, which read only the arguments it named: empty strings after
         * them (old clients' dummies, {@code REASON ['']}) are accepted and ignored here too;
         * other surplus arguments stay an error (207).
         */
        public Builder emptySurplusIgnored() {
            emptySurplusIgnored = true;
            return this;
        }

        /** What the command does, in one line (the catalogue, the CLI and the docs show it). */
        public Builder summary(String text) {
            summary = text;
            return this;
        }

        /**
         * The method the Python and C++ clients get for it (generated by {@code make catalogue}):
         * its name, what it answers, and one parameter per argument, {@code "count:int"} for a
         * number (the last repeats when the command is variadic). Optional: without it the
         * command is reached through {@code call}, or by a method written by hand.
         */
        public Builder face(String method, Face.Answer answer, String... parameters) {
            face = Face.of(method, answer, List.of(parameters));
            return this;
        }

        /**
         * A way to answer it while another directive holds the reference (from the state its
         * reasoner last published), tried before waiting; sources are asked in the order given.
         */
        public Builder whileBusy(AnswerSource source) {
            whileBusy.add(source);
            return this;
        }

        /** A subscription to it asks the command written {@code words} instead (same arguments). */
        public Builder subscribedAs(String words) {
            subscribedAs = normalise(words);
            return this;
        }

        /** A read: never mount-checked. */
        public void query(Handler handler) {
            register(CommandKind.QUERY, handler);
        }

        /** A change: refused with 102 while another client holds the mount. */
        public void manipulation(Handler handler) {
            register(CommandKind.MANIPULATION, handler);
        }

        /** A utility on an existing reference that changes nothing (SAVE). */
        public void onReference(Handler handler) {
            register(CommandKind.REFERENCE, handler);
        }

        /** Takes or releases the reference's mount. */
        public void mounting(Handler handler) {
            register(CommandKind.MOUNTING, handler);
        }

        /** Unloads the reference. */
        public void dropping(Handler handler) {
            register(CommandKind.DROPPING, handler);
        }

        /** Creates the reference the directive names (LOAD, CREATE). */
        public void creating(Handler handler) {
            register(CommandKind.CREATING, handler);
        }

        /** Needs no reference (GET ALL REFS, LOG). */
        public void global(Handler handler) {
            register(CommandKind.GLOBAL, handler);
        }

        private void register(CommandKind kind, Handler handler) {
            if (summary.isBlank()) {
                throw new IllegalStateException("command " + key + " has no summary");
            }
            if (face != null) {
                face.checkFits(key, kind, required.size(), variadic);
            }
            boolean plugin = !origin.equals(BUILT_IN);
            CommandSpec spec = new CommandSpec(key, aliases, kind, required, optional, variadic,
                    emptySurplusIgnored, summary, origin,
                    plugin ? PluginGuard.guard(key, origin, handler) : handler,
                    plugin ? whileBusy.stream().map(source -> PluginGuard.guard(key, origin, source)).toList()
                            : whileBusy, subscribedAs);
            List<String> keys = new ArrayList<>(aliases);
            keys.add(0, key);
            for (String name : keys) {
                if (byKey.putIfAbsent(name, spec) != null) {
                    throw new IllegalStateException("command registered twice: " + name);
                }
            }
            commands.put(key, spec);
            if (face != null) {
                faces.put(key, face);
            }
        }
    }
}
