// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

/**
 * The state directory's {@link Storage} over real files, counting every I/O call, which can make
 * the k-th call fail with an I/O error (the SQLite way: run k fails call k) or cut the power at
 * it. A power cut stops the process (every later call throws {@link PowerCut}, which no code
 * of the core catches) and {@link #losePower()} then puts the files back as a disk keeps them:
 * only what was forced. File data is kept by a force of the file; a file made, renamed or
 * deleted is kept by a force of its directory. Folders made outside this storage count as kept.
 */
final class SimulatedDisk implements Storage {
    enum Call { WRITE, FORCE, TRUNCATE, CREATE, APPEND, READ, RENAME, SYNC_DIRECTORY, DELETE, MAKE_DIRECTORY }

    /** The process died at a power cut: nothing it does afterwards reaches the disk. */
    static final class PowerCut extends Error {
        PowerCut(String at) {
            super("power cut at " + at);
        }
    }

    /** What a disk keeps of one file: the bytes of its last force. */
    private static final class Inode {
        byte[] forced;

        Inode(byte[] forced) {
            this.forced = forced;
        }
    }

    private final Path root;
    private final Map<Path, Inode> liveFiles = new HashMap<>();
    private final Map<Path, Inode> keptFiles = new HashMap<>();
    // Folders made through this storage whose parent was not forced since: lost at a power cut.
    private final Set<Path> newDirs = new HashSet<>();
    // Folders renamed away whose parent was not forced since: back at a power cut.
    private final Set<Path> movedAway = new HashSet<>();
    // Folders renamed away for good: what the disk kept under them is gone.
    private final Set<Path> goneDirs = new HashSet<>();
    private final Map<Call, Integer> counts = new EnumMap<>(Call.class);
    private final List<String> log = new ArrayList<>();
    private int calls;
    private int failAt = -1;
    private Set<Call> failing = Set.of(Call.values());
    private int cutAt = -1;
    private boolean dead;

    /** The files now under {@code root} count as forced. */
    SimulatedDisk(Path root) throws IOException {
        this.root = root;
        if (Files.exists(root)) {
            try (Stream<Path> paths = Files.walk(root)) {
                for (Path path : paths.toList()) {
                    if (Files.isRegularFile(path)) {
                        Inode inode = new Inode(Files.readAllBytes(path));
                        liveFiles.put(path, inode);
                        keptFiles.put(path, inode);
                    }
                }
            }
        }
    }

    /** Makes call number {@code k} (from 1) fail with an I/O error, if it is of one of these kinds. */
    SimulatedDisk failCall(int k, Set<Call> kinds) {
        failAt = k;
        failing = kinds;
        return this;
    }

    /** Cuts the power at call number {@code k}: it and every later call throw {@link PowerCut}. */
    SimulatedDisk cutPowerAtCall(int k) {
        cutAt = k;
        return this;
    }

    int calls() {
        return calls;
    }

    Map<Call, Integer> counts() {
        return counts;
    }

    /** What call k was, by its number: "17 FORCE journal-1.log". */
    List<String> log() {
        return log;
    }

    boolean poweredOff() {
        return dead;
    }

    private void call(Call kind, Path path) throws IOException {
        if (dead) {
            throw new PowerCut("a call after the cut");
        }
        calls++;
        counts.merge(kind, 1, Integer::sum);
        String what = calls + " " + kind + " " + root.relativize(path);
        log.add(what);
        if (calls == cutAt) {
            dead = true;
            throw new PowerCut(what);
        }
        if (calls == failAt && failing.contains(kind)) {
            throw new IOException("injected I/O error at call " + what);
        }
    }

    /**
     * Puts the files back as the disk kept them: unforced data gone, entries of directories not
     * forced since undone.
     */
    void losePower() throws IOException {
        dead = true;
        Set<Path> files = new HashSet<>(liveFiles.keySet());
        files.addAll(keptFiles.keySet());
        for (Path file : files) {
            Inode kept = keptFiles.get(file);
            if (kept != null && dirKept(file.getParent())) {
                Files.createDirectories(file.getParent());
                Files.write(file, kept.forced);
            } else {
                Files.deleteIfExists(file);
            }
        }
        for (Path dir : newDirs.stream().sorted(Comparator.reverseOrder()).toList()) {
            if (Files.exists(dir)) {
                try (Stream<Path> paths = Files.walk(dir)) {
                    for (Path path : paths.sorted(Comparator.reverseOrder()).toList()) {
                        Files.delete(path);
                    }
                }
            }
        }
    }

    private boolean dirKept(Path dir) {
        for (Path d = dir; d != null && d.startsWith(root); d = d.getParent()) {
            if (newDirs.contains(d) || goneDirs.contains(d)) {
                return false;
            }
        }
        return true;
    }

    @Override
    public Output append(Path file) throws IOException {
        call(Call.APPEND, file);
        return track(file, Storage.FILES.append(file));
    }

    @Override
    public Output create(Path file) throws IOException {
        call(Call.CREATE, file);
        return track(file, Storage.FILES.create(file));
    }

    private Output track(Path file, Output real) {
        Inode inode = liveFiles.computeIfAbsent(file, f -> new Inode(new byte[0]));
        return new Output() {
            @Override
            public void write(ByteBuffer data) throws IOException {
                call(Call.WRITE, file);
                real.write(data);
            }

            @Override
            public void force() throws IOException {
                call(Call.FORCE, file);
                real.force();
                inode.forced = Files.readAllBytes(file);
            }

            @Override
            public void truncate(long size) throws IOException {
                call(Call.TRUNCATE, file);
                real.truncate(size);
            }

            @Override
            public long size() throws IOException {
                return real.size();
            }

            @Override
            public void close() throws IOException {
                real.close();
            }
        };
    }

    @Override
    public byte[] read(Path file) throws IOException {
        call(Call.READ, file);
        return Storage.FILES.read(file);
    }

    @Override
    public void rename(Path source, Path target) throws IOException {
        call(Call.RENAME, source);
        boolean directory = Files.isDirectory(source);
        Storage.FILES.rename(source, target);
        for (Path path : new ArrayList<>(liveFiles.keySet())) {
            if (path.startsWith(source)) {
                liveFiles.put(target.resolve(source.relativize(path)), liveFiles.remove(path));
            }
        }
        if (directory) {
            if (!newDirs.remove(source)) {
                movedAway.add(source);
            }
            newDirs.add(target);
        }
    }

    @Override
    public void syncDirectory(Path directory) throws IOException {
        call(Call.SYNC_DIRECTORY, directory);
        Storage.FILES.syncDirectory(directory);
        for (Path file : new ArrayList<>(keptFiles.keySet())) {
            if (directory.equals(file.getParent()) && !liveFiles.containsKey(file)) {
                keptFiles.remove(file);
            }
        }
        liveFiles.forEach((file, inode) -> {
            if (directory.equals(file.getParent())) {
                keptFiles.put(file, inode);
            }
        });
        newDirs.removeIf(dir -> directory.equals(dir.getParent()));
        for (Path dir : new ArrayList<>(movedAway)) {
            if (directory.equals(dir.getParent())) {
                movedAway.remove(dir);
                goneDirs.add(dir);
            }
        }
    }

    @Override
    public void deleteIfExists(Path file) throws IOException {
        call(Call.DELETE, file);
        Storage.FILES.deleteIfExists(file);
        liveFiles.remove(file);
    }

    @Override
    public void createDirectories(Path directory) throws IOException {
        call(Call.MAKE_DIRECTORY, directory);
        for (Path d = directory; d != null && d.startsWith(root) && !Files.exists(d); d = d.getParent()) {
            newDirs.add(d);
            goneDirs.remove(d);
        }
        Storage.FILES.createDirectories(directory);
    }
}
