// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.CRC32C;

/**
 * An append-only file of records, each framed as {@code [length][CRC32C][payload]}. A record
 * that could not be written whole is cut off again before the append fails, so a record
 * acknowledged later never follows a broken one. Reading stops at the first record whose length
 * or checksum does not hold and says whether what follows looks like a write cut short by a
 * crash (a torn tail) or like damage (intact records after a broken one, or a broken record
 * that is complete).
 */
final class Journal implements Closeable {
    private static final int HEADER_BYTES = 8;
    private static final int MAX_RECORD_BYTES = 64 << 20;

    private final Storage.Output out;
    private final boolean fsync;
    // Where the last record known to be whole ends; bytes after it are a failed append's.
    private long validBytes;
    private long beforeLastRecord;
    private boolean tailToCut;

    private Journal(Storage.Output out, boolean fsync, long validBytes) {
        this.out = out;
        this.fsync = fsync;
        this.validBytes = validBytes;
    }

    /** Opens (creating if needed) for appending after its last byte, which must end a whole record. */
    static Journal openForAppend(Storage storage, Path file, boolean fsync) throws IOException {
        Storage.Output out = storage.append(file);
        try {
            return new Journal(out, fsync, out.size());
        } catch (RuntimeException e) {
            out.close();
            throw e;
        }
    }

    /**
     * Writes one record; with fsync on, it is on the disk when this returns. When it fails
     * (disk full, I/O error) the file is cut back to the records before it, now or, if even that
     * fails, before the next append, which fails until it can be. A record larger than recovery
     * reads back is refused, so its change is undone rather than acknowledged and lost at the
     * next restart.
     */
    void append(byte[] payload) throws IOException {
        if (payload.length > MAX_RECORD_BYTES) {
            throw new IOException("a record of " + payload.length + " bytes exceeds the journal's limit of "
                    + MAX_RECORD_BYTES + " bytes");
        }
        if (tailToCut) {
            cutTail();
        }
        ByteBuffer frame = ByteBuffer.allocate(HEADER_BYTES + payload.length)
                .putInt(payload.length).putInt(checksum(payload, 0, payload.length)).put(payload).flip();
        try {
            out.write(frame);
            if (fsync) {
                out.force();
            }
        } catch (IOException e) {
            tailToCut = true;
            try {
                cutTail();
            } catch (IOException cut) {
                e.addSuppressed(cut);
            }
            throw e;
        }
        beforeLastRecord = validBytes;
        validBytes += frame.capacity();
    }

    /**
     * Takes the last appended record back out (its list was refused elsewhere); if the file
     * cannot be cut now, the next append cuts it first.
     */
    void retractLast() throws IOException {
        validBytes = beforeLastRecord;
        tailToCut = true;
        cutTail();
    }

    private void cutTail() throws IOException {
        out.truncate(validBytes);
        if (fsync) {
            out.force();
        }
        tailToCut = false;
    }

    /** What reading found after the last whole record. */
    enum End {
        /** Nothing: every byte belongs to a whole record. */
        CLEAN,
        /** The start of a record cut short (or zeros): a write a crash interrupted. */
        TORN,
        /** A broken record that is complete, or whole records after a broken one. */
        DAMAGED
    }

    /** The records of a journal file, where its valid part ends, and what follows it. */
    record Contents(List<byte[]> records, long validBytes, long fileBytes, End end) {
        static final Contents EMPTY = new Contents(List.of(), 0, 0, End.CLEAN);
    }

    static Contents parse(byte[] bytes) {
        ByteBuffer data = ByteBuffer.wrap(bytes);
        List<byte[]> records = new ArrayList<>();
        int valid = 0;
        while (valid < bytes.length) {
            int length = wholeRecordAt(bytes, valid);
            if (length < 0) {
                return new Contents(records, valid, bytes.length, endAfter(bytes, valid));
            }
            byte[] payload = new byte[length];
            data.position(valid + HEADER_BYTES);
            data.get(payload);
            records.add(payload);
            valid += HEADER_BYTES + length;
        }
        return new Contents(records, valid, bytes.length, End.CLEAN);
    }

    /** The payload length of the whole, checksummed record at {@code offset}, or -1. */
    private static int wholeRecordAt(byte[] bytes, int offset) {
        if (bytes.length - offset < HEADER_BYTES) {
            return -1;
        }
        ByteBuffer header = ByteBuffer.wrap(bytes, offset, HEADER_BYTES);
        int length = header.getInt();
        int expected = header.getInt();
        // No record is empty: a header of zeros is a file extended but never written.
        if (length <= 0 || length > MAX_RECORD_BYTES || length > bytes.length - offset - HEADER_BYTES) {
            return -1;
        }
        return checksum(bytes, offset + HEADER_BYTES, length) == expected ? length : -1;
    }

    /**
     * A write cut short leaves the start of one record and nothing after it. Anything else after
     * the last whole record is damage: a whole record further on, or a record whose declared
     * length fits but whose checksum fails, or whose bytes to the end match its checksum (its
     * length field was damaged).
     */
    private static End endAfter(byte[] bytes, int broken) {
        int rest = bytes.length - broken;
        boolean zeros = true;
        for (int i = broken; i < bytes.length && zeros; i++) {
            zeros = bytes[i] == 0;
        }
        if (zeros || rest < HEADER_BYTES) {
            return End.TORN;
        }
        ByteBuffer header = ByteBuffer.wrap(bytes, broken, HEADER_BYTES);
        int length = header.getInt();
        int expected = header.getInt();
        boolean cutShort = length > rest - HEADER_BYTES && length <= MAX_RECORD_BYTES;
        if (!cutShort || checksum(bytes, broken + HEADER_BYTES, rest - HEADER_BYTES) == expected) {
            return End.DAMAGED;
        }
        for (int offset = broken + 1; offset + HEADER_BYTES < bytes.length; offset++) {
            if (wholeRecordAt(bytes, offset) > 0) {
                return End.DAMAGED;
            }
        }
        return End.TORN;
    }

    private static int checksum(byte[] bytes, int offset, int length) {
        CRC32C crc = new CRC32C();
        crc.update(bytes, offset, length);
        return (int) crc.getValue();
    }

    @Override
    public void close() throws IOException {
        out.close();
    }
}
