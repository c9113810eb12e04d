// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

import java.util.List;

/**
 * How large a request (and a SPARQL answer) may be. A request over a limit is refused with
 * {@link ExitCode#TOO_LARGE} before any work: nothing is parsed, changed, journaled or kept.
 * Sizes are counted in UTF-8 bytes, as the strings travel in ROS messages. The figures are
 * documented in docs/commands.md (size limits); change both together.
 */
public final class SizeLimits {
    /** client_name, reference_name, command and the two specs, each. */
    public static final int NAME_BYTES = 1024;
    /** Each argument: room for any name, IRI, class expression, rule or query a robot sends. */
    public static final int ARGUMENT_BYTES = 1 << 20;
    /** All strings of one directive together. */
    public static final int DIRECTIVE_BYTES = 4 << 20;
    /** Directives in one list (armor_interface_serialized_srv). */
    public static final int LIST_DIRECTIVES = 10_000;
    /** All strings of one list together; its journal record stays well under the journal's 64 MiB. */
    public static final int LIST_BYTES = 8 << 20;
    /** The rows of one SPARQL answer, rendered. */
    public static final int ANSWER_BYTES = 32 << 20;
    /**
     * A frame between the node and the core, either way (armor_service/wire.py reads no larger
     * one): every answer, a list's answers together included, must fit in one.
     */
    public static final int FRAME_BYTES = 256 << 20;
    // What a frame holds besides the responses: its id, the list's own fields.
    private static final int FRAME_MARGIN = 64 << 10;
    // A response's field names and values besides its strings, and each string's quotes and comma.
    private static final int RESPONSE_OVERHEAD = 160;
    private static final int STRING_OVERHEAD = 3;
    private static final int ITEM_OVERHEAD = 24;

    private SizeLimits() {}

    /** Refuses a directive that exceeds a limit; returns its size in bytes. */
    public static long check(Directive directive) {
        long total = 0;
        total += name("client_name", directive.clientName());
        total += name("reference_name", directive.referenceName());
        total += name("command", directive.command());
        total += name("primary_command_spec", directive.primarySpec());
        total += name("secondary_command_spec", directive.secondarySpec());
        List<String> args = directive.args();
        for (int i = 0; i < args.size(); i++) {
            long size = utf8Bytes(args.get(i));
            if (size > ARGUMENT_BYTES) {
                throw tooLarge("argument " + i + " of " + directive.describe() + " is " + size(size)
                        + "; the limit is " + size(ARGUMENT_BYTES) + " per argument");
            }
            total += size;
        }
        if (total > DIRECTIVE_BYTES) {
            throw tooLarge(directive.describe() + " is " + size(total) + " in all; the limit is "
                    + size(DIRECTIVE_BYTES) + " per directive");
        }
        return total;
    }

    /** Refuses a list that exceeds a limit, or any directive of it that does. */
    public static void checkList(List<Directive> directives) {
        if (directives.size() > LIST_DIRECTIVES) {
            throw tooLarge("the list holds " + directives.size() + " directives; the limit is " + LIST_DIRECTIVES);
        }
        long total = 0;
        for (int i = 0; i < directives.size(); i++) {
            try {
                total += check(directives.get(i));
            } catch (ArmorException e) {
                throw tooLarge("directive " + i + ": " + e.getMessage());
            }
        }
        if (total > LIST_BYTES) {
            throw tooLarge("the list is " + size(total) + " in all; the limit is " + size(LIST_BYTES) + " per list");
        }
    }

    /**
     * Refuses what the answers of a list add up to once they outgrow a frame, so that the list is
     * answered 221 (and undone) instead of a frame the node cannot read.
     *
     * @param answered the frame bytes of the list's earlier answers
     * @return the frame bytes of its answers with {@code response}
     */
    public static long addAnswer(long answered, Response response) {
        long total = answered + frameBytes(response);
        if (total > FRAME_BYTES - FRAME_MARGIN) {
            throw tooLarge("the answers of this list come to more than " + size(FRAME_BYTES - FRAME_MARGIN)
                    + ", what one frame from the core to the node carries (" + size(FRAME_BYTES)
                    + "); ask in smaller lists");
        }
        return total;
    }

    /** How many bytes a response takes in a frame (JSON-escaped UTF-8), counted without encoding it. */
    public static long frameBytes(Response response) {
        long bytes = RESPONSE_OVERHEAD + jsonBytes(response.errorDescription());
        for (String object : response.queriedObjects()) {
            bytes += STRING_OVERHEAD + jsonBytes(object);
        }
        for (Response.QueryItem item : response.sparqlQueriedObjects()) {
            bytes += ITEM_OVERHEAD + jsonBytes(item.key()) + jsonBytes(item.value());
        }
        return bytes;
    }

    /** The bytes of {@code text} as a JSON string's content: UTF-8, escapes counted as written. */
    static long jsonBytes(String text) {
        long bytes = 0;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '"' || c == '\\' || c == '\n' || c == '\r' || c == '\t' || c == '\b' || c == '\f') {
                bytes += 2;
            } else if (c < 0x20 || c == '\u2028' || c == '\u2029') {
                bytes += 6;
            } else {
                bytes += charBytes(text, i);
            }
        }
        return bytes;
    }

    /** The UTF-8 size of {@code text}, counted without encoding it. */
    public static long utf8Bytes(String text) {
        long bytes = 0;
        for (int i = 0; i < text.length(); i++) {
            bytes += charBytes(text, i);
        }
        return bytes;
    }

    public static ArmorException tooLarge(String description) {
        return new ArmorException(ExitCode.TOO_LARGE, description + " (docs/commands.md#size-limits); nothing done");
    }

    public static String size(long bytes) {
        return String.format(java.util.Locale.ROOT, "%,d bytes", bytes);
    }

    private static long name(String field, String value) {
        long size = utf8Bytes(value);
        if (size > NAME_BYTES) {
            throw tooLarge(field + " is " + size(size) + "; the limit is " + size(NAME_BYTES));
        }
        return size;
    }

    // A surrogate pair is four bytes: two each.
    private static int charBytes(String text, int i) {
        char c = text.charAt(i);
        return c < 0x80 ? 1 : c < 0x800 ? 2 : Character.isSurrogate(c) ? 2 : 3;
    }
}
