// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import java.io.File;
import java.io.FilterInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.semanticweb.owlapi.io.FileDocumentSource;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * How far a LOAD has got: bytes of the file read by the parser, then the reasoner starting. A
 * load that takes long is logged every few seconds (the node shows it at INFO), and GET LOAD
 * PROGRESS lets a client draw a progress bar while its LOAD is in flight.
 */
public final class LoadProgress implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(LoadProgress.class);
    private static final long REPORT_EVERY_S = 5;
    // A LOAD this slow, or of a file this large, says what it read and how long it took.
    private static final long NOTEWORTHY_MS = 2_000;
    private static final long NOTEWORTHY_BYTES = 10_000_000;
    private static final Map<String, LoadProgress> RUNNING = new ConcurrentHashMap<>();
    private static final ThreadLocal<LoadProgress> CURRENT = new ThreadLocal<>();
    private static final ScheduledExecutorService REPORTER = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread thread = new Thread(r, "armor-load-progress");
        thread.setDaemon(true);
        return thread;
    });

    private final String reference;
    private final String source;
    private final long totalBytes;
    private final long started = System.nanoTime();
    private final AtomicLong read = new AtomicLong();
    private final ScheduledFuture<?> report;
    private volatile String phase = "reading";

    private LoadProgress(String reference, String source, long totalBytes) {
        this.reference = reference;
        this.source = source;
        this.totalBytes = totalBytes;
        this.report = REPORTER.scheduleAtFixedRate(this::log, REPORT_EVERY_S, REPORT_EVERY_S, TimeUnit.SECONDS);
    }

    /** Starts tracking the LOAD of {@code reference} from a file (or URL) on this thread. */
    public static LoadProgress start(String reference, String source) {
        long size = source == null ? -1 : new File(source).length();
        LoadProgress progress = new LoadProgress(reference, source, size > 0 ? size : -1);
        RUNNING.put(reference, progress);
        CURRENT.set(progress);
        return progress;
    }

    /** One line per LOAD in flight: reference, phase, bytes read, bytes in all (-1 unknown), elapsed ms. */
    public static List<String> running() {
        return RUNNING.values().stream().map(p -> p.reference + " " + p.phase + " " + p.read.get() + " "
                + p.totalBytes + " " + p.elapsedMs()).sorted().toList();
    }

    /** A file source whose reads count towards the LOAD running on this thread. */
    static FileDocumentSource counted(File file) {
        LoadProgress progress = CURRENT.get();
        if (progress == null) {
            return new FileDocumentSource(file);
        }
        return new FileDocumentSource(file) {
            @Override
            public Optional<InputStream> getInputStream() {
                progress.read.set(0);  // each parser tried reads from the start
                return super.getInputStream().map(stream -> new FilterInputStream(stream) {
                    @Override
                    public int read() throws IOException {
                        int b = super.read();
                        if (b >= 0) {
                            progress.read.incrementAndGet();
                        }
                        return b;
                    }

                    @Override
                    public int read(byte[] buffer, int offset, int length) throws IOException {
                        int n = super.read(buffer, offset, length);
                        if (n > 0) {
                            progress.read.addAndGet(n);
                        }
                        return n;
                    }
                });
            }
        };
    }

    /** The document is parsed: says what it held when that took a while, and what comes next. */
    public void parsed(long axioms, long individuals, String reasoner) {
        phase = "starting-reasoner";
        if (noteworthy()) {
            LOG.info("loading '{}': read {} in {} s: {} axioms, {} individuals; starting {}", reference, source,
                    elapsedMs() / 1000, axioms, individuals, reasoner);
        }
    }

    @Override
    public void close() {
        report.cancel(false);
        RUNNING.remove(reference, this);
        CURRENT.remove();
        if (noteworthy()) {
            LOG.info("loading '{}' took {} s", reference, elapsedMs() / 1000);
        }
    }

    /**
     * Slow, or large: how fast a given file parses depends on the machine and its load, so a
     * large file is reported whatever the time it took (a test of a 14 MB file saw the
     * counts line appear on a busy machine and not on a quiet one).
     */
    private boolean noteworthy() {
        return elapsedMs() >= NOTEWORTHY_MS || totalBytes >= NOTEWORTHY_BYTES;
    }

    private long elapsedMs() {
        return TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
    }

    private void log() {
        if (phase.equals("reading")) {
            LOG.info("loading '{}' from {}: {} s, {}", reference, source, elapsedMs() / 1000, totalBytes > 0
                    ? String.format("%.1f of %.1f MB read (%d%%)", read.get() / 1e6, totalBytes / 1e6,
                    Math.min(100, 100 * read.get() / totalBytes)) : read.get() / 1_000_000 + " MB read");
        } else {
            LOG.info("loading '{}': {} s, {}", reference, elapsedMs() / 1000, phase.replace('-', ' '));
        }
    }
}
