// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import com.google.gson.JsonParser;
import io.github.armor.core.reasoning.ClassifiedSchema;
import io.github.armor.core.reference.Reference;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The reference's kept class hierarchy beside its checkpoint ({@code classified-schema.json}), so
 * a restart does not classify an upper ontology again: written when the reference has a
 * classification not written yet (checked after each of its changes; a classification in the
 * background ends between them), read at recovery and offered to the restored reference, which
 * takes it only if its schema's digest is the same ({@link ClassifiedSchema}). Losing it costs
 * one classification, never an answer.
 */
final class HierarchySidecar {
    private static final Logger LOG = LoggerFactory.getLogger(HierarchySidecar.class);
    private static final String FILE = "classified-schema.json";

    private HierarchySidecar() {}

    /** How the store writes a file durably (temporary file, forced, renamed over). */
    @FunctionalInterface
    interface DurableWrite {
        void write(Path target, byte[] bytes) throws IOException;
    }

    /** Writes a reference's hierarchy (read under its lock with {@link #of}; written from any thread). */
    static void write(Path dir, ClassifiedSchema schema, DurableWrite durably) {
        try {
            durably.write(dir.resolve(FILE), schema.toJson().toString().getBytes(StandardCharsets.UTF_8));
        } catch (IOException | RuntimeException e) {
            LOG.warn("could not keep the class hierarchy beside the checkpoint in {}: {}", dir, e.toString());
        }
    }

    /** What the reference keeps now, to be written when its checkpoint is (read under its lock). */
    static ClassifiedSchema of(Reference reference) {
        return reference.classifiedSchema().orElse(null);
    }

    /** Reads the sidecar of a recovered reference, if there is one, and offers it to the reference opened next. */
    static void read(Storage storage, Path dir) {
        Path file = dir.resolve(FILE);
        if (!Files.isRegularFile(file)) {
            return;
        }
        try {
            String text = new String(storage.read(file), StandardCharsets.UTF_8);
            ClassifiedSchema.remember(ClassifiedSchema.fromJson(JsonParser.parseString(text).getAsJsonObject(),
                    OWLManager.getOWLDataFactory()));
        } catch (IOException | RuntimeException e) {
            LOG.warn("the class hierarchy beside {} is unreadable ({}); it will be classified again", dir,
                    e.toString());
        }
    }
}
