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
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Executor;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.CRC32C;
import org.semanticweb.owlapi.model.OWLDocumentFormat;
import org.semanticweb.owlapi.model.OWLOntology;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The files of one reference: {@code meta.json} and its twin {@code meta-copy.json} (how to make
 * the reference again and which files are current, with a checksum), {@code checkpoint-N.ofn}
 * (the ontology; {@code .owx} when functional syntax cannot carry it) and {@code journal-N.log}
 * (changes acknowledged since). A reference is its checkpoint plus its journals replayed in order.
 * The checkpoint before the current one and the journals between them are kept too: a current
 * checkpoint found damaged at restore is replaced by that one with every journal since.
 *
 * <p>Each journal record carries the reference's revision after it ({@code {"revision": n,
 * "directives": [...]}}; records of older versions, bare arrays, count one more than the one
 * before), and meta names the revision of its checkpoint, so a restored reference continues the
 * revisions it had.
 *
 * <p>Checkpoints are taken in two steps so that queries wait only for an in-memory copy: under
 * the reference's lock the ontology is copied and a new journal is started (meta then lists
 * both journals); the copy is written in the background, and only when it is on disk and reads
 * back equal does meta switch to it. Every step that fails leaves meta naming files that hold
 * every acknowledged change.
 */
final class ReferenceStore {
    private static final Logger LOG = LoggerFactory.getLogger(ReferenceStore.class);
    private static final Pattern NUMBERED = Pattern.compile("(checkpoint|journal)-(\\d+)\\..*");

    private final Storage storage;
    private final Path dir;
    private final String name;
    private final Durability durability;
    private Reference.Settings settings;
    private String formatClass;
    private CheckpointFile.Written checkpoint;
    // The mount holder when the checkpoint was taken: replaying its journals changes it as it changed.
    private String mountedAtCheckpoint = "";
    // The change history as it was at the checkpoint: the journals it replaces are deleted, and
    // GET REF CHANGES must still answer for those changes after a restart.
    private List<AcknowledgedChange> historyInCheckpoint = new ArrayList<>();
    private List<Long> journalSeqs = new ArrayList<>();
    private CheckpointFile.Written previous;
    private List<Long> previousJournals = new ArrayList<>();
    private long highestSeq;
    private Journal journal;
    // File operations a restore that found damage still owes (the disk refused them): changes
    // are refused until they are done.
    private final List<Repair> repairs = new ArrayList<>();
    private int recordsSinceCheckpoint;
    private long lastCheckpointNanos = System.nanoTime();
    private boolean checkpointInFlight;
    // The digest of the class hierarchy last written beside the checkpoint (HierarchySidecar).
    private String hierarchyDigest;
    // What a restore read from the journals, where each record is and the list it belongs to:
    // kept until every reference is read, to take out a list not all its references recorded.
    private List<Replayed> replayed = new ArrayList<>();

    /** A journal record a restore replays: its change, where it starts, and its list (or null). */
    record Replayed(AcknowledgedChange change, long seq, long offset, ListSpan list) {}

    @FunctionalInterface
    interface Repair {
        void run() throws IOException;
    }

    private ReferenceStore(Storage storage, Path dir, String name, Durability durability) {
        this.storage = storage;
        this.dir = dir;
        this.name = name;
        this.durability = durability;
    }

    /** Parses a checkpoint file of a reference with these settings and document format; throws when it cannot. */
    @FunctionalInterface
    interface Loader {
        OWLOntology load(Path checkpoint, Reference.Settings settings, String formatClass);
    }

    /**
     * What recovery found: the ontology to start from, the records to replay on top, and what
     * could not be brought back (empty when nothing was lost).
     */
    record Recovered(ReferenceStore store, String name, Reference.Settings settings, String mountedBy,
                     String formatClass, OWLOntology ontology, List<AcknowledgedChange> records, long revision,
                     List<AcknowledgedChange> history, List<String> problems, Path setAside) {}

    /** A reference's files that cannot be restored at all (no meta, no checkpoint that reads). */
    static final class Unrestorable extends IOException {
        final List<String> problems;

        Unrestorable(List<String> problems) {
            super(String.join("; ", problems));
            this.problems = problems;
        }
    }

    /**
     * A folder without meta: a LOAD or CREATE cut short before it was acknowledged (meta is
     * written last, and never missing afterwards).
     */
    static final class Unfinished extends IOException {
        Unfinished() {
            super("no meta.json: a reference whose creation was never finished");
        }
    }

    /** Files for a new reference: its first checkpoint is the ontology as loaded. */
    static ReferenceStore create(Storage storage, Path dir, Reference reference, Durability durability)
            throws IOException {
        storage.createDirectories(dir);
        storage.syncDirectory(dir.getParent());
        ReferenceStore store = new ReferenceStore(storage, dir, reference.name(), durability);
        store.settings = reference.settings();
        OWLDocumentFormat format = reference.manager().getOntologyFormat(reference.ontology());
        store.formatClass = format == null ? "" : format.getClass().getName();
        store.highestSeq = 1;
        store.checkpoint = CheckpointFile.write(storage, CheckpointFile.snapshot(reference), dir, 1,
                reference.revision());
        store.keepHierarchy(reference, Runnable::run);
        store.journal = Journal.openForAppend(storage, store.journalFile(1), durability.fsync());
        store.journalSeqs.add(1L);
        store.mountedAtCheckpoint = reference.mountedBy();
        store.writeMeta();
        return store;
    }

    /**
     * Reads a reference's files: meta (or its twin), the current checkpoint (or the one before
     * it), the journals up to the first damaged record. Torn tails (writes a crash cut short,
     * never acknowledged) are cut off. Damaged files are moved into {@code setAside}, the intact
     * part of a damaged journal stays, and meta is rewritten to name what remains, so the files
     * again hold exactly the restored reference.
     */
    static Recovered recover(Storage storage, Path dir, Durability durability, Loader loader, Path setAside)
            throws IOException {
        List<String> problems = new ArrayList<>();
        JsonObject meta = readMeta(storage, dir, problems);
        HierarchySidecar.read(storage, dir);
        ReferenceStore store = new ReferenceStore(storage, dir, meta.get("name").getAsString(), durability);
        store.readFields(meta);
        store.highestSeq = highestSeqIn(dir);
        List<Path> damaged = new ArrayList<>();
        OWLOntology ontology = null;
        List<Long> toReplay = new ArrayList<>(store.journalSeqs);
        long revision = store.checkpoint.revision();
        try {
            ontology = store.load(store.checkpoint, loader);
        } catch (IOException | RuntimeException e) {
            problems.add(describe(e));
            damaged.add(dir.resolve(store.checkpoint.file()));
            if (store.previous != null) {
                try {
                    ontology = store.load(store.previous, loader);
                    toReplay = new ArrayList<>(store.previousJournals);
                    toReplay.addAll(store.journalSeqs);
                    revision = store.previous.revision();
                    problems.add("restored from the checkpoint before it, " + store.previous.file()
                            + ", and every journal since");
                    store.checkpoint = store.previous;
                    store.historyInCheckpoint = new ArrayList<>();
                } catch (IOException | RuntimeException older) {
                    problems.add(describe(older));
                }
            }
            store.previous = null;
            store.previousJournals = new ArrayList<>();
            if (ontology == null) {
                throw new Unrestorable(problems);
            }
        }
        List<Replayed> records = new ArrayList<>();
        List<Long> kept = new ArrayList<>();
        boolean broken = false;
        for (long seq : toReplay) {
            Path file = store.journalFile(seq);
            if (broken) {
                // Its changes follow lost ones: it goes aside.
                damaged.add(file);
                continue;
            }
            byte[] bytes;
            try {
                bytes = storage.read(file);
            } catch (NoSuchFileException e) {
                problems.add(file.getFileName() + " is missing; the journals from it on were not replayed");
                broken = true;
                continue;
            } catch (IOException e) {
                problems.add(file.getFileName() + " cannot be read (" + e.getMessage()
                        + "); the journals from it on were not replayed");
                damaged.add(file);
                broken = true;
                continue;
            }
            kept.add(seq);
            Journal.Contents contents = Journal.parse(bytes);
            int decoded = 0;
            long offset = 0;
            for (byte[] record : contents.records()) {
                try {
                    JsonElement json = JsonParser.parseString(new String(record, StandardCharsets.UTF_8));
                    AcknowledgedChange change = AcknowledgedChange.fromJson(json, revision + 1);
                    ListSpan list = json.isJsonObject() ? ListSpan.fromRecord(json.getAsJsonObject()) : null;
                    dropRefused(records, change, file);
                    revision = change.revision();
                    records.add(new Replayed(change, seq, offset, list));
                    decoded++;
                    offset += 8 + record.length;
                } catch (RuntimeException e) {
                    break;
                }
            }
            if (contents.end() == Journal.End.DAMAGED || decoded < contents.records().size()) {
                long intact = prefixOf(contents, decoded);
                problems.add(file.getFileName() + ": record " + (decoded + 1) + " is damaged; it and the "
                        + (bytes.length - intact) + " byte(s) after it (changes after revision " + revision
                        + ") were not replayed");
                byte[] intactBytes = Arrays.copyOf(bytes, (int) intact);
                store.repairs.add(() -> {
                    storage.createDirectories(setAside);
                    storage.rename(file, setAside.resolve(file.getFileName()));
                    store.writeDurably(file, intactBytes);
                });
                broken = true;
            } else if (contents.end() == Journal.End.TORN) {
                LOG.warn("journal {} of '{}': cut a torn tail of {} bytes (a write a crash interrupted, never"
                        + " acknowledged)", file.getFileName(), store.name, contents.fileBytes() - contents.validBytes());
                long valid = contents.validBytes();
                store.repairs.add(() -> {
                    try (Storage.Output out = storage.append(file)) {
                        out.truncate(valid);
                        out.force();
                    }
                });
            }
        }
        if (kept.isEmpty()) {
            // Not one journal could be read: appends go to a fresh one, made before meta names it.
            long fresh = ++store.highestSeq;
            kept.add(fresh);
            store.repairs.add(() -> Journal.openForAppend(storage, store.journalFile(fresh), false).close());
        }
        store.journalSeqs = kept;
        for (Path file : damaged) {
            store.repairs.add(() -> {
                if (Files.exists(file)) {
                    storage.createDirectories(setAside);
                    storage.rename(file, setAside.resolve(file.getFileName()));
                }
            });
        }
        if (!problems.isEmpty()) {
            store.repairs.add(store::writeMeta);
        }
        store.runRepairsQuietly();
        store.replayed = records;
        return store.recovered(meta.get("mounted_by").getAsString(), ontology, problems, setAside);
    }

    /** What is to be replayed of this reference now, with the revision and history it gives. */
    private Recovered recovered(String mountedBy, OWLOntology ontology, List<String> problems, Path setAside) {
        List<AcknowledgedChange> records = replayed.stream().map(Replayed::change).toList();
        long revision = records.isEmpty() ? checkpoint.revision() : records.get(records.size() - 1).revision();
        recordsSinceCheckpoint = records.size();
        return new Recovered(this, name, settings, mountedBy, formatClass, ontology, records, revision,
                historyOf(historyInCheckpoint, records), problems, setAside);
    }

    /** The journal records a restore read, in order, with their lists. */
    List<Replayed> replayed() {
        return replayed;
    }

    /** The revision the current checkpoint holds: every change up to it is in there, not in a journal. */
    long checkpointRevision() {
        return checkpoint.revision();
    }

    /**
     * Takes the records from {@code index} on out of a restore, and out of the files: record
     * {@code index} belongs to an atomic list that not every one of its references recorded.
     * {@code inFlight}: it is the last record and the others are missing only because a crash
     * came before their records were on the disk, so the list was never acknowledged and its
     * record is cut off like a torn tail; otherwise what is cut is set aside and reported.
     */
    synchronized Recovered withoutRecordsFrom(StateStore.Restorable recovered, int index, boolean inFlight,
                                              String why) {
        Replayed first = replayed.get(index);
        List<String> problems = new ArrayList<>(recovered.problems());
        long before = index == 0 ? checkpoint.revision() : replayed.get(index - 1).change().revision();
        List<Long> later = journalSeqs.stream().filter(seq -> seq > first.seq()).toList();
        Path file = journalFile(first.seq());
        // Reopened once the files are cut, so that it appends (and cuts back a failed append) at their new end.
        close();
        journal = null;
        if (inFlight && later.isEmpty() && index == replayed.size() - 1) {
            LOG.warn("journal {} of '{}': cut the record of an atomic list a crash interrupted before all its"
                    + " references recorded it (never acknowledged): {}", file.getFileName(), name, why);
            repairs.add(() -> {
                try (Storage.Output out = storage.append(file)) {
                    out.truncate(first.offset());
                    out.force();
                }
            });
        } else {
            problems.add(file.getFileName() + ": record at byte " + first.offset() + " " + why + "; it and the "
                    + (replayed.size() - index) + " record(s) from it on (changes after revision " + before
                    + ") were not replayed");
            Path setAside = recovered.setAside();
            repairs.add(() -> {
                byte[] intact = Arrays.copyOf(storage.read(file), (int) first.offset());
                storage.createDirectories(setAside);
                storage.rename(file, setAside.resolve(file.getFileName()));
                writeDurably(file, intact);
            });
            for (long seq : later) {
                Path laterFile = journalFile(seq);
                repairs.add(() -> {
                    if (Files.exists(laterFile)) {
                        storage.createDirectories(setAside);
                        storage.rename(laterFile, setAside.resolve(laterFile.getFileName()));
                    }
                });
            }
            journalSeqs = new ArrayList<>(journalSeqs.stream().filter(seq -> seq <= first.seq()).toList());
            repairs.add(this::writeMeta);
        }
        replayed = new ArrayList<>(replayed.subList(0, index));
        runRepairsQuietly();
        return recovered(recovered.mountedBy(), recovered.ontology(), problems, recovered.setAside());
    }

    /**
     * A record whose append failed, and which could not be cut off again, may still be whole in
     * the file (its write succeeded, its fsync did not). The change after it was acknowledged with
     * the same revision, so a record followed by one of the same or a lower revision was refused:
     * it is dropped here.
     */
    private static void dropRefused(List<Replayed> records, AcknowledgedChange next, Path file) {
        while (!records.isEmpty() && records.get(records.size() - 1).change().revision() >= next.revision()) {
            AcknowledgedChange refused = records.remove(records.size() - 1).change();
            LOG.warn("{}: dropped the record of revision {}, refused when it was written (a later record has the"
                    + " same revision)", file.getFileName(), refused.revision());
        }
    }

    /** Bytes of the first {@code records} records: where a damaged journal's intact part ends. */
    private static long prefixOf(Journal.Contents contents, int records) {
        long bytes = 0;
        for (int i = 0; i < records; i++) {
            bytes += 8 + contents.records().get(i).length;
        }
        return bytes;
    }

    private OWLOntology load(CheckpointFile.Written written, Loader loader) throws IOException {
        CheckpointFile.check(storage, dir, written);
        try {
            return loader.load(dir.resolve(written.file()), settings, formatClass);
        } catch (RuntimeException e) {
            throw new IOException(written.file() + " does not parse: " + e.getMessage(), e);
        }
    }

    private static String describe(Exception e) {
        return e instanceof IOException && e.getMessage() != null ? e.getMessage() : e.toString();
    }

    private static long highestSeqIn(Path dir) throws IOException {
        long highest = 0;
        try (Stream<Path> files = Files.list(dir)) {
            for (Path file : files.toList()) {
                Matcher m = NUMBERED.matcher(file.getFileName().toString());
                if (m.matches()) {
                    highest = Math.max(highest, Long.parseLong(m.group(2)));
                }
            }
        }
        return highest;
    }

    /**
     * meta.json, or meta-copy.json when the first is missing or fails its checksum. Files of
     * older versions have no checksum and no twin.
     */
    private static JsonObject readMeta(Storage storage, Path dir, List<String> problems) throws IOException {
        for (String file : List.of("meta.json", "meta-copy.json")) {
            Path path = dir.resolve(file);
            if (!Files.exists(path)) {
                continue;
            }
            try {
                JsonObject wrapper = JsonParser.parseString(new String(storage.read(path), StandardCharsets.UTF_8))
                        .getAsJsonObject();
                if (!wrapper.has("meta")) {
                    return wrapper;
                }
                JsonObject meta = wrapper.getAsJsonObject("meta");
                if (crc32c(meta.toString()) != wrapper.get("crc32c").getAsLong()) {
                    throw new IOException("its checksum does not match");
                }
                return meta;
            } catch (IOException | RuntimeException e) {
                problems.add(file + " is damaged: " + describe(e) + (file.equals("meta.json")
                        ? " (meta-copy.json used)" : ""));
            }
        }
        if (problems.isEmpty()) {
            throw new Unfinished();
        }
        throw new Unrestorable(problems);
    }

    private void readFields(JsonObject meta) {
        JsonObject s = meta.getAsJsonObject("settings");
        settings = new Reference.Settings(s.get("source").isJsonNull() ? null : s.get("source").getAsString(),
                s.get("ontology_iri").getAsString(), s.get("reasoner").getAsString(),
                s.get("buffered_manipulation").getAsBoolean(), s.get("buffered_reasoner").getAsBoolean());
        formatClass = meta.get("format").getAsString();
        mountedAtCheckpoint = meta.get("mounted_by").getAsString();
        long revision = meta.has("checkpoint_revision") ? meta.get("checkpoint_revision").getAsLong() : 0;
        checkpoint = meta.has("current") ? CheckpointFile.Written.fromJson(meta.getAsJsonObject("current"))
                // Written before checkpoints had checksums: trusted as they are.
                : new CheckpointFile.Written("checkpoint-" + meta.get("checkpoint").getAsLong() + ".ofn", -1, -1,
                        revision);
        if (meta.has("recent_changes")) {
            for (JsonElement change : meta.getAsJsonArray("recent_changes")) {
                historyInCheckpoint.add(AcknowledgedChange.fromJson(change, 0));
            }
        }
        meta.getAsJsonArray("journals").forEach(seq -> journalSeqs.add(seq.getAsLong()));
        if (meta.has("previous")) {
            JsonObject before = meta.getAsJsonObject("previous");
            previous = CheckpointFile.Written.fromJson(before.getAsJsonObject("checkpoint"));
            before.getAsJsonArray("journals").forEach(seq -> previousJournals.add(seq.getAsLong()));
        }
    }

    private static List<AcknowledgedChange> historyOf(List<AcknowledgedChange> inCheckpoint,
                                                      List<AcknowledgedChange> journaled) {
        List<AcknowledgedChange> history = new ArrayList<>(inCheckpoint);
        history.addAll(journaled);
        return history;
    }

    /**
     * Appends one record: the directives of one acknowledgement, replayed together or not at all,
     * and the reference's revision once they are applied. When it throws, nothing of the record
     * stays in the journal.
     */
    synchronized void record(AcknowledgedChange change, ListSpan list) throws IOException {
        runRepairs();
        JsonObject json = change.toJson();
        if (list != null) {
            json.add("list", list.toJson());
        }
        journal.append(json.toString().getBytes(StandardCharsets.UTF_8));
        recordsSinceCheckpoint++;
    }

    /** Takes the last record back out: a list whose other records were refused. */
    synchronized void retractLast() throws IOException {
        recordsSinceCheckpoint--;
        journal.retractLast();
    }

    private void runRepairs() throws IOException {
        while (!repairs.isEmpty()) {
            repairs.get(0).run();
            repairs.remove(0);
        }
        if (journal == null) {
            journal = Journal.openForAppend(storage, journalFile(journalSeqs.get(journalSeqs.size() - 1)),
                    durability.fsync());
        }
    }

    private void runRepairsQuietly() {
        try {
            runRepairs();
            deleteUnnamedFiles();
        } catch (IOException e) {
            LOG.error("the files of '{}' could not be put in order ({}); its changes are refused until they can",
                    name, e.toString());
        }
    }

    /** Files a failed or interrupted step left behind, which meta does not name. */
    private void deleteUnnamedFiles() throws IOException {
        Set<String> named = new java.util.HashSet<>(List.of("meta.json", "meta-copy.json", checkpoint.file()));
        journalSeqs.forEach(seq -> named.add(journalFile(seq).getFileName().toString()));
        if (previous != null) {
            named.add(previous.file());
            previousJournals.forEach(seq -> named.add(journalFile(seq).getFileName().toString()));
        }
        try (Stream<Path> files = Files.list(dir)) {
            for (Path file : files.toList()) {
                String fileName = file.getFileName().toString();
                if (!named.contains(fileName) && (fileName.endsWith(".tmp") || NUMBERED.matcher(fileName).matches())) {
                    storage.deleteIfExists(file);
                }
            }
        }
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
            if (!due || checkpointInFlight || reference.hasPending() || !repairs.isEmpty()) {
                return;
            }
            checkpointInFlight = true;
            // Counted from this attempt, so a disk that refuses it is not asked again at every change.
            recordsSinceCheckpoint = 0;
            lastCheckpointNanos = System.nanoTime();
        }
        try {
            OWLOntology copy = CheckpointFile.snapshot(reference);
            String mountedBy = reference.mountedBy();
            long revision = reference.revision();
            List<AcknowledgedChange> history = reference.changeHistory().all();
            long next = startNextJournal();
            background.execute(() -> finishCheckpoint(copy, next, revision, mountedBy, history));
        } catch (IOException | RuntimeException e) {
            LOG.error("checkpoint of '{}' failed; its journal keeps growing until the next one: {}", name,
                    e.toString());
            synchronized (this) {
                checkpointInFlight = false;
            }
        }
    }

    /**
     * Writes the class hierarchy of a reference over an upper ontology beside the checkpoint when
     * it has one not written yet (a standalone ontology classifies in less time than reading it back).
     */
    private void keepHierarchy(Reference reference, Executor background) {
        io.github.armor.core.reasoning.ClassifiedSchema hierarchy = HierarchySidecar.of(reference);
        if (hierarchy == null || hierarchy.digest().equals(hierarchyDigest)
                || !io.github.armor.core.reasoning.RealisationScope.overUpperOntology(reference.ontology())) {
            return;
        }
        hierarchyDigest = hierarchy.digest();
        background.execute(() -> HierarchySidecar.write(dir, hierarchy, this::writeDurably));
    }

    /** Opens the next journal and names it in meta; when either fails the current one stays in use. */
    private synchronized long startNextJournal() throws IOException {
        long next = ++highestSeq;
        Journal fresh = Journal.openForAppend(storage, journalFile(next), durability.fsync());
        journalSeqs.add(next);
        try {
            writeMeta();
        } catch (IOException | RuntimeException e) {
            journalSeqs.remove(next);
            fresh.close();
            // Deleted only once no meta names it; left empty it replays as nothing.
            if (restoreMeta(e)) {
                storage.deleteIfExists(journalFile(next));
            }
            throw e;
        }
        journal.close();
        journal = fresh;
        return next;
    }

    private void finishCheckpoint(OWLOntology copy, long seq, long revision, String mountedBy,
                                  List<AcknowledgedChange> history) {
        CheckpointFile.Written written = null;
        try {
            written = CheckpointFile.write(storage, copy, dir, seq, revision);
            List<Path> obsolete = new ArrayList<>();
            synchronized (this) {
                CheckpointFile.Written oldCheckpoint = checkpoint;
                CheckpointFile.Written oldPrevious = previous;
                List<Long> oldJournals = journalSeqs;
                List<Long> oldPreviousJournals = previousJournals;
                List<AcknowledgedChange> oldHistory = historyInCheckpoint;
                String oldMounted = mountedAtCheckpoint;
                previous = checkpoint;
                previousJournals = journalSeqs.stream().filter(s -> s < seq).toList();
                journalSeqs = new ArrayList<>(journalSeqs.stream().filter(s -> s >= seq).toList());
                checkpoint = written;
                historyInCheckpoint = history;
                mountedAtCheckpoint = mountedBy;
                try {
                    writeMeta();
                } catch (IOException | RuntimeException e) {
                    checkpoint = oldCheckpoint;
                    previous = oldPrevious;
                    journalSeqs = oldJournals;
                    previousJournals = oldPreviousJournals;
                    historyInCheckpoint = oldHistory;
                    mountedAtCheckpoint = oldMounted;
                    if (!restoreMeta(e)) {
                        written = null;
                    }
                    throw e;
                }
                // Meta names it now: whatever fails from here on must not delete it.
                written = null;
                if (oldPrevious != null) {
                    obsolete.add(dir.resolve(oldPrevious.file()));
                }
                oldPreviousJournals.forEach(s -> obsolete.add(journalFile(s)));
            }
            for (Path file : obsolete) {
                storage.deleteIfExists(file);
            }
        } catch (IOException | RuntimeException e) {
            if (!Files.isDirectory(dir)) {
                // A DROP moved the reference's folder away while this ran: nothing is left to keep.
                LOG.info("checkpoint {} of '{}' abandoned: the reference was dropped", seq, name);
                return;
            }
            LOG.error("writing checkpoint {} of '{}' failed; the previous one and every journal since stay in use:"
                    + " {}", seq, name, e.toString());
            if (written != null) {
                try {
                    storage.deleteIfExists(dir.resolve(written.file()));
                } catch (IOException ignored) {
                    // Deleted at the next restore: meta does not name it.
                }
            }
        } finally {
            synchronized (this) {
                checkpointInFlight = false;
            }
        }
    }

    synchronized void close() {
        if (journal == null) {
            return;
        }
        try {
            journal.close();
        } catch (IOException e) {
            LOG.warn("closing the journal of '{}' failed: {}", name, e.toString());
        }
    }

    /**
     * After a failed meta write (one of the two copies may have been replaced), writes meta as it
     * was again; false when that fails too, and files the new meta names must then stay.
     */
    private boolean restoreMeta(Exception failure) {
        try {
            writeMeta();
            return true;
        } catch (IOException | RuntimeException e) {
            failure.addSuppressed(e);
            return false;
        }
    }

    private void writeMeta() throws IOException {
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
        meta.addProperty("mounted_by", mountedAtCheckpoint);
        meta.add("current", checkpoint.toJson());
        meta.addProperty("checkpoint_revision", checkpoint.revision());
        meta.add("journals", numbers(journalSeqs));
        if (previous != null) {
            JsonObject before = new JsonObject();
            before.add("checkpoint", previous.toJson());
            before.add("journals", numbers(previousJournals));
            meta.add("previous", before);
        }
        JsonArray recent = new JsonArray();
        historyInCheckpoint.forEach(change -> recent.add(change.toJson()));
        meta.add("recent_changes", recent);
        JsonObject wrapper = new JsonObject();
        wrapper.add("meta", meta);
        wrapper.addProperty("crc32c", crc32c(meta.toString()));
        byte[] bytes = wrapper.toString().getBytes(StandardCharsets.UTF_8);
        writeDurably(dir.resolve("meta.json"), bytes);
        writeDurably(dir.resolve("meta-copy.json"), bytes);
    }

    private static JsonArray numbers(List<Long> values) {
        JsonArray array = new JsonArray();
        values.forEach(array::add);
        return array;
    }

    private static long crc32c(String text) {
        CRC32C crc = new CRC32C();
        crc.update(text.getBytes(StandardCharsets.UTF_8));
        return crc.getValue();
    }

    private Path journalFile(long seq) {
        return dir.resolve("journal-" + seq + ".log");
    }

    /** Temporary file, forced to disk, renamed over the target: readers see old or new, never half. */
    private void writeDurably(Path target, byte[] bytes) throws IOException {
        Path temporary = target.resolveSibling(target.getFileName() + ".tmp");
        try {
            try (Storage.Output out = storage.create(temporary)) {
                out.write(ByteBuffer.wrap(bytes));
                out.force();
            }
            storage.rename(temporary, target);
        } catch (IOException | RuntimeException e) {
            try {
                storage.deleteIfExists(temporary);
            } catch (IOException cleanup) {
                e.addSuppressed(cleanup);
            }
            throw e;
        }
        storage.syncDirectory(target.getParent());
    }

    /** The folder of these files. */
    Path dir() {
        return dir;
    }
}
