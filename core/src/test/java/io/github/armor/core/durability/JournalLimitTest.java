// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A record larger than recovery reads back is refused, never written and then lost (issue 20 item 7). */
class JournalLimitTest {
    @TempDir
    Path scratch;

    @Test
    void aRecordTooLargeToReadBackIsRefusedAndTheJournalStaysValid() throws IOException {
        Path file = scratch.resolve("journal.log");
        try (Journal journal = Journal.openForAppend(Storage.FILES, file, false)) {
            journal.append("first".getBytes());
            IOException refused = assertThrows(IOException.class, () -> journal.append(new byte[(64 << 20) + 1]));
            assertEquals(true, refused.getMessage().contains("exceeds the journal's limit"));
            journal.append("second".getBytes());
        }
        Journal.Contents contents = Journal.parse(Files.readAllBytes(file));
        assertEquals(2, contents.records().size());
        assertEquals("second", new String(contents.records().get(1)));
        assertEquals(Journal.End.CLEAN, contents.end());
    }
}
