// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.command.CommandSpec.Handler;
import io.github.armor.core.command.CommandSpec.Target;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

/** All commands the core answers, by dispatch key ({@code "QUERY IND CLASS"}, {@code "DROP - -"}). */
public final class CommandTable {
    private final Map<String, CommandSpec> specs = new TreeMap<>();

    /** The table with every command of the contract registered. */
    public static CommandTable standard() {
        CommandTable table = new CommandTable();
        ReferenceCommands.register(table);
        Manipulations.register(table);
        Queries.register(table);
        return table;
    }

    public Optional<CommandSpec> find(String key) {
        return Optional.ofNullable(specs.get(key));
    }

    public Collection<CommandSpec> all() {
        return specs.values();
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

    /** Collects one command's shape, then registers it with its handler. */
    public final class Builder {
        private final String key;
        private final List<String> aliases = new ArrayList<>();
        private List<String> required = List.of();
        private List<String> optional = List.of();
        private boolean variadic;

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

        public Builder variadic() {
            variadic = true;
            return this;
        }

        /** A read: never mount-checked. */
        public void query(Handler handler) {
            register(Target.EXISTING, false, handler);
        }

        /** A change: refused with 102 while another client holds the mount. */
        public void manipulation(Handler handler) {
            register(Target.EXISTING, true, handler);
        }

        /** A utility on an existing reference (SAVE, DROP, MOUNT...): no mount check. */
        public void onReference(Handler handler) {
            register(Target.EXISTING, false, handler);
        }

        /** Creates the reference the directive names (LOAD, CREATE). */
        public void creating(Handler handler) {
            register(Target.NEW, false, handler);
        }

        /** Needs no reference (GET ALL REFS, LOG). */
        public void global(Handler handler) {
            register(Target.NONE, false, handler);
        }

        private void register(Target target, boolean mountChecked, Handler handler) {
            for (String name : concat(key, aliases)) {
                CommandSpec previous = specs.put(name, new CommandSpec(name, target, mountChecked, required,
                        optional, variadic, handler));
                if (previous != null) {
                    throw new IllegalStateException("command registered twice: " + name);
                }
            }
        }

        private List<String> concat(String first, List<String> rest) {
            List<String> all = new ArrayList<>(rest);
            all.add(0, first);
            return all;
        }
    }
}
