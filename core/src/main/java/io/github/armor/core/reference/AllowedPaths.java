// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Optional;

/**
 * The confinement rule (node parameter allowed_dirs): a file the core reads or writes for a
 * client (LOAD, SAVE, LOG FILE, an owl:imports, a catalog entry) must lie inside an allowed
 * directory once every symbolic link on its way is followed, dangling links included. The
 * path returned is that final target, so the file opened is the file checked.
 */
public final class AllowedPaths {
    // As the kernel: a chain of more links than this is a loop.
    private static final int MAX_LINKS = 40;

    private final List<Path> roots;

    public AllowedPaths(List<Path> roots) {
        this.roots = List.copyOf(roots);
    }

    /** A path a client sent, absolute, confined; 213 when it is relative or leads outside. */
    public Path check(String clientPath) {
        if (clientPath == null || clientPath.isBlank()) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "empty path");
        }
        Path target;
        try {
            Path given = Path.of(clientPath.trim());
            if (!given.isAbsolute()) {
                // Relative to what? The node's folder is not the caller's: the clients make paths absolute
                // against the caller's (docs/commands.md#paths), and a raw directive must do the same.
                throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "relative path '" + clientPath + "' refused:"
                        + " send an absolute path (the node would have taken it as " + given.toAbsolutePath()
                        + ", in its own working directory, not the caller's)");
            }
            target = inside(given).orElse(null);
        } catch (ArmorException e) {
            throw e;
        } catch (IOException | RuntimeException e) {
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "path '" + clientPath + "' cannot be used: " + e);
        }
        if (target == null) {
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "path '" + clientPath + "' " + outsideText());
        }
        return target;
    }

    /** The final target of a path when it lies inside an allowed directory, else empty. */
    public Optional<Path> inside(Path path) throws IOException {
        Path target = finalTarget(path.toAbsolutePath());
        for (Path root : roots) {
            if (target.startsWith(finalTarget(root.toAbsolutePath()))) {
                return Optional.of(target);
            }
        }
        return Optional.empty();
    }

    /** The end of a refusal: where paths must lie and which parameter says so. */
    public String outsideText() {
        return "is outside the allowed directories " + roots + " (node parameter allowed_dirs)";
    }

    /**
     * Where a path leads: each component in turn, every symbolic link replaced by its target
     * (also one whose target does not exist yet), and ".." applied after links, as the kernel
     * does when it opens the path. Components that do not exist are kept as they are.
     */
    static Path finalTarget(Path absolute) throws IOException {
        Deque<String> remaining = new ArrayDeque<>();
        absolute.forEach(part -> remaining.add(part.toString()));
        Path resolved = absolute.getRoot();
        int links = 0;
        while (!remaining.isEmpty()) {
            String part = remaining.pollFirst();
            if (part.equals(".") || part.isEmpty()) {
                continue;
            }
            if (part.equals("..")) {
                resolved = resolved.getParent() == null ? resolved : resolved.getParent();
                continue;
            }
            Path next = resolved.resolve(part);
            if (!Files.isSymbolicLink(next)) {
                resolved = next;
                continue;
            }
            if (++links > MAX_LINKS) {
                throw new IOException("more than " + MAX_LINKS + " symbolic links on the way to " + absolute);
            }
            Path link = Files.readSymbolicLink(next);
            Deque<String> linkParts = new ArrayDeque<>();
            link.forEach(p -> linkParts.add(p.toString()));
            while (!linkParts.isEmpty()) {
                remaining.addFirst(linkParts.pollLast());
            }
            if (link.isAbsolute()) {
                resolved = link.getRoot();
            }
        }
        return resolved;
    }
}
