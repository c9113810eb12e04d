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
    private final ConcurrentHashMap<String, ReferenceStore> stores = new ConcurrentHashMap<>();
    private final ExecutorService checkpointWriter = Executors.newSingleThreadExecutor(r -> {
        Thread thread = new Thread(r, "armor-checkpoint-writer");
        thread.setDaemon(true);
        return thread;
    });

    public StateStore(Durability durability) {
        this.durability = durability;
        this.refsDir = durability.stateDir().resolve("refs");
    }

    /**
     * A reference as it was: its checkpoint loaded, the records to replay, its mount holder, its
     * revision, and its latest acknowledged changes (for GET REF CHANGES).
     */
    public record Restorable(String name, OWLOntology ontology, Reference.Settings settings, String mountedBy,
                             List<AcknowledgedChange> records, long revision, ReferenceStore store,
                             List<AcknowledgedChange> history) {}

    /**
     * Reads every reference found on disk (or, when restoring is off, deletes them for a clean
     * start). A reference whose files cannot be read is moved aside and reported, not fatal.
     */
    public List<Restorable> recoverAll(OntologyFiles files) {
        List<Restorable> found = new ArrayList<>();
        try {
            lockStateDirectory();
            if (!durability.restore()) {
                deleteTree(refsDir);
            }
            Files.createDirectories(refsDir);
            try (Stream<Path> dirs = Files.list(refsDir)) {
                for (Path dir : dirs.sorted().toList()) {
                    try {
                        ReferenceStore.Recovered r = ReferenceStore.recover(dir, durability);
                        Path importsDir = r.settings().source() == null || r.settings().source().startsWith("http")
                                ? null : Path.of(r.settings().source()).toAbsolutePath().getParent();
                        OWLOntology ontology = files.loadTrusted(r.checkpoint(), importsDir);
                        restoreFormat(ontology, r.formatClass());
                        found.add(new Restorable(r.name(), ontology, r.settings(), r.mountedBy(), r.records(),
                                r.revision(), r.store(), r.history()));
                    } catch (IOException | RuntimeException e) {
                        Path aside = durability.stateDir().resolve("unreadable").resolve(dir.getFileName()
                                + "-" + System.currentTimeMillis());
                        LOG.error("cannot restore {}: {}; moved to {}", dir, e, aside);
                        Files.createDirectories(aside.getParent());
                        Files.move(dir, aside);
                    }
                }
            }
        } catch (IOException e) {
            throw new IllegalStateException("state directory " + refsDir + " is unusable: " + e, e);
        }
        return found;
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

    /** Takes over the files of a restored reference for its further changes. */
    public void adopt(Restorable restored) {
        stores.put(restored.name(), restored.store());
    }

    public void created(Reference reference) {
        try {
            stores.put(reference.name(), ReferenceStore.create(dirFor(reference.name()), reference, durability));
        } catch (IOException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "cannot keep reference '" + reference.name()
                    + "' in the state directory: " + e.getMessage(), e);
        }
    }

    /**
     * Records acknowledged directives with the revision they give the reference; on failure the
     * caller must undo them (nothing was acknowledged).
     */
    public void record(Reference reference, AcknowledgedChange change) {
        ReferenceStore store = stores.get(reference.name());
        if (store == null) {
            throw new ArmorException(ExitCode.INTERNAL_ERROR, "reference '" + reference.name() + "' has no journal");
        }
        try {
            store.record(change);
        } catch (IOException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "cannot write the journal of '" + reference.name()
                    + "', change undone: " + e.getMessage(), e);
        }
    }

    /** Checkpoints the reference if due; the caller holds its lock. */
    public void checkpointIfDue(Reference reference) {
        ReferenceStore store = stores.get(reference.name());
        if (store != null) {
            store.maybeCheckpoint(reference, checkpointWriter);
        }
    }

    public void dropped(Reference reference) {
        ReferenceStore store = stores.remove(reference.name());
        if (store == null) {
            return;
        }
        try {
            store.delete();
        } catch (IOException e) {
            LOG.error("could not delete the state of dropped reference '{}'", reference.name(), e);
        }
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

    private static void restoreFormat(OWLOntology ontology, String formatClass) {
        if (formatClass.isEmpty()) {
            return;
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
