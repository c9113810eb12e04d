// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Every line the core writes on stderr starts with its level, which the node maps onto its
 * logger: directives at INFO, reasoner chatter at DEBUG (and only when asked for), reasoner
 * warnings at WARN (issue 18 item 4, issue 11 item 10).
 */
class ProcessLogTest {
    private static List<String> stderrOf(String... jvmOptions) throws Exception {
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        command.addAll(List.of(jvmOptions));
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), ProcessLogProbe.class.getName()));
        Process probe = new ProcessBuilder(command).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        String output = new String(probe.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, probe.waitFor(), output);
        return output.lines().filter(l -> !l.startsWith("SLF4J")).toList();
    }

    @Test
    void eachLineStartsWithItsLevelAndReasonerChatterIsHiddenByDefault() throws Exception {
        List<String> lines = stderrOf();
        assertTrue(lines.contains("WARN openllet.core.KnowledgeBaseImpl: ignoring unsupported axiom SWRL built-in"),
                String.join("\n", lines));
        assertTrue(lines.contains("INFO restored reference 'r'"), String.join("\n", lines));
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("INFO ") && l.contains("[c] r: QUERY IND CLASS [Room] -> 0")),
                String.join("\n", lines));
        assertEquals(3, lines.size(), "reasoner INFO, core DEBUG and library INFO stay out:\n" + String.join("\n", lines));
    }

    @Test
    void reasonerInfoBecomesDebugWhenTheNodeShowsDebug() throws Exception {
        List<String> lines = stderrOf("-Darmor.log.level=debug");
        assertTrue(lines.contains("DEBUG openllet.core.KnowledgeBaseImpl: classified 42 classes in 7 ms"),
                String.join("\n", lines));
        assertTrue(lines.contains("DEBUG core detail"), String.join("\n", lines));
        assertTrue(lines.stream().noneMatch(l -> l.contains("library chatter")), String.join("\n", lines));
        assertTrue(lines.stream().allMatch(l -> l.matches("^(ERROR|WARN|INFO|DEBUG) .*")), String.join("\n", lines));
    }
}
