// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

/** What the client method of a command's face ({@link CommandBuilder#face}) makes of its answer. */
public enum FaceAnswer {
    /** Nothing: a change, whose answer is only success and consistency. */
    NONE,
    /** The queried objects as entity names (short names, or IRIs on request). */
    ENTITIES,
    /** The queried objects as typed values: literals converted, entities named. */
    VALUES,
    /** The queried objects as Manchester text, its IRIs written as short names. */
    EXPRESSIONS
}
