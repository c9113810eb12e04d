// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/**
 * The class loader of the plugin directory: every jar in it, on top of the core's own class
 * path. {@code java -jar} ignores {@code -cp}, so this is how command groups and reasoner
 * factories from other jars reach the core.
 */
final class Plugins {
    private Plugins() {}

    /** The core's own class loader when {@code directory} is blank, else one over its jars. */
    static ClassLoader classLoader(String directory) {
        ClassLoader own = Plugins.class.getClassLoader();
        if (directory == null || directory.isBlank()) {
            return own;
        }
        Path dir = Path.of(directory);
        if (!Files.isDirectory(dir)) {
            throw new IllegalArgumentException("plugin_dir '" + directory + "' is not a directory");
        }
        try (Stream<Path> entries = Files.list(dir)) {
            List<Path> jars = entries.filter(p -> p.getFileName().toString().endsWith(".jar")).sorted().toList();
            URL[] urls = new URL[jars.size()];
            for (int i = 0; i < urls.length; i++) {
                urls[i] = jars.get(i).toUri().toURL();
            }
            return new URLClassLoader("armor-plugins", urls, own);
        } catch (MalformedURLException e) {
            throw new IllegalArgumentException("plugin_dir '" + directory + "': " + e.getMessage(), e);
        } catch (IOException e) {
            throw new UncheckedIOException("plugin_dir '" + directory + "' could not be listed", e);
        }
    }
}
