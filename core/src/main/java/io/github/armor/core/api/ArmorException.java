// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

/** A directive failed in a way the client must hear about: the code and a description naming the cause. */
public class ArmorException extends RuntimeException {
    private final ExitCode exitCode;
    private final boolean timeout;

    public ArmorException(ExitCode exitCode, String description) {
        this(exitCode, description, null);
    }

    public ArmorException(ExitCode exitCode, String description, Throwable cause) {
        super(description, cause);
        this.exitCode = exitCode;
        this.timeout = exitCode == ExitCode.TIMEOUT;
    }

    public ExitCode exitCode() {
        return exitCode;
    }

    public boolean isTimeout() {
        return timeout;
    }
}
