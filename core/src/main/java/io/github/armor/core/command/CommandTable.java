// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.command.CommandSpec.Handler;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.ServiceLoader;
import java.util.TreeMap;

/** All commands the core answers, by dispatch key ({@code "QUERY IND CLASS"}, {@code "DROP - -"}). */
public final class CommandTable {
    private final Map<String, CommandSpec> byKey = new TreeMap<>();
    private final Map<String, CommandSpec> commands = new LinkedHashMap<>();

    /** The table of every {@link CommandGroup} the class loader finds: the built-in ones, then plugins'. */
    public static CommandTable load(ClassLoader loader) {
        CommandTable table = new CommandTable();
        for (CommandGroup group : ServiceLoader.load(CommandGroup.class, loader)) {
            group.register(table);
        }
        return table;
    }

    /** The table of the core's own jar (and its class path). */
    public static CommandTable standard() {
        return load(CommandTable.class.getClassLoader());
    }

    public Optional<CommandSpec> find(String key) {
        return Optional.ofNullable(byKey.get(key));
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
            CommandSpec spec = new CommandSpec(key, aliases, kind, required, optional, variadic,
                    emptySurplusIgnored, summary, handler);
            List<String> keys = new ArrayList<>(aliases);
            keys.add(0, key);
            for (String name : keys) {
                if (byKey.putIfAbsent(name, spec) != null) {
                    throw new IllegalStateException("command registered twice: " + name);
                }
            }
            commands.put(key, spec);
        }
    }
}
