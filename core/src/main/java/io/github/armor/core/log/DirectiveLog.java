// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.log;

import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.Objects;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Collectors;

/**
 * LOG SCREEN / LOG FILE: a line per directive and its outcome, to stderr (the node logs it at INFO)
 * and/or a file.
 *
 * <p>A directive only formats its line and queues it; one writer thread does all the writing.
 * A slow disk or a full pipe therefore delays log lines, never a directive: no lock a directive
 * takes is ever held across I/O. When the queue is full, lines are dropped and counted.
 */
public final class DirectiveLog {
    private static final int QUEUE_LINES = 10_000;
    private static final long CLOSE_WAIT_S = 5;
    private static final int SHOWN_ARGUMENT_CHARS = 200;

    /** A line and where it goes, as decided when its directive ended. */
    /** A line to write, or (text null) the signal to close {@code toFile} once the lines before it are written. */
    private record Line(String text, boolean toScreen, FileChannel toFile, CountDownLatch closed) {}

    private final PrintStream screen;
    private volatile boolean screenOn;
    private final AtomicReference<FileChannel> file = new AtomicReference<>();
    private final BlockingQueue<Line> queue = new ArrayBlockingQueue<>(QUEUE_LINES);
    private final AtomicLong dropped = new AtomicLong();
    private Thread writer;

    public DirectiveLog(PrintStream screen) {
        this.screen = screen;
    }

    /** The writer thread, started when logging is first turned on. */
    private synchronized void startWriter() {
        if (writer == null) {
            writer = new Thread(this::writeLines, "armor-directive-log");
            writer.setDaemon(true);
            writer.start();
        }
    }

    public void record(Directive directive, Response response) {
        boolean toScreen = screenOn;
        FileChannel toFile = file.get();
        if (!toScreen && toFile == null) {
            return;
        }
        String line = Instant.now() + " [" + shown(directive.clientName()) + "] " + shown(directive.referenceName())
                + ": " + shown(directive.describe()) + " "
                + directive.args().stream().map(DirectiveLog::shown).collect(Collectors.joining(", ", "[", "]"))
                + " -> " + response.exitCode() + (response.success() ? "" : " " + shown(response.errorDescription()));
        if (!queue.offer(new Line(line, toScreen, toFile, null))) {
            dropped.incrementAndGet();
        }
    }

    public void screen(boolean on) {
        if (on) {
            startWriter();
        }
        screenOn = on;
    }

    /**
     * Starts writing to {@code channel}, a regular file opened for appending
     * ({@code WritablePaths.openLog}); the file written before is closed once its lines are in.
     */
    public void file(FileChannel channel) {
        startWriter();
        closeAfterQueuedLines(file.getAndSet(channel));
    }

    /** Stops writing to the file; the lines of directives answered before are in it when this returns. */
    public void closeFile() {
        closeAfterQueuedLines(file.getAndSet(null));
    }

    private void closeAfterQueuedLines(FileChannel channel) {
        if (channel == null) {
            return;
        }
        CountDownLatch closed = new CountDownLatch(1);
        try {
            queue.put(new Line(null, false, channel, closed));
            if (!closed.await(CLOSE_WAIT_S, TimeUnit.SECONDS)) {
                screen.println("the directive log file was still being written after " + CLOSE_WAIT_S + " s");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            close(channel);
        }
    }

    private void writeLines() {
        while (true) {
            Line line;
            try {
                line = queue.take();
            } catch (InterruptedException e) {
                return;
            }
            if (line.text() == null) {
                close(line.toFile());
                line.closed().countDown();
                continue;
            }
            long lost = dropped.getAndSet(0);
            String droppedText = lost > 0 ? Instant.now() + " " + lost + " directive log line(s) dropped: the log could"
                    + " not keep up" : "";
            if (line.toScreen()) {
                // Screen lines are log lines of the node: the level first (see server/ProcessLog).
                if (lost > 0) {
                    screen.println("WARN " + droppedText);
                }
                screen.println("INFO " + line.text());
            }
            String text = (lost > 0 ? droppedText + System.lineSeparator() : "") + line.text();
            if (line.toFile() != null) {
                write(line.toFile(), text + System.lineSeparator());
            }
        }
    }

    private void write(FileChannel channel, String text) {
        try {
            ByteBuffer bytes = ByteBuffer.wrap(text.getBytes(StandardCharsets.UTF_8));
            while (bytes.hasRemaining()) {
                channel.write(bytes);
            }
        } catch (IOException e) {
            if (channel.isOpen() && file.compareAndSet(channel, null)) {
                screen.println("WARN directive log file failed, closing it: " + e);
                close(channel);
            }
        }
    }

    private void close(FileChannel channel) {
        if (channel == null) {
            return;
        }
        try {
            channel.close();
        } catch (IOException e) {
            screen.println("WARN closing the directive log file failed: " + e);
        }
    }

    /**
     * A field as the line shows it: shortened, and with every control character (line breaks,
     * terminal escapes) and backslash escaped, so that one directive is one line whatever it holds
     * and no text of a client's can pass for a line of its own.
     */
    static String shown(String text) {
        String value = Objects.toString(text, "");
        String kept = value.length() <= SHOWN_ARGUMENT_CHARS ? value : value.substring(0, SHOWN_ARGUMENT_CHARS);
        StringBuilder line = new StringBuilder(kept.length() + 16);
        kept.codePoints().forEach(c -> {
            switch (c) {
                case '\\' -> line.append("\\\\");
                case '\n' -> line.append("\\n");
                case '\r' -> line.append("\\r");
                case '\t' -> line.append("\\t");
                default -> {
                    if (Character.isISOControl(c) || c == 0x2028 || c == 0x2029) {
                        line.append(String.format("\\u%04x", c));
                    } else {
                        line.appendCodePoint(c);
                    }
                }
            }
        });
        return kept.length() == value.length() ? line.toString()
                : line + "... (" + value.length() + " characters)";
    }
}
