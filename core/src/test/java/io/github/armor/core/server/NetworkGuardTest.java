// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** With web loading off the core process opens no connection, whatever the scheme (issue 20 item 2). */
class NetworkGuardTest {
    @Test
    void noSchemeReachesTheNetworkAndLocalFilesStillRead() throws Exception {
        AtomicInteger connections = new AtomicInteger();
        try (ServerSocket listener = new ServerSocket(0, 50, InetAddress.getLoopbackAddress())) {
            listener.setSoTimeout(200);
            Thread accepting = new Thread(() -> {
                while (!listener.isClosed()) {
                    try (Socket ignored = listener.accept()) {
                        connections.incrementAndGet();
                    } catch (SocketTimeoutException e) {
                        // keep listening
                    } catch (IOException e) {
                        return;
                    }
                }
            });
            accepting.start();
            String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            Process probe = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                    NetworkGuardProbe.class.getName(), String.valueOf(listener.getLocalPort()))
                    .redirectErrorStream(true).start();
            String output = new String(probe.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertEquals(0, probe.waitFor(), output);
            listener.close();
            accepting.join();
            List<String> lines = output.lines().filter(l -> !l.startsWith("SLF4J")).toList();
            assertEquals(6, lines.stream().filter(l -> l.startsWith("refused") || l.startsWith("read local")).count(),
                    output);
            assertTrue(lines.stream().noneMatch(l -> l.startsWith("OPENED") || l.startsWith("WRONG")), output);
        }
        assertEquals(0, connections.get(), "the guarded process connected to the listener");
    }
}
