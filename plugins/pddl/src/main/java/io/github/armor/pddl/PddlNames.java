// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.pddl;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.util.Collection;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import org.semanticweb.owlapi.model.IRI;

/**
 * PDDL names. PDDL ignores case and allows letters, digits, '-' and '_' after a first letter,
 * so an OWL name becomes lower case, camel case split by '-' ({@code ChargingStation} is
 * {@code charging-station}), every run of other characters one '-'; a name that would not start
 * with a letter, or is a PDDL keyword, gets {@code x-} in front. Objects whose names still
 * coincide ({@code R1} and {@code r1}) are numbered in the order of their IRIs.
 */
final class PddlNames {
    private static final Pattern NAME = Pattern.compile("[a-z][a-z0-9_-]*");
    // Words of PDDL's syntax: no name may be one of these.
    private static final Set<String> KEYWORDS = Set.of("and", "or", "not", "imply", "exists", "forall", "when",
            "either", "define", "domain", "problem");
    // Names PDDL predefines: a mapping may use them (the type object), an individual is not named so.
    private static final Set<String> PREDEFINED = Set.of("object", "number");

    private PddlNames() {}

    /** A valid PDDL name made from any text. */
    static String sanitise(String text) {
        StringBuilder name = new StringBuilder();
        boolean gap = false;
        int previous = 0;
        for (int i = 0; i < text.length(); ) {
            int c = text.codePointAt(i);
            i += Character.charCount(c);
            boolean kept = c < 128 && (Character.isLetterOrDigit(c) || c == '_' || c == '-');
            if (!kept) {
                gap = name.length() > 0;
                continue;
            }
            boolean camelStep = Character.isUpperCase(c) && (Character.isLowerCase(previous)
                    || Character.isDigit(previous));
            if ((gap || camelStep) && name.length() > 0 && name.charAt(name.length() - 1) != '-') {
                name.append('-');
            }
            gap = false;
            name.appendCodePoint(Character.toLowerCase(c));
            previous = c;
        }
        String made = name.toString();
        if (made.isEmpty() || !Character.isLetter(made.charAt(0)) || KEYWORDS.contains(made)
                || PREDEFINED.contains(made)) {
            made = "x-" + made;
        }
        return made.endsWith("-") ? made + "x" : made;
    }

    /**
     * A name the mapping gives, or, when it gives none, the sanitised short name of the entity.
     *
     * @throws ArmorException 207 for a given name that is not a PDDL name
     */
    static String given(String name, IRI entity, String where) {
        return name == null || name.isBlank() ? sanitise(entity.getShortForm()) : valid(name, "mapping " + where);
    }

    /**
     * A name as written, lower-cased (PDDL ignores case).
     *
     * @throws ArmorException 207 when it is not a PDDL name
     */
    static String valid(String name, String where) {
        String lower = name.trim().toLowerCase(Locale.ROOT);
        if (!NAME.matcher(lower).matches() || KEYWORDS.contains(lower)) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, where + ": '" + name
                    + "' is not a PDDL name (a letter, then letters, digits, '-' or '_'; not a keyword)");
        }
        return lower;
    }

    /** One name per IRI, unique, the same for the same set of IRIs whatever their order. */
    static Map<IRI, String> unique(Collection<IRI> iris) {
        Map<IRI, String> names = new LinkedHashMap<>();
        Set<String> taken = new HashSet<>();
        List<IRI> ordered = iris.stream().distinct().sorted().toList();
        for (IRI iri : ordered) {
            String base = sanitise(iri.getShortForm().isEmpty() ? iri.toString() : iri.getShortForm());
            String name = base;
            for (int n = 2; !taken.add(name); n++) {
                name = base + "-" + n;
            }
            names.put(iri, name);
        }
        return names;
    }
}
