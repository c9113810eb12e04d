// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Stream;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What the state directory could not bring back or cannot keep, for the operator: each restore
 * that found damage (kept in {@code <state_dir>/damaged/<reference>-<time>/} with the damaged
 * files and a {@code report.json}, until the operator deletes it), and each reference whose
 * changes are being refused now because the disk does not take them. Answered by GET STATE
 * DAMAGE, shown by the web view, logged.
 */
final class StateDamage {
    private static final Logger LOG = LoggerFactory.getLogger(StateDamage.class);

    private final Storage storage;
    private final Path damagedDir;
    private final List<JsonObject> restores = new ArrayList<>();
    private final Map<String, JsonObject> refusing = new ConcurrentHashMap<>();

    StateDamage(Storage storage, Path stateDir) {
        this.storage = storage;
        this.damagedDir = stateDir.resolve("damaged");
    }

    /** A folder of its own for what one restore of {@code reference} set aside. */
    Path newEntry(String escapedName) {
        return damagedDir.resolve(escapedName + "-" + System.currentTimeMillis());
    }

    /** Reads the reports earlier restores left, which stay until the operator deletes them. */
    synchronized void readEarlier() {
        if (!Files.isDirectory(damagedDir)) {
            return;
        }
        try (Stream<Path> entries = Files.list(damagedDir)) {
            for (Path entry : entries.sorted().toList()) {
                Path report = entry.resolve("report.json");
                try {
                    restores.add(JsonParser.parseString(Files.readString(report)).getAsJsonObject());
                } catch (IOException | RuntimeException e) {
                    JsonObject unreadable = report(entry.getFileName().toString(), false, -1,
                            List.of("its report.json cannot be read: " + e.getMessage()), entry);
                    restores.add(unreadable);
                }
            }
        } catch (IOException e) {
            LOG.error("cannot list {}: {}", damagedDir, e.toString());
        }
    }

    /**
     * Records a restore that found damage, logs it, and writes its report beside the files set
     * aside (best effort: the log and the in-memory report stand when the disk refuses it).
     */
    synchronized void restored(String reference, boolean restored, long revision, List<String> problems,
                               Path entry) {
        JsonObject report = report(reference, restored, revision, problems, entry);
        restores.add(report);
        LOG.error("state of reference '{}' is damaged: {}; {}; what was set aside is in {} (delete it once dealt"
                + " with)", reference, String.join("; ", problems),
                restored ? "restored up to revision " + revision : "NOT restored", entry);
        try {
            storage.createDirectories(entry);
            Path file = entry.resolve("report.json");
            try (Storage.Output out = storage.create(file)) {
                out.write(ByteBuffer.wrap(report.toString().getBytes(StandardCharsets.UTF_8)));
                out.force();
            }
            storage.syncDirectory(entry);
        } catch (IOException e) {
            LOG.error("could not write the damage report into {}: {}", entry, e.toString());
        }
    }

    private static JsonObject report(String reference, boolean restored, long revision, List<String> problems,
                                     Path entry) {
        JsonObject report = new JsonObject();
        report.addProperty("reference", reference);
        report.addProperty("when", Instant.now().toString());
        report.addProperty("restored", restored);
        if (restored) {
            report.addProperty("revision", revision);
        }
        JsonArray list = new JsonArray();
        problems.forEach(list::add);
        report.add("problems", list);
        report.addProperty("kept_in", entry.toString());
        return report;
    }

    void refusing(String reference, String why) {
        refusing.computeIfAbsent(reference, r -> {
            JsonObject entry = new JsonObject();
            entry.addProperty("reference", r);
            entry.addProperty("since", Instant.now().toString());
            LOG.error("changes to '{}' are refused: {}", r, why);
            return entry;
        }).addProperty("refusing_changes", why);
    }

    void accepting(String reference) {
        if (refusing.remove(reference) != null) {
            LOG.info("changes to '{}' are accepted again: the state directory takes them", reference);
        }
    }

    /** One JSON object per problem: restores that found damage, then references refusing changes. */
    synchronized List<String> lines() {
        List<String> lines = new ArrayList<>();
        restores.forEach(r -> lines.add(r.toString()));
        refusing.values().forEach(r -> lines.add(r.toString()));
        return lines;
    }
}
