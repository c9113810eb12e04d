// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

/**
 * A group of commands the core answers: the one way commands come to exist.
 *
 * <p>Groups are found with {@link java.util.ServiceLoader}: a class implementing this interface,
 * public with a public no-argument constructor, named in a
 * {@code META-INF/services/io.github.armor.core.command.CommandGroup} file of its jar. The
 * built-in groups (references, manipulations, queries) are registered that way in the core's
 * own jar; a plugin jar placed in the core's plugin directory ({@code plugin_dir}) adds its
 * groups the same way, and its commands appear in the catalogue ({@code --catalogue}, the
 * {@code catalogue} socket operation) beside the built-in ones.
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
 * the kind. A key registered twice stops the core at start.
 */
public interface CommandGroup {
    /** Registers this group's commands; called once for every table the core builds. */
    void register(CommandTable table);
}
