// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import io.github.armor.core.api.AcknowledgedChange;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig.Durability;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reference.OntologyFiles;
import io.github.armor.core.reference.Reference;
import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.OWLDocumentFormat;
import org.semanticweb.owlapi.model.OWLOntology;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Every reference's journal and checkpoints under one state directory
 * ({@code <state_dir>/refs/<escaped name>/}). Nothing is acknowledged before it is recorded here.
 */
public final class StateStore {
    private static final Logger LOG = LoggerFactory.getLogger(StateStore.class);

    private static final long LOCK_WAIT_NANOS = 10_000_000_000L;

    private final Path refsDir;
    private FileLock stateLock;
    private final Durability durability;
    private final Storage storage;
    private final StateDamage damage;
    private final ConcurrentHashMap<String, ReferenceStore> stores = new ConcurrentHashMap<>();
    private final ExecutorService checkpointWriter;

    public StateStore(Durability durability) {
        this(durability, Storage.FILES, Executors.newSingleThreadExecutor(r -> {
            Thread thread = new Thread(r, "armor-checkpoint-writer");
            thread.setDaemon(true);
            return thread;
        }));
    }

    /**
     * A state store whose files go through {@code storage} and whose checkpoints are written by
     * {@code checkpointWriter} (tests pass a storage that fails or loses power on cue, and a
     * writer that runs in the caller's thread).
     */
    public StateStore(Durability durability, Storage storage, ExecutorService checkpointWriter) {
        this.durability = durability;
        this.storage = storage;
        this.checkpointWriter = checkpointWriter;
        this.refsDir = durability.stateDir().resolve("refs");
        this.damage = new StateDamage(storage, durability.stateDir());
    }

    /**
     * A reference as it was: its checkpoint loaded, the records to replay, its mount holder, its
     * revision, its latest acknowledged changes (for GET REF CHANGES), and what of it could not be
     * brought back.
     */
    public record Restorable(String name, OWLOntology ontology, Reference.Settings settings, String mountedBy,
                             List<AcknowledgedChange> records, long revision, ReferenceStore store,
                             List<AcknowledgedChange> history, List<String> problems, Path setAside) {}

    /**
     * Reads every reference found on disk (or, when restoring is off, deletes them for a clean
     * start), each up to its last intact point. A reference that cannot be restored at all is
     * moved into {@code damaged/} and reported, never fatal.
     */
    public List<Restorable> recoverAll(OntologyFiles files) {
        List<Restorable> found = new ArrayList<>();
        try {
            lockStateDirectory();
            if (!durability.restore()) {
                deleteTree(refsDir);
            }
            deleteTree(durability.stateDir().resolve("dropped"));
            Files.createDirectories(refsDir);
            damage.readEarlier();
            try (Stream<Path> dirs = Files.list(refsDir)) {
                for (Path dir : dirs.sorted().toList()) {
                    Path setAside = damage.newEntry(dir.getFileName().toString());
                    try {
                        ReferenceStore.Recovered r = ReferenceStore.recover(storage, dir, durability,
                                (checkpoint, settings, formatClass) -> restoreFormat(files.loadTrusted(checkpoint,
                                        importsDir(settings)), formatClass), setAside);
                        found.add(restorable(r));
                    } catch (ReferenceStore.Unfinished e) {
                        LOG.info("{}: {}; deleted", dir, e.getMessage());
                        deleteTree(dir);
                    } catch (IOException | RuntimeException e) {
                        List<String> problems = e instanceof ReferenceStore.Unrestorable u ? u.problems
                                : List.of(e.toString());
                        try {
                            storage.createDirectories(setAside.getParent());
                            storage.rename(dir, setAside);
                        } catch (IOException move) {
                            LOG.error("cannot move {} aside: {}", dir, move.toString());
                        }
                        damage.restored(unescape(dir.getFileName().toString()), false, -1, problems, setAside);
                    }
                }
            }
        } catch (IOException e) {
            throw new IllegalStateException("state directory " + refsDir + " is unusable: " + e, e);
        }
        return IncompleteLists.takenOut(found);
    }

    static Restorable restorable(ReferenceStore.Recovered r) {
        return new Restorable(r.name(), r.ontology(), r.settings(), r.mountedBy(), r.records(), r.revision(),
                r.store(), r.history(), r.problems(), r.setAside());
    }

    private static Path importsDir(Reference.Settings settings) {
        return settings.source() == null || settings.source().startsWith("http")
                ? null : Path.of(settings.source()).toAbsolutePath().getParent();
    }

    /**
     * Holds the state directory for this process's lifetime: two cores replaying and writing the
     * same journals would corrupt them. The lock file names the node holding it. A predecessor
     * core of this same node that is still dying gets a few seconds; another live node gets none.
     */
    private void lockStateDirectory() throws IOException {
        Files.createDirectories(durability.stateDir());
        FileChannel channel = FileChannel.open(durability.stateDir().resolve("lock"), StandardOpenOption.CREATE,
                StandardOpenOption.READ, StandardOpenOption.WRITE);
        long node = ProcessHandle.current().parent().map(ProcessHandle::pid).orElse(-1L);
        long deadline = System.nanoTime() + LOCK_WAIT_NANOS;
        while ((stateLock = channel.tryLock()) == null) {
            long holder = holderNode(channel);
            boolean otherLiveNode = holder > 0 && holder != node
                    && ProcessHandle.of(holder).map(ProcessHandle::isAlive).orElse(false);
            if (otherLiveNode || System.nanoTime() > deadline) {
                channel.close();
                throw new StateDirectoryInUse("state directory " + durability.stateDir() + " is in use by another"
                        + " ARMOR node" + (holder > 0 ? " (pid " + holder + ")" : "")
                        + "; give each node its own state_dir");
            }
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while waiting for the state directory", e);
            }
        }
        channel.truncate(0);
        channel.write(java.nio.ByteBuffer.wrap(("node " + node + " core " + ProcessHandle.current().pid() + "\n")
                .getBytes(StandardCharsets.US_ASCII)), 0);
    }

    /** The pid of the node named in a lock file, or -1. */
    private static long holderNode(FileChannel channel) {
        try {
            java.nio.ByteBuffer text = java.nio.ByteBuffer.allocate(100);
            channel.read(text, 0);
            String[] words = new String(text.array(), 0, text.position(), StandardCharsets.US_ASCII).trim().split(" ");
            return words.length >= 2 && words[0].equals("node") ? Long.parseLong(words[1]) : -1;
        } catch (IOException | NumberFormatException e) {
            return -1;
        }
    }

    /** Another ARMOR node holds the state directory. */
    public static final class StateDirectoryInUse extends IllegalStateException {
        StateDirectoryInUse(String message) {
            super(message);
        }
    }

    /**
     * Takes over the files of a restored reference for its further changes, and reports what its
     * restore could not bring back: damage found in its files, and journal records that failed
     * when replayed ({@code replayFailures}).
     */
    public void adopt(Restorable restored, long revision, List<String> replayFailures) {
        stores.put(restored.name(), restored.store());
        List<String> problems = new ArrayList<>(restored.problems());
        problems.addAll(replayFailures);
        if (!problems.isEmpty()) {
            damage.restored(restored.name(), true, revision, problems, restored.setAside());
        }
    }

    /** A reference whose files were read but which could not be made again: reported, its files left. */
    public void notRestored(Restorable restorable, String why) {
        restorable.store().close();
        damage.restored(restorable.name(), false, -1, List.of(why + "; its files were left in "
                + restorable.store().dir() + " for the next start"), restorable.setAside());
    }

    public void created(Reference reference) {
        Path dir = dirFor(reference.name());
        try {
            stores.put(reference.name(), ReferenceStore.create(storage, dir, reference, durability));
        } catch (IOException | RuntimeException failure) {
            // An ontology the OWL API cannot copy or write (an ontology IRI it refuses) cannot be kept either.
            IOException e = failure instanceof IOException io ? io : new IOException(failure.toString(), failure);
            try {
                deleteTree(dir);
            } catch (IOException cleanup) {
                LOG.warn("could not delete the unfinished state of '{}': {}", reference.name(), cleanup.toString());
            }
            throw notDurable("cannot keep reference '" + reference.name() + "' in the state directory", e);
        }
    }

    /**
     * Records acknowledged directives with the revision they give the reference; on failure the
     * caller must undo them (nothing was acknowledged).
     */
    private void record(Reference reference, AcknowledgedChange change, ListSpan list) {
        ReferenceStore store = stores.get(reference.name());
        if (store == null) {
            throw new ArmorException(ExitCode.INTERNAL_ERROR, "reference '" + reference.name() + "' has no journal");
        }
        try {
            store.record(change, list);
            damage.accepting(reference.name());
        } catch (IOException e) {
            damage.refusing(reference.name(), e.getMessage() == null ? e.toString() : e.getMessage());
            throw notDurable("cannot write the journal of '" + reference.name() + "'", e);
        }
    }

    /**
     * Records one change on each of several references (an atomic list): all or none. When one
     * cannot be written, those already written are taken back out of their journals. Each record
     * of a list over several references names the list and all of them, so that a crash between
     * two of its records restores none of it (IncompleteLists).
     */
    public void recordAll(Map<Reference, AcknowledgedChange> changes) {
        List<Reference> written = new ArrayList<>();
        Map<String, Long> revisions = new java.util.LinkedHashMap<>();
        changes.forEach((reference, change) -> revisions.put(reference.name(), change.revision()));
        ListSpan list = changes.size() > 1 ? ListSpan.fresh(revisions) : null;
        try {
            for (Map.Entry<Reference, AcknowledgedChange> change : changes.entrySet()) {
                record(change.getKey(), change.getValue(), list);
                written.add(change.getKey());
            }
        } catch (ArmorException e) {
            for (Reference reference : written) {
                try {
                    stores.get(reference.name()).retractLast();
                } catch (IOException retract) {
                    // Cut before the next append (which fails until it can be), or at restore: a
                    // later record of the same revision marks it refused.
                    LOG.error("could not take the refused list's record back out of the journal of '{}' yet: {}",
                            reference.name(), retract.toString());
                }
            }
            throw e;
        }
    }

    private static ArmorException notDurable(String what, IOException e) {
        return new ArmorException(ExitCode.NOT_DURABLE, "not durable: " + what + " ("
                + (e.getMessage() == null ? e.toString() : e.getMessage()) + "); nothing changed", e);
    }

    /** Checkpoints the reference if due; the caller holds its lock. */
    public void checkpointIfDue(Reference reference) {
        ReferenceStore store = stores.get(reference.name());
        if (store != null) {
            store.maybeCheckpoint(reference, checkpointWriter);
        }
    }

    /**
     * Forgets a reference's state before it is unloaded: its folder is moved out of {@code refs/}
     * (one rename, forced to disk), then deleted. When the move fails the reference must stay:
     * a restart would bring it back.
     */
    public void dropped(Reference reference) {
        ReferenceStore store = stores.get(reference.name());
        if (store == null) {
            return;
        }
        Path gone = durability.stateDir().resolve("dropped").resolve(store.dir().getFileName() + "-" + System.nanoTime());
        try {
            storage.createDirectories(gone.getParent());
            storage.rename(store.dir(), gone);
        } catch (IOException e) {
            throw notDurable("cannot remove the state of '" + reference.name() + "'", e);
        }
        try {
            storage.syncDirectory(refsDir);
        } catch (IOException e) {
            // Not known to be on the disk: put the folder back and refuse. If even that fails, the
            // folder is out of refs/ and the DROP goes on (only a power cut now could undo it).
            try {
                storage.rename(gone, store.dir());
                throw notDurable("cannot remove the state of '" + reference.name() + "'", e);
            } catch (IOException back) {
                LOG.error("the DROP of '{}' could not be forced to disk nor undone: {}", reference.name(),
                        back.toString());
            }
        }
        stores.remove(reference.name());
        store.close();
        try {
            deleteTree(gone);
        } catch (IOException e) {
            LOG.warn("could not delete the state of dropped reference '{}' ({}); the next start does", reference.name(),
                    e.toString());
        }
    }

    /**
     * What the state directory could not bring back or cannot keep, one JSON object per problem
     * (GET STATE DAMAGE): restores that found damage, references whose changes are refused now.
     */
    public List<String> damage() {
        return damage.lines();
    }

    /** Lets checkpoints in progress finish, closes the journals and releases the directory. */
    public synchronized void close() {
        checkpointWriter.shutdown();
        try {
            if (!checkpointWriter.awaitTermination(60, java.util.concurrent.TimeUnit.SECONDS)) {
                LOG.warn("a checkpoint was still being written at close; the previous one stays in use");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        stores.values().forEach(ReferenceStore::close);
        stores.clear();
        if (stateLock != null) {
            try {
                stateLock.channel().close();
            } catch (IOException e) {
                LOG.warn("could not release the state directory lock: {}", e.toString());
            }
            stateLock = null;
        }
    }

    private Path dirFor(String name) {
        StringBuilder escaped = new StringBuilder();
        for (byte b : name.getBytes(StandardCharsets.UTF_8)) {
            char c = (char) (b & 0xff);
            if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-') {
                escaped.append(c);
            } else {
                escaped.append('%').append(String.format("%02X", b & 0xff));
            }
        }
        return refsDir.resolve(escaped.toString());
    }

    private static String unescape(String escaped) {
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        for (int i = 0; i < escaped.length(); i++) {
            char c = escaped.charAt(i);
            if (c == '%' && i + 2 < escaped.length()) {
                bytes.write(Integer.parseInt(escaped.substring(i + 1, i + 3), 16));
                i += 2;
            } else {
                bytes.write(c);
            }
        }
        return bytes.toString(StandardCharsets.UTF_8);
    }

    private static OWLOntology restoreFormat(OWLOntology ontology, String formatClass) {
        if (formatClass.isEmpty()) {
            return ontology;
        }
        try {
            OWLDocumentFormat format = (OWLDocumentFormat) Class.forName(formatClass).getDeclaredConstructor()
                    .newInstance();
            OWLDocumentFormat loaded = ontology.getOWLOntologyManager().getOntologyFormat(ontology);
            if (loaded != null && loaded.isPrefixOWLDocumentFormat() && format.isPrefixOWLDocumentFormat()) {
                format.asPrefixOWLDocumentFormat().copyPrefixesFrom(loaded.asPrefixOWLDocumentFormat());
            }
            ontology.getOWLOntologyManager().setOntologyFormat(ontology, format);
        } catch (ReflectiveOperationException | ClassCastException e) {
            LOG.warn("document format {} not restored, SAVE will default to the checkpoint's", formatClass);
        }
        return ontology;
    }

    private static void deleteTree(Path root) throws IOException {
        if (!Files.exists(root)) {
            return;
        }
        try (Stream<Path> files = Files.walk(root)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(file);
            }
        }
    }
}
