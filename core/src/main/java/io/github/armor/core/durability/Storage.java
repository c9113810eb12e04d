// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;

/**
 * Every file operation the state directory makes, and nothing else: the one seam where a test
 * makes the k-th write, fsync or read fail, or cuts the power after it. The real one is
 * {@link #FILES}; durability code never touches {@link Files} for writing directly.
 */
public interface Storage {
    /** A file open for writing at its end. */
    interface Output extends Closeable {
        void write(ByteBuffer data) throws IOException;

        /** Forces what was written, and the file's size, to the disk. */
        void force() throws IOException;

        /** Cuts the file to {@code size} bytes and writes from there on. */
        void truncate(long size) throws IOException;

        long size() throws IOException;
    }

    /** Opens for appending, creating the file if it is missing. */
    Output append(Path file) throws IOException;

    /** Creates the file, or empties it, for writing from its start. */
    Output create(Path file) throws IOException;

    byte[] read(Path file) throws IOException;

    /** Renames atomically, replacing {@code target}. */
    void rename(Path source, Path target) throws IOException;

    /** Forces a directory's entries (files made, renamed or deleted in it) to the disk. */
    void syncDirectory(Path directory) throws IOException;

    void deleteIfExists(Path file) throws IOException;

    void createDirectories(Path directory) throws IOException;

    /** The real file system. */
    Storage FILES = new Storage() {
        @Override
        public Output append(Path file) throws IOException {
            FileChannel channel = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                    StandardOpenOption.READ);
            channel.position(channel.size());
            return new ChannelOutput(channel);
        }

        @Override
        public Output create(Path file) throws IOException {
            return new ChannelOutput(FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING));
        }

        @Override
        public byte[] read(Path file) throws IOException {
            return Files.readAllBytes(file);
        }

        @Override
        public void rename(Path source, Path target) throws IOException {
            Files.move(source, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        }

        @Override
        public void syncDirectory(Path directory) throws IOException {
            try (FileChannel channel = FileChannel.open(directory, StandardOpenOption.READ)) {
                channel.force(true);
            }
        }

        @Override
        public void deleteIfExists(Path file) throws IOException {
            Files.deleteIfExists(file);
        }

        @Override
        public void createDirectories(Path directory) throws IOException {
            Files.createDirectories(directory);
        }
    };

    /** A {@link FileChannel} as an {@link Output}. */
    final class ChannelOutput implements Output {
        private final FileChannel channel;

        ChannelOutput(FileChannel channel) {
            this.channel = channel;
        }

        @Override
        public void write(ByteBuffer data) throws IOException {
            while (data.hasRemaining()) {
                channel.write(data);
            }
        }

        @Override
        public void force() throws IOException {
            // fdatasync: the data and the size that reads it back, without the times.
            channel.force(false);
        }

        @Override
        public void truncate(long size) throws IOException {
            channel.truncate(size);
            channel.position(size);
        }

        @Override
        public long size() throws IOException {
            return channel.size();
        }

        @Override
        public void close() throws IOException {
            channel.close();
        }
    }
}
