// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

/**
 * A group of commands the core answers: the one way commands come to exist.
 *
 * <p>Groups are found with {@link java.util.ServiceLoader}: a class implementing this interface,
 * public with a public no-argument constructor, named in a
 * {@code META-INF/services/io.github.armor.core.command.CommandGroup} file of its jar. The
 * built-in groups (references, manipulations, queries) are registered that way in the core's
 * own jar; a plugin jar placed in one of the core's plugin directories ({@code plugin_dirs})
 * adds its groups the same way, and its commands appear in the catalogue ({@code --catalogue},
 * the {@code catalogue} socket operation, GET CATALOGUE) beside the built-in ones, with the
 * jar's name as their origin.
 *
 * <p>A group registers each command once, with its words, argument names, a one-line summary
 * and its {@link CommandKind}, through {@link CommandTable#command(String)}:
 * <pre>{@code
 * public final class HelloCommands implements CommandGroup {
 *     public void register(CommandTable table) {
 *         table.command("QUERY HELLO").args("ind").summary("greets an individual")
 *                 .query(c -> c.ok(List.of("hello " + c.arg(0))));
 *     }
 * }
 * }</pre>
 * The core runs every command the same way whatever group it came from: size limits, the
 * argument count, the reference lock, the mount check, journaling and rollback all follow from
 * the kind. A plugin's command also runs on a thread of its own within {@code plugin_timeout_ms}
 * (see {@code PluginGuard}): a long loop should check {@link Thread#interrupted()}, and a change
 * goes through {@link CommandContext#change} so that a failure or a list's rollback undoes it.
 * A key registered twice among the built-in groups stops the core at start; a plugin's group
 * that registers a taken key, or throws, is left out with an ERROR line naming its jar.
 */
public interface CommandGroup {
    /** Registers this group's commands; called once for every table the core builds. */
    void register(CommandTable table);
}
