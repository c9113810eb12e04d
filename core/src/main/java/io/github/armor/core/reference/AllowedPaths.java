// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.ExitCode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Optional;

/**
 * The read rule (node parameter allowed_dirs): a file the core reads for a client (LOAD, an
 * owl:imports, a catalog entry, a PDDL mapping) must lie inside an allowed directory once every
 * symbolic link on its way is followed, dangling links included; never in the state directory,
 * and never in a hidden file or folder below the allowed directory it lies in (an allowed
 * directory that is itself hidden, or inside a hidden one, is the operator's explicit choice).
 * The path returned is that final target, so the file opened is the file checked. What may be
 * written is {@link WritablePaths}' rule.
 */
public final class AllowedPaths {
    // As the kernel: a chain of more links than this is a loop.
    private static final int MAX_LINKS = 40;

    private final List<Path> roots;
    private final List<Path> unreachable;

    public AllowedPaths(List<Path> roots) {
        this(roots, List.of());
    }

    /** Reads inside {@code roots}, never inside {@code unreachable} (the state directory). */
    public AllowedPaths(List<Path> roots, List<Path> unreachable) {
        this.roots = List.copyOf(roots);
        this.unreachable = List.copyOf(unreachable);
    }

    /** What a client may make the core read under {@code config}: allowed_dirs, never state_dir. */
    public static AllowedPaths forReading(CoreConfig config) {
        Path stateDir = config.durability().stateDir();
        return new AllowedPaths(config.allowedDirs(), stateDir == null ? List.of() : List.of(stateDir));
    }

    /** A path a client sent, absolute and confined; 213 when it is relative or may not be read. */
    public Path check(String clientPath) {
        Path target = finalTarget(clientPath);
        String refusal;
        try {
            refusal = refusal(target);
        } catch (IOException | RuntimeException e) {
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "path '" + clientPath + "' cannot be used: " + e);
        }
        if (refusal != null) {
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "path '" + clientPath + "' " + refusal);
        }
        return target;
    }

    /** The final target of a path when it may be read, else empty. */
    public Optional<Path> inside(Path path) throws IOException {
        Path target = finalTarget(path.toAbsolutePath());
        return refusal(target) == null ? Optional.of(target) : Optional.empty();
    }

    /** Why a final target may not be read ("is outside ..."), or null when it may. */
    public String refusal(Path target) throws IOException {
        for (Path dir : unreachable) {
            if (target.startsWith(finalTarget(dir.toAbsolutePath()))) {
                return "lies in the state directory " + dir + ", which no directive reads or writes";
            }
        }
        String hidden = null;
        for (Path root : roots) {
            Path rootTarget = finalTarget(root.toAbsolutePath());
            if (target.startsWith(rootTarget)) {
                Optional<String> dotted = hiddenPart(rootTarget.relativize(target));
                if (dotted.isEmpty()) {
                    return null;
                }
                hidden = dotted.get();
            }
        }
        return hidden != null ? "is a hidden file or folder ('" + hidden + "'), read only where allowed_dirs"
                + " names a folder inside it" : outsideText();
    }

    /** The end of a refusal: where paths must lie and which parameter says so. */
    public String outsideText() {
        return "is outside the allowed directories " + roots + " (node parameter allowed_dirs)";
    }

    /** The first component of {@code path} that names a hidden file or folder (".ssh"), if any. */
    static Optional<String> hiddenPart(Path path) {
        for (Path part : path) {
            String name = part.toString();
            if (name.startsWith(".") && !name.equals(".") && !name.equals("..")) {
                return Optional.of(name);
            }
        }
        return Optional.empty();
    }

    /** An absolute path a client sent, as {@link #finalTarget(Path)} resolves it; 213 when it cannot be. */
    static Path finalTarget(String clientPath) {
        if (clientPath == null || clientPath.isBlank()) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "empty path");
        }
        Path given;
        try {
            given = Path.of(clientPath.trim());
        } catch (RuntimeException e) {
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "path '" + clientPath + "' cannot be used: " + e);
        }
        if (!given.isAbsolute()) {
            // Relative to what? The node's folder is not the caller's: the clients make paths absolute
            // against the caller's (docs/commands.md#paths), and a raw directive must do the same.
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "relative path '" + clientPath + "' refused:"
                    + " send an absolute path (the node would have taken it as " + given.toAbsolutePath()
                    + ", in its own working directory, not the caller's)");
        }
        try {
            return finalTarget(given);
        } catch (IOException | RuntimeException e) {
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "path '" + clientPath + "' cannot be used: " + e);
        }
    }

    /** The final targets of directories, for comparing final targets with. */
    static List<Path> finalTargets(List<Path> directories) throws IOException {
        List<Path> targets = new ArrayList<>();
        for (Path directory : directories) {
            targets.add(finalTarget(directory.toAbsolutePath()));
        }
        return targets;
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
