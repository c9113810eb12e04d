// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.api.AcknowledgedChange;
import io.github.armor.core.api.CoreConfig.Durability;
import io.github.armor.core.reference.Reference;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.stream.Stream;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.formats.FunctionalSyntaxDocumentFormat;
import org.semanticweb.owlapi.model.AddImport;
import org.semanticweb.owlapi.model.OWLDocumentFormat;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.OWLOntologyStorageException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The files of one reference: {@code meta.json} (how to make the reference again and which
 * files are current), {@code checkpoint-N.ofn} (the ontology in OWL functional syntax) and
 * {@code journal-N.log} (directives acknowledged since). A reference is its checkpoint plus
 * its journals replayed in order.
 *
 * <p>Each journal record carries the reference's revision after it ({@code {"revision": n,
 * "directives": [...]}}; records of older versions, bare arrays, count one more than the one
 * before), and meta names the revision of its checkpoint, so a restored reference continues the
 * revisions it had.
 *
 * <p>Checkpoints are taken in two steps so that queries wait only for an in-memory copy: under
 * the reference's lock the ontology is copied and a new journal is started (meta then lists
 * both journals); the copy is written in the background, and only when it is on disk does meta
 * switch to it and the old files go.
 */
final class ReferenceStore {
    private static final Logger LOG = LoggerFactory.getLogger(ReferenceStore.class);

    private final Path dir;
    private final String name;
    private final Durability durability;
    private Reference.Settings settings;
    private String formatClass;
    private long checkpointSeq;
    private long checkpointRevision;
    // The change history as it was at the checkpoint: the journals it replaces are deleted, and
    // GET REF CHANGES must still answer for those changes after a restart.
    private List<AcknowledgedChange> historyInCheckpoint = new ArrayList<>();
    private final List<Long> journalSeqs = new ArrayList<>();
    private Journal journal;
    private int recordsSinceCheckpoint;
    private long lastCheckpointNanos = System.nanoTime();
    private boolean checkpointInFlight;
    // The digest of the class hierarchy last written beside the checkpoint (HierarchySidecar).
    private String hierarchyDigest;

    private ReferenceStore(Path dir, String name, Durability durability) {
        this.dir = dir;
        this.name = name;
        this.durability = durability;
    }

    /** What recovery needs: the checkpoint to load and the records to replay on top. */
    record Recovered(ReferenceStore store, String name, Reference.Settings settings, String mountedBy,
                     String formatClass, Path checkpoint, List<AcknowledgedChange> records, long revision,
                     int tornTails, List<AcknowledgedChange> history) {}

    /** Files for a new reference: its first checkpoint is the ontology as loaded. */
    static ReferenceStore create(Path dir, Reference reference, Durability durability) throws IOException {
        Files.createDirectories(dir);
        ReferenceStore store = new ReferenceStore(dir, reference.name(), durability);
        store.settings = reference.settings();
        OWLDocumentFormat format = reference.manager().getOntologyFormat(reference.ontology());
        store.formatClass = format == null ? "" : format.getClass().getName();
        store.checkpointSeq = 1;
        store.checkpointRevision = reference.revision();
        writeCheckpoint(snapshot(reference), store.checkpointFile(1));
        store.keepHierarchy(reference, Runnable::run);
        store.startJournal(1);
        store.writeMeta(reference.mountedBy());
        return store;
    }

    /** Reads a reference's files, cutting torn journal tails, and opens it for appending again. */
    static Recovered recover(Path dir, Durability durability) throws IOException {
        JsonObject meta = JsonParser.parseString(Files.readString(dir.resolve("meta.json"))).getAsJsonObject();
        HierarchySidecar.read(dir);
        ReferenceStore store = new ReferenceStore(dir, meta.get("name").getAsString(), durability);
        JsonObject s = meta.getAsJsonObject("settings");
        store.settings = new Reference.Settings(s.get("source").isJsonNull() ? null : s.get("source").getAsString(),
                s.get("ontology_iri").getAsString(), s.get("reasoner").getAsString(),
                s.get("buffered_manipulation").getAsBoolean(), s.get("buffered_reasoner").getAsBoolean());
        store.formatClass = meta.get("format").getAsString();
        store.checkpointSeq = meta.get("checkpoint").getAsLong();
        store.checkpointRevision = meta.has("checkpoint_revision") ? meta.get("checkpoint_revision").getAsLong() : 0;
        if (meta.has("recent_changes")) {
            for (JsonElement change : meta.getAsJsonArray("recent_changes")) {
                store.historyInCheckpoint.add(AcknowledgedChange.fromJson(change, 0));
            }
        }
        List<AcknowledgedChange> records = new ArrayList<>();
        long revision = store.checkpointRevision;
        int torn = 0;
        for (JsonElement seq : meta.getAsJsonArray("journals")) {
            Path file = store.journalFile(seq.getAsLong());
            Journal.Contents contents = Journal.read(file);
            if (contents.tornTail()) {
                torn++;
                LOG.warn("journal {} of '{}': dropped a torn tail of {} bytes", file.getFileName(), store.name,
                        contents.fileBytes() - contents.validBytes());
                Journal.truncate(file, contents.validBytes());
            }
            for (byte[] record : contents.records()) {
                AcknowledgedChange change = AcknowledgedChange.fromJson(
                        JsonParser.parseString(new String(record, StandardCharsets.UTF_8)), revision + 1);
                revision = change.revision();
                records.add(change);
            }
            store.journalSeqs.add(seq.getAsLong());
        }
        long last = store.journalSeqs.get(store.journalSeqs.size() - 1);
        store.journal = Journal.openForAppend(store.journalFile(last), durability.fsync());
        store.recordsSinceCheckpoint = records.size();
        return new Recovered(store, store.name, store.settings, meta.get("mounted_by").getAsString(),
                store.formatClass, store.checkpointFile(store.checkpointSeq), records, revision, torn,
                historyOf(store.historyInCheckpoint, records));
    }

    private static List<AcknowledgedChange> historyOf(List<AcknowledgedChange> inCheckpoint,
                                                      List<AcknowledgedChange> journaled) {
        List<AcknowledgedChange> history = new ArrayList<>(inCheckpoint);
        history.addAll(journaled);
        return history;
    }

    /**
     * Appends one record: the directives of one acknowledgement, replayed together or not at all,
     * and the reference's revision once they are applied.
     */
    synchronized void record(AcknowledgedChange change) throws IOException {
        journal.append(change.toJson().toString().getBytes(StandardCharsets.UTF_8));
        recordsSinceCheckpoint++;
    }

    /**
     * Starts a checkpoint when one is due. The caller holds the reference's lock; the reference
     * must have no buffered changes waiting (a checkpoint holds applied changes only).
     */
    void maybeCheckpoint(Reference reference, Executor background) {
        keepHierarchy(reference, background);
        long ageS = (System.nanoTime() - lastCheckpointNanos) / 1_000_000_000L;
        synchronized (this) {
            boolean due = recordsSinceCheckpoint >= durability.checkpointEveryChanges()
                    || (recordsSinceCheckpoint > 0 && ageS >= durability.checkpointEverySeconds());
            if (!due || checkpointInFlight || reference.hasPending()) {
                return;
            }
            checkpointInFlight = true;
        }
        try {
            OWLOntology copy = snapshot(reference);
            String mountedBy = reference.mountedBy();
            long revision = reference.revision();
            List<AcknowledgedChange> history = reference.changeHistory().all();
            long next;
            synchronized (this) {
                next = Math.max(checkpointSeq, journalSeqs.get(journalSeqs.size() - 1)) + 1;
                journal.close();
                startJournal(next);
                recordsSinceCheckpoint = 0;
                lastCheckpointNanos = System.nanoTime();
                writeMeta(mountedBy);
            }
            background.execute(() -> finishCheckpoint(copy, next, revision, mountedBy, history));
        } catch (IOException | RuntimeException e) {
            LOG.error("checkpoint of '{}' failed; its journal keeps growing until the next one", name, e);
            synchronized (this) {
                checkpointInFlight = false;
            }
        }
    }

    /** Writes the reference's class hierarchy beside the checkpoint when it has one not written yet. */
    private void keepHierarchy(Reference reference, Executor background) {
        io.github.armor.core.reasoning.ClassifiedSchema hierarchy = HierarchySidecar.of(reference);
        if (hierarchy != null && !hierarchy.digest().equals(hierarchyDigest)) {
            hierarchyDigest = hierarchy.digest();
            background.execute(() -> HierarchySidecar.write(dir, hierarchy));
        }
    }

    private void finishCheckpoint(OWLOntology copy, long seq, long revision, String mountedBy,
                                  List<AcknowledgedChange> history) {
        try {
            writeCheckpoint(copy, checkpointFile(seq));
            List<Long> obsoleteJournals;
            long obsoleteCheckpoint;
            synchronized (this) {
                obsoleteCheckpoint = checkpointSeq;
                obsoleteJournals = journalSeqs.stream().filter(s -> s < seq).toList();
                checkpointSeq = seq;
                checkpointRevision = revision;
                historyInCheckpoint = history;
                journalSeqs.removeAll(obsoleteJournals);
                writeMeta(mountedBy);
            }
            Files.deleteIfExists(checkpointFile(obsoleteCheckpoint));
            for (long old : obsoleteJournals) {
                Files.deleteIfExists(journalFile(old));
            }
        } catch (IOException | RuntimeException e) {
            LOG.error("writing checkpoint {} of '{}' failed; recovery uses the previous one", seq, name, e);
        } finally {
            synchronized (this) {
                checkpointInFlight = false;
            }
        }
    }

    synchronized void close() {
        try {
            journal.close();
        } catch (IOException e) {
            LOG.warn("closing the journal of '{}' failed: {}", name, e.toString());
        }
    }

    synchronized void delete() throws IOException {
        journal.close();
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(file);
            }
        }
    }

    private void startJournal(long seq) throws IOException {
        journal = Journal.openForAppend(journalFile(seq), durability.fsync());
        journalSeqs.add(seq);
    }

    private void writeMeta(String mountedBy) throws IOException {
        JsonObject s = new JsonObject();
        s.addProperty("source", settings.source());
        s.addProperty("ontology_iri", settings.ontologyIri());
        s.addProperty("reasoner", settings.reasoner());
        s.addProperty("buffered_manipulation", settings.bufferedManipulation());
        s.addProperty("buffered_reasoner", settings.bufferedReasoner());
        JsonObject meta = new JsonObject();
        meta.addProperty("name", name);
        meta.add("settings", s);
        meta.addProperty("format", formatClass);
        meta.addProperty("mounted_by", mountedBy);
        meta.addProperty("checkpoint", checkpointSeq);
        meta.addProperty("checkpoint_revision", checkpointRevision);
        JsonArray journals = new JsonArray();
        journalSeqs.forEach(journals::add);
        meta.add("journals", journals);
        JsonArray recent = new JsonArray();
        historyInCheckpoint.forEach(change -> recent.add(change.toJson()));
        meta.add("recent_changes", recent);
        writeDurably(dir.resolve("meta.json"), out -> out.write(meta.toString().getBytes(StandardCharsets.UTF_8)));
    }

    private Path checkpointFile(long seq) {
        return dir.resolve("checkpoint-" + seq + ".ofn");
    }

    private Path journalFile(long seq) {
        return dir.resolve("journal-" + seq + ".log");
    }

    /** The ontology's own axioms, annotations and imports, with its prefixes, in a manager of its own. */
    private static OWLOntology snapshot(Reference reference) {
        OWLOntology live = reference.ontology();
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        try {
            OWLOntology copy = manager.createOntology(live.getOntologyID());
            manager.addAxioms(copy, live.axioms());
            live.annotations().forEach(a -> manager.applyChange(
                    new org.semanticweb.owlapi.model.AddOntologyAnnotation(copy, a)));
            live.importsDeclarations().forEach(i -> manager.applyChange(new AddImport(copy, i)));
            FunctionalSyntaxDocumentFormat format = new FunctionalSyntaxDocumentFormat();
            OWLDocumentFormat original = reference.manager().getOntologyFormat(live);
            if (original != null && original.isPrefixOWLDocumentFormat()) {
                format.copyPrefixesFrom(original.asPrefixOWLDocumentFormat());
            }
            manager.setOntologyFormat(copy, format);
            return copy;
        } catch (OWLOntologyCreationException e) {
            throw new IllegalStateException("could not copy ontology of '" + reference.name() + "'", e);
        }
    }

    private static void writeCheckpoint(OWLOntology copy, Path file) throws IOException {
        writeDurably(file, out -> {
            try {
                copy.getOWLOntologyManager().saveOntology(copy, copy.getOWLOntologyManager().getOntologyFormat(copy),
                        out);
            } catch (OWLOntologyStorageException e) {
                throw new IOException("cannot write checkpoint: " + e.getMessage(), e);
            }
        });
    }

    @FunctionalInterface
    interface Writer {
        void write(OutputStream out) throws IOException;
    }

    /** Temporary file, forced to disk, renamed over the target: readers see old or new, never half. */
    static void writeDurably(Path target, Writer writer) throws IOException {
        Path temporary = target.resolveSibling(target.getFileName() + ".tmp");
        try (FileChannel channel = FileChannel.open(temporary, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                StandardOpenOption.TRUNCATE_EXISTING)) {
            OutputStream out = Channels.newOutputStream(channel);
            writer.write(out);
            out.flush();
            channel.force(true);
        }
        Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        try (FileChannel directory = FileChannel.open(target.getParent(), StandardOpenOption.READ)) {
            directory.force(true);
        }
    }
}
