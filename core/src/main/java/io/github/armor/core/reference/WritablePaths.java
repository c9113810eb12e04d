// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.ExitCode;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.channels.SeekableByteChannel;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.OpenOption;
import java.nio.file.Path;
import java.nio.file.SecureDirectoryStream;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributeView;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.UUID;

/**
 * The write rule (node parameter write_dirs): SAVE, SAVE INFERENCE, SAVE PDDL PROBLEM and LOG FILE
 * write only inside a write directory, judged where the path finally leads (links followed as
 * {@link AllowedPaths} follows them), and never, whatever the settings say:
 * <ul>
 * <li>a hidden file or folder (a path component starting with '.': dotfiles, ~/.ssh, a .venv),</li>
 * <li>a file directly in the home directory, the working directory or a temporary directory
 * (folders inside them may be write directories),</li>
 * <li>anything in the installation (protected_dirs, as the node finds it: its Python environment,
 * packages and checkout; the core's own folder and the Java runtime), plugin_dirs or state_dir.</li>
 * </ul>
 * The write itself walks down from the write directory without following any link (openat with
 * O_NOFOLLOW), so a link swapped in after the check leads nowhere, and makes only the missing
 * folders below the write directory.
 */
public final class WritablePaths {
    private static final Set<PosixFilePermission> DOCUMENT = PosixFilePermissions.fromString("rw-r--r--");
    private static final Set<PosixFilePermission> PRIVATE_FOLDER = PosixFilePermissions.fromString("rwx------");
    private static final Set<PosixFilePermission> PRIVATE_FILE = PosixFilePermissions.fromString("rw-------");
    private static final List<String> TEMPORARY_DIRS = List.of("/tmp", "/var/tmp", "/dev/shm");

    private final List<Path> roots;
    /** Directory -> what it is, for the refusal: never written, nor anything inside. */
    private final Map<Path, String> protectedDirs = new LinkedHashMap<>();
    /** Directory -> what it is: no file directly in it is written. */
    private final Map<Path, String> shared = new LinkedHashMap<>();

    private WritablePaths(List<Path> roots) {
        this.roots = List.copyOf(roots);
    }

    /** The rule the settings make: write_dirs, and what is never written. */
    public static WritablePaths of(CoreConfig config) {
        CoreConfig.Writing writing = config.writing();
        WritablePaths paths = new WritablePaths(writing.writeDirs());
        if (config.durability().stateDir() != null) {
            paths.protectedDirs.put(config.durability().stateDir(), "the state directory (state_dir)");
        }
        writing.pluginDirs().forEach(dir -> paths.protectedDirs.put(dir, "a plugin directory (plugin_dirs)"));
        writing.protectedDirs().forEach(dir -> paths.protectedDirs.put(dir, "the installation (protected_dirs)"));
        coreFolder().ifPresent(dir -> paths.protectedDirs.put(dir, "the core's installation"));
        paths.protectedDirs.put(Path.of(System.getProperty("java.home")), "the Java runtime");
        paths.shared.put(Path.of(System.getProperty("user.home")), "the home directory");
        paths.shared.put(Path.of(System.getProperty("user.dir")), "the working directory");
        paths.shared.put(Path.of(System.getProperty("java.io.tmpdir")), "a temporary directory");
        TEMPORARY_DIRS.forEach(dir -> paths.shared.put(Path.of(dir), "a temporary directory"));
        return paths;
    }

    /** The final target of a path a client sent, when it may be written; 213 saying why not. */
    public Path check(String clientPath) {
        Path target = AllowedPaths.finalTarget(clientPath);
        String refusal;
        try {
            refusal = refusal(target);
        } catch (IOException | RuntimeException e) {
            refusal = "cannot be used: " + e;
        }
        if (refusal != null) {
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "path '" + clientPath + "' " + refusal
                    + "; directives write only inside write_dirs " + roots + " (docs/security.md)");
        }
        return target;
    }

    /** Why a final target may not be written, or null when it may. */
    String refusal(Path target) throws IOException {
        Optional<String> hidden = AllowedPaths.hiddenPart(target);
        if (hidden.isPresent()) {
            return "is a hidden file or folder ('" + hidden.get() + "'), never written";
        }
        for (Map.Entry<Path, String> dir : protectedDirs.entrySet()) {
            if (target.startsWith(AllowedPaths.finalTarget(dir.getKey().toAbsolutePath()))) {
                return "lies in " + dir.getValue() + ", " + dir.getKey() + ", never written";
            }
        }
        for (Map.Entry<Path, String> dir : shared.entrySet()) {
            Path folder = AllowedPaths.finalTarget(dir.getKey().toAbsolutePath());
            if (target.equals(folder) || folder.equals(target.getParent())) {
                return "is directly in " + dir.getValue() + " " + dir.getKey() + ", never written (a folder inside"
                        + " it may be a write directory)";
            }
        }
        return root(target).isPresent() ? null : "is outside the write directories";
    }

    /** The write directory (final target) holding {@code target}, the innermost if several do. */
    private Optional<Path> root(Path target) throws IOException {
        Path found = null;
        for (Path root : AllowedPaths.finalTargets(roots)) {
            if (target.startsWith(root) && !target.equals(root) && (found == null || root.startsWith(found))) {
                found = root;
            }
        }
        return Optional.ofNullable(found);
    }

    /** What a document writer writes. */
    @FunctionalInterface
    public interface Content {
        void writeTo(OutputStream out) throws IOException;
    }

    /**
     * Writes a document to a checked target atomically: a temporary file in the target's folder,
     * forced to disk, then renamed over the target; folders missing below the write directory are
     * made. 213 when a link was swapped in on the way since the check, 209 when writing fails.
     */
    public void write(Path checked, Content content) {
        Path name = checked.getFileName();
        Path temporary = Path.of(".armor-" + UUID.randomUUID() + ".partial");
        try (SecureDirectoryStream<Path> folder = folderOf(checked)) {
            try {
                Set<OpenOption> options = Set.of(StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE,
                        LinkOption.NOFOLLOW_LINKS);
                try (SeekableByteChannel channel = folder.newByteChannel(temporary, options,
                        PosixFilePermissions.asFileAttribute(DOCUMENT))) {
                    OutputStream out = Channels.newOutputStream(channel);
                    content.writeTo(out);
                    out.flush();
                    if (channel instanceof FileChannel file) {
                        file.force(true);
                    }
                }
                // The creation mode is cut by the umask; a saved document is an ordinary one.
                folder.getFileAttributeView(temporary, PosixFileAttributeView.class, LinkOption.NOFOLLOW_LINKS)
                        .setPermissions(DOCUMENT);
                folder.move(temporary, folder, name);
            } catch (IOException | RuntimeException e) {
                deleteQuietly(folder, temporary);
                throw e;
            }
        } catch (IOException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "could not write '" + checked + "': " + e.getMessage(), e);
        }
    }

    /**
     * Opens a checked target for appending log lines (created 0600 if missing), reached as
     * {@link #write} reaches its folder; only a regular file is taken (a FIFO would block its
     * writer, a device is no log). 209 otherwise.
     */
    public FileChannel openLog(Path checked) {
        Path name = checked.getFileName();
        try (SecureDirectoryStream<Path> folder = folderOf(checked)) {
            Set<OpenOption> options = Set.of(StandardOpenOption.CREATE, StandardOpenOption.READ,
                    StandardOpenOption.WRITE, LinkOption.NOFOLLOW_LINKS);
            // Read-write: opening a FIFO this way never waits for a reader, as a write-only open would.
            SeekableByteChannel channel = folder.newByteChannel(name, options,
                    PosixFilePermissions.asFileAttribute(PRIVATE_FILE));
            boolean regular = folder.getFileAttributeView(name, BasicFileAttributeView.class,
                    LinkOption.NOFOLLOW_LINKS).readAttributes().isRegularFile();
            if (!regular || !(channel instanceof FileChannel file)) {
                channel.close();
                throw new ArmorException(ExitCode.LOAD_FAILED, "'" + checked + "' is not a regular file (a directory,"
                        + " FIFO, socket or device); LOG FILE writes only to regular files");
            }
            file.position(file.size());
            return file;
        } catch (IOException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "cannot open log file '" + checked + "': " + e, e);
        }
    }

    /**
     * Makes each write directory that is missing (0700: only this user reads what clients
     * write); answers why any of them can never be written (the core then refuses to start).
     */
    public List<String> prepare() {
        List<String> problems = new ArrayList<>();
        for (Path root : roots) {
            try {
                Path target = AllowedPaths.finalTarget(root.toAbsolutePath());
                String refusal = refusal(target.resolve("x"));
                if (refusal != null && !refusal.startsWith("is directly in")) {
                    problems.add("write_dirs entry " + root + " can never be written: it " + refusal.replace(
                            "is a hidden", "is or lies in a hidden"));
                    continue;
                }
                if (!Files.exists(target)) {
                    Files.createDirectories(target);
                    Files.setPosixFilePermissions(target, PRIVATE_FOLDER);
                }
            } catch (IOException | RuntimeException e) {
                problems.add("write_dirs entry " + root + " cannot be made: " + e);
            }
        }
        return problems;
    }

    /** The checked target's folder, reached from its write directory without following a link. */
    private SecureDirectoryStream<Path> folderOf(Path checked) throws IOException {
        Path root = root(checked).orElseThrow(() -> new ArmorException(ExitCode.PATH_NOT_ALLOWED, "'" + checked
                + "' is outside the write directories " + roots));
        SecureDirectoryStream<Path> folder = secure(Files.newDirectoryStream(root));
        Path physical = root;
        try {
            Path below = root.relativize(checked.getParent());
            for (Path part : below.toString().isEmpty() ? List.<Path>of() : below) {
                physical = physical.resolve(part);
                SecureDirectoryStream<Path> next;
                try {
                    next = folder.newDirectoryStream(part, LinkOption.NOFOLLOW_LINKS);
                } catch (NoSuchFileException e) {
                    Files.createDirectory(physical);
                    next = folder.newDirectoryStream(part, LinkOption.NOFOLLOW_LINKS);
                }
                folder.close();
                folder = next;
            }
        } catch (IOException | RuntimeException e) {
            folder.close();
            if (Files.isSymbolicLink(physical)) {
                throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "'" + physical + "' became a symbolic link after"
                        + " the path was checked; nothing written", e);
            }
            throw e;
        }
        return folder;
    }

    private static SecureDirectoryStream<Path> secure(DirectoryStream<Path> stream) throws IOException {
        if (stream instanceof SecureDirectoryStream<Path> secure) {
            return secure;
        }
        stream.close();
        throw new IOException("this file system cannot open folders without following links; writing refused");
    }

    private static void deleteQuietly(SecureDirectoryStream<Path> folder, Path file) {
        try {
            folder.deleteFile(file);
        } catch (IOException e) {
            // nothing was written, or it is gone already: the write's own failure is what matters
        }
    }

    /** The folder of the core's own jar (its classes folder when run from a build). */
    private static Optional<Path> coreFolder() {
        try {
            Path code = Path.of(WritablePaths.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            return Optional.ofNullable(Files.isDirectory(code) ? code : code.getParent());
        } catch (java.net.URISyntaxException | RuntimeException e) {
            return Optional.empty();
        }
    }
}
