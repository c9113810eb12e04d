// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

/** Where a {@link CommandGroup} registers its commands. */
public interface CommandTable {
    /** Starts registering the command written as "COMMAND [PRIMARY [SECONDARY]]". */
    CommandBuilder command(String words);
}
