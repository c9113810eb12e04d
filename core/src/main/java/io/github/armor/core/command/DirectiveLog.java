// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import java.io.IOException;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;

/** LOG SCREEN / LOG FILE: a line per directive and its outcome, to stderr and/or a file. */
public final class DirectiveLog {
    private final PrintStream screen;
    private boolean screenOn;
    private Writer file;

    public DirectiveLog(PrintStream screen) {
        this.screen = screen;
    }

    public synchronized void record(Directive directive, Response response) {
        if (!screenOn && file == null) {
            return;
        }
        String line = Instant.now() + " [" + directive.clientName() + "] " + directive.referenceName() + ": "
                + directive.describe() + " " + directive.args() + " -> " + response.exitCode()
                + (response.success() ? "" : " " + response.errorDescription());
        if (screenOn) {
            screen.println(line);
        }
        if (file != null) {
            try {
                file.write(line + System.lineSeparator());
                file.flush();
            } catch (IOException e) {
                screen.println("directive log file failed, closing it: " + e);
                closeFile();
            }
        }
    }

    public synchronized void screen(boolean on) {
        screenOn = on;
    }

    public synchronized void file(Path path) {
        closeFile();
        try {
            file = Files.newBufferedWriter(path, StandardCharsets.UTF_8, StandardOpenOption.CREATE,
                    StandardOpenOption.APPEND);
        } catch (IOException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "cannot open log file '" + path + "': " + e.getMessage(), e);
        }
    }

    public synchronized void closeFile() {
        if (file != null) {
            try {
                file.close();
            } catch (IOException e) {
                screen.println("closing the directive log file failed: " + e);
            }
            file = null;
        }
    }
}
