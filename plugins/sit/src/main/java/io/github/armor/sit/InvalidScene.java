// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

/** A scene the logic refuses, having changed nothing; the kind decides the exit code. */
public final class InvalidScene extends RuntimeException {
    /** What is wrong with it. */
    public enum Kind {
        /** An unknown type, a feature list of the wrong length, no element, a malformed argument. */
        SHAPE,
        /** A number that is not a finite number, or out of its range. */
        VALUE,
        /** More elements than a scene may have. */
        TOO_LARGE,
        /** The reference is inconsistent: no class membership means anything. */
        INCONSISTENT
    }

    private final Kind kind;

    public InvalidScene(Kind kind, String message) {
        super(message);
        this.kind = kind;
    }

    public Kind kind() {
        return kind;
    }
}
