// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.CRC32C;

/**
 * An append-only file of records, each framed as {@code [length][CRC32C][payload]}. A crash can
 * tear only the last record; reading stops at the first record whose length or checksum does
 * not hold, and everything before it is returned.
 */
final class Journal implements Closeable {
    private static final int HEADER_BYTES = 8;
    private static final int MAX_RECORD_BYTES = 64 << 20;

    private final FileChannel channel;
    private final boolean fsync;

    private Journal(FileChannel channel, boolean fsync) {
        this.channel = channel;
        this.fsync = fsync;
    }

    /** Opens (creating if needed) for appending after the last valid record. */
    static Journal openForAppend(Path file, boolean fsync) throws IOException {
        FileChannel channel = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                StandardOpenOption.READ);
        channel.position(channel.size());
        return new Journal(channel, fsync);
    }

    /**
     * Writes one record; with fsync on, it is on the disk when this returns. A record larger
     * than recovery reads back is refused, so its change is undone rather than acknowledged
     * and lost at the next restart.
     */
    void append(byte[] payload) throws IOException {
        if (payload.length > MAX_RECORD_BYTES) {
            throw new IOException("a record of " + payload.length + " bytes exceeds the journal's limit of "
                    + MAX_RECORD_BYTES + " bytes");
        }
        CRC32C crc = new CRC32C();
        crc.update(payload);
        ByteBuffer frame = ByteBuffer.allocate(HEADER_BYTES + payload.length)
                .putInt(payload.length).putInt((int) crc.getValue()).put(payload).flip();
        while (frame.hasRemaining()) {
            channel.write(frame);
        }
        if (fsync) {
            channel.force(false);
        }
    }

    /** The records of a journal file and where its valid part ends. */
    record Contents(List<byte[]> records, long validBytes, long fileBytes) {
        boolean tornTail() {
            return validBytes < fileBytes;
        }
    }

    static Contents read(Path file) throws IOException {
        if (!Files.exists(file)) {
            return new Contents(List.of(), 0, 0);
        }
        ByteBuffer data = ByteBuffer.wrap(Files.readAllBytes(file));
        List<byte[]> records = new ArrayList<>();
        long valid = 0;
        while (data.remaining() >= HEADER_BYTES) {
            int length = data.getInt();
            int expected = data.getInt();
            if (length < 0 || length > MAX_RECORD_BYTES || length > data.remaining()) {
                break;
            }
            byte[] payload = new byte[length];
            data.get(payload);
            CRC32C crc = new CRC32C();
            crc.update(payload);
            if ((int) crc.getValue() != expected) {
                break;
            }
            records.add(payload);
            valid = data.position();
        }
        return new Contents(records, valid, data.capacity());
    }

    /** Cuts a torn tail off, so new records follow the last valid one. */
    static void truncate(Path file, long validBytes) throws IOException {
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.WRITE)) {
            channel.truncate(validBytes);
            channel.force(true);
        }
    }

    @Override
    public void close() throws IOException {
        channel.close();
    }
}
