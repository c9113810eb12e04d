// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogManager;
import java.util.logging.LogRecord;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * How the core's log lines leave the process: every line on stderr starts with its level
 * (ERROR, WARN, INFO or DEBUG), which the node maps onto its own logger's levels.
 *
 * <p>The core logs through SLF4J (simplelogger.properties sets the line format). Reasoners that
 * log through java.util.logging (Openllet) would otherwise print two-line records of their own
 * at INFO; their records are routed here, and their INFO and below become DEBUG: a reasoner's
 * progress is chatter to a robot's operator, its warnings are not.
 */
public final class ProcessLog {
    private ProcessLog() {}

    /** The SLF4J logger every reasoner record goes through (simplelogger.properties sets its level). */
    private static final String REASONERS = "reasoner";

    /**
     * Call first thing in main, before any logger exists: with {@code -Darmor.log.level=debug}
     * (the node passes it when its own logger shows DEBUG) the core's and the reasoners' DEBUG
     * lines are written too.
     */
    public static void install() {
        if ("debug".equalsIgnoreCase(System.getProperty("armor.log.level", ""))) {
            System.setProperty("org.slf4j.simpleLogger.log.io.github.armor", "debug");
            System.setProperty("org.slf4j.simpleLogger.log." + REASONERS, "debug");
        }
        LogManager.getLogManager().reset();
        java.util.logging.Logger root = java.util.logging.Logger.getLogger("");
        root.setLevel(Level.INFO);
        root.addHandler(new ReasonerChatter());
    }

    private static final class ReasonerChatter extends Handler {
        @Override
        public void publish(LogRecord record) {
            Logger target = LoggerFactory.getLogger(REASONERS);
            String message = formatted(record);
            message = (record.getLoggerName() == null ? "" : record.getLoggerName() + ": ") + message;
            int level = record.getLevel().intValue();
            if (level >= Level.SEVERE.intValue()) {
                target.error(message, record.getThrown());
            } else if (level >= Level.WARNING.intValue()) {
                target.warn(message, record.getThrown());
            } else {
                target.debug(message, record.getThrown());
            }
        }

        /** Reasoners pass both JUL's {0} and SLF4J's {} placeholders to JUL: fill in either. */
        private static String formatted(LogRecord record) {
            String message = String.valueOf(record.getMessage());
            Object[] parameters = record.getParameters();
            if (parameters == null || parameters.length == 0) {
                return message;
            }
            if (message.contains("{0")) {
                try {
                    return java.text.MessageFormat.format(message, parameters);
                } catch (IllegalArgumentException e) {
                    return message;
                }
            }
            StringBuilder text = new StringBuilder();
            int from = 0;
            for (Object parameter : parameters) {
                int at = message.indexOf("{}", from);
                if (at < 0) {
                    break;
                }
                text.append(message, from, at).append(parameter);
                from = at + 2;
            }
            return text.append(message.substring(from)).toString();
        }

        @Override
        public void flush() {
            // SimpleLogger writes through at once.
        }

        @Override
        public void close() {
            // nothing held
        }
    }
}
