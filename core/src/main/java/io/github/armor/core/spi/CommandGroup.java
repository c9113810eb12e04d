// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

/**
 * A plugin's group of commands. A public class with a public no-argument constructor, named in
 * a {@code META-INF/services/io.github.armor.core.spi.CommandGroup} file of its jar; a jar in
 * one of the core's plugin directories ({@code plugin_dirs}) adds its groups, and their commands
 * appear in the catalogue beside the built-in ones, with the jar's name as their origin:
 * <pre>{@code
 * public final class HelloCommands implements CommandGroup {
 *     public void register(CommandTable table) {
 *         table.command("QUERY HELLO").args("ind").summary("greets an individual")
 *                 .query(c -> c.ok(List.of("hello " + c.arg(0))));
 *     }
 * }
 * }</pre>
 * The core runs a plugin's command as a built-in one of the same kind (size limits, argument
 * count, lock, mount check, journal, rollback), on a thread of its own within
 * {@code plugin_timeout_ms}: a long loop should check {@link Thread#interrupted()}. A group that
 * throws, or registers a key another group has, is left out whole with an ERROR line naming its
 * jar; the core starts without it.
 */
public interface CommandGroup {
    /** Registers this group's commands; called once for every table the core builds. */
    void register(CommandTable table);
}
