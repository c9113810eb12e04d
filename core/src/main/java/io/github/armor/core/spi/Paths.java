// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;

/** The core's confinement of the files a client names, for a plugin's reads and writes. */
public interface Paths {
    /** The file a client names to read, inside {@code allowed_dirs}; otherwise refused (213). */
    Path readable(String clientPath);

    /** The file a client names to write, inside {@code write_dirs}; otherwise refused (213). */
    Path writable(String clientPath);

    /** Writes a checked target atomically (a temporary file renamed over it). */
    void write(Path checked, Content content);

    /** What a writer writes. */
    @FunctionalInterface
    interface Content {
        void writeTo(OutputStream out) throws IOException;
    }
}
