// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.log.DirectiveLog;
import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import static io.github.armor.core.CoreFixture.assertFails;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * LOG FILE ON takes a regular file inside allowed_dirs, its final target checked (issue 20
 * items 3-4), and log I/O never holds up a directive.
 */
class LogFileTest {
    @TempDir
    Path scratch;
    @TempDir
    Path outside;

    private Response logTo(CoreFixture f, Path path) {
        return f.core.execute(Directive.of("c", "", "LOG", "FILE", "ON", path.toString()));
    }

    @Test
    void anythingButARegularFileIsRefused() throws Exception {
        CoreFixture f = new CoreFixture(scratch);
        Path fifo = scratch.resolve("log.fifo");
        assertTrue(new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor() == 0);
        Response refused = logTo(f, fifo);
        assertFails(refused, 209);
        assertTrue(refused.errorDescription().contains("regular file"), refused.errorDescription());
        assertFails(logTo(f, Files.createDirectory(scratch.resolve("folder"))), 209);
    }

    @Test
    void theFinalTargetIsConfinedAlsoThroughDanglingLinks() throws Exception {
        CoreFixture f = new CoreFixture(scratch);
        Path target = outside.resolve("created.log");
        Path dangling = Files.createSymbolicLink(scratch.resolve("dangling.log"), target);
        assertFails(logTo(f, dangling), 213);
        assertFails(logTo(f, Files.createSymbolicLink(scratch.resolve("chain.log"), dangling)), 213);
        assertFails(logTo(f, Files.createSymbolicLink(scratch.resolve("out"), outside).resolve("x.log")), 213);
        assertFails(logTo(f, scratch.resolve("out/../../").resolve(outside.getFileName()).resolve("y.log")), 213);
        Files.createSymbolicLink(scratch.resolve("loop"), scratch.resolve("loop"));
        assertFails(logTo(f, scratch.resolve("loop")), 213);
        assertFalse(Files.exists(target) || Files.exists(outside.resolve("x.log")));
        // A link that stays inside is followed to its target.
        Path inside = scratch.resolve("real.log");
        assertTrue(logTo(f, Files.createSymbolicLink(scratch.resolve("inside.log"), inside)).success());
        f.core.execute(Directive.of("c", "", "GET", "ALL", "REFS"));
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (!Files.exists(inside) || !Files.readString(inside).contains("GET ALL REFS")) {
            assertTrue(System.nanoTime() < deadline, "no line reached the log file");
            Thread.sleep(20);
        }
        f.core.execute(Directive.of("c", "", "LOG", "FILE", "OFF"));
    }

    @Test
    void oneDirectiveIsOneLineWhateverItHolds() throws Exception {
        CoreFixture f = new CoreFixture(scratch);
        Path log = scratch.resolve("logs/directives.log");
        assertTrue(logTo(f, log).success());
        f.core.execute(Directive.of("evil\nclient", "nowhere", "ADD", "IND", "CLASS",
                "x\n$(touch /tmp/pwned)\r\u001b[2K\u2028\\n", "Robot"));
        f.core.execute(Directive.of("c", "", "LOG", "FILE", "OFF"));
        List<String> lines = Files.readAllLines(log);
        assertEquals(2, lines.size(), lines.toString());
        String line = lines.get(1);
        assertTrue(line.contains("[evil\\nclient]") && line.contains("x\\n$(touch /tmp/pwned)\\r\\u001b[2K"
                + "\\u2028\\\\n"), line);
    }

    @Test
    void aBlockedLogNeverHoldsUpDirectives() throws Exception {
        CountDownLatch release = new CountDownLatch(1);
        ByteArrayOutputStream written = new ByteArrayOutputStream();
        OutputStream stuck = new OutputStream() {
            @Override
            public void write(int b) {
                try {
                    release.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                synchronized (written) {
                    written.write(b);
                }
            }
        };
        DirectiveLog log = new DirectiveLog(new PrintStream(stuck, true));
        log.screen(true);
        Directive directive = Directive.of("c", "r", "QUERY", "IND", "CLASS", "x".repeat(1 << 20));
        Response answer = Response.ok(true, List.of());
        Thread directives = new Thread(() -> {
            for (int i = 0; i < 20_000; i++) {
                log.record(directive, answer);
            }
        });
        directives.start();
        // A liveness guard, not a speed target: with a lock held across the write this never ends.
        directives.join(60_000);
        assertFalse(directives.isAlive(), "recording waited for the blocked log");
        release.countDown();
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (true) {
            String text;
            synchronized (written) {
                text = written.toString();
            }
            if (text.contains("dropped")) {
                // Arguments are abbreviated in log lines: a 1 MiB argument is not written out.
                assertTrue(text.contains("(1048576 characters)"), text.substring(0, Math.min(500, text.length())));
                break;
            }
            assertTrue(System.nanoTime() < deadline, "the dropped lines were never reported");
            Thread.sleep(20);
        }
    }
}
