// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * The class loader of the plugin directories: every jar in them, on top of the core's own
 * class path. {@code java -jar} ignores {@code -cp}, so this is how command groups and
 * reasoner factories from other jars reach the core.
 */
final class Plugins {
    private Plugins() {}

    /**
     * The core's own class loader when no directory is named, else one over their jars: the
     * directories in the order given, the jars of each by name (a plugin's libraries may lie
     * beside it).
     *
     * @throws IllegalArgumentException naming an entry that is not a directory
     */
    static ClassLoader classLoader(List<String> directories) {
        ClassLoader own = Plugins.class.getClassLoader();
        List<URL> urls = new ArrayList<>();
        for (String directory : directories) {
            if (directory == null || directory.isBlank()) {
                continue;
            }
            Path dir = Path.of(directory.trim());
            if (!Files.isDirectory(dir)) {
                throw new IllegalArgumentException("plugin_dirs entry '" + directory + "' is not a directory");
            }
            try (Stream<Path> entries = Files.list(dir)) {
                for (Path jar : entries.filter(p -> p.getFileName().toString().endsWith(".jar")).sorted().toList()) {
                    urls.add(jar.toUri().toURL());
                }
            } catch (MalformedURLException e) {
                throw new IllegalArgumentException("plugin_dirs entry '" + directory + "': " + e.getMessage(), e);
            } catch (IOException e) {
                throw new UncheckedIOException("plugin_dirs entry '" + directory + "' could not be listed", e);
            }
        }
        return urls.isEmpty() ? own : new URLClassLoader("armor-plugins", urls.toArray(URL[]::new), own);
    }
}
