// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

import java.util.List;
import java.util.Locale;

/** One ARMOR request, field for field as {@code armor_msgs/ArmorDirectiveReq}. */
public record Directive(
        String clientName,
        String referenceName,
        String command,
        String primarySpec,
        String secondarySpec,
        List<String> args) {

    public Directive {
        clientName = nullToEmpty(clientName);
        referenceName = nullToEmpty(referenceName).trim();
        command = nullToEmpty(command).trim();
        primarySpec = nullToEmpty(primarySpec).trim();
        secondarySpec = nullToEmpty(secondarySpec).trim();
        args = args == null ? List.of() : List.copyOf(args.stream().map(Directive::nullToEmpty).toList());
    }

    public static Directive of(String client, String reference, String command, String primary,
                               String secondary, String... args) {
        return new Directive(client, reference, command, primary, secondary, List.of(args));
    }

    /** The dispatch key: command and specs upper-cased, an empty spec or "-" written as "-". */
    public String key() {
        return normalise(command) + " " + normalise(primarySpec) + " " + normalise(secondarySpec);
    }

    /** How the client wrote the combination, for error messages. */
    public String describe() {
        return (command + " " + primarySpec + " " + secondarySpec).trim().replaceAll("\\s+", " ");
    }

    private static String normalise(String spec) {
        return spec.isEmpty() ? "-" : spec.toUpperCase(Locale.ROOT);
    }

    private static String nullToEmpty(String s) {
        return s == null ? "" : s;
    }
}
