// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.semanticweb.owlapi.io.OWLParser;
import org.semanticweb.owlapi.io.OWLParserException;
import org.semanticweb.owlapi.io.UnparsableOntologyException;

/**
 * Turns the OWL API's "every parser failed" into what a user can act on. A document that looks
 * like one syntax gets that syntax's complaint; anything else is "not an ontology in any
 * supported syntax", with the syntaxes tried and the complaint of the first, in place of a
 * parser-internal message from whichever parser happened to read furthest.
 */
final class ParseComplaints {
    private static final int MAX_CHARS = 400;
    // The syntaxes in the order users expect them named; the OWL API's own parsers first.
    private static final List<String> ORDER = List.of("RDF/XML", "OWL/XML", "Functional", "Turtle", "Manchester",
            "N-Triples", "N-Quads", "TriG", "N3", "JSON-LD", "RDF/JSON");
    private static final Pattern SAX_POSITION = Pattern.compile(
            "org\\.xml\\.sax\\.SAXParseException;(?: systemId: [^;]*;)? lineNumber: (\\d+); columnNumber: (\\d+); ");
    private static final Pattern JAVA_PREFIX = Pattern.compile("^(?:[a-z]\\w*\\.)+[A-Z]\\w*(?:Exception|Error): ?");

    private ParseComplaints() {}

    static String explain(String document, UnparsableOntologyException e, Optional<OntologyHeaders.Syntax> looksLike) {
        // The OWL API's parser of a syntax before RDF4J's, whose messages are less direct.
        List<Map.Entry<OWLParser, OWLParserException>> attempts = new ArrayList<>(e.getExceptions().entrySet());
        attempts.sort(java.util.Comparator.comparing(a -> a.getKey().getClass().getName().contains("rio")));
        Map<String, String> bySyntax = new LinkedHashMap<>();
        for (String syntax : ORDER) {
            for (Map.Entry<OWLParser, OWLParserException> attempt : attempts) {
                if (syntax.equals(syntaxOf(attempt.getKey())) && !bySyntax.containsKey(syntax)) {
                    bySyntax.put(syntax, clean(attempt.getValue()));
                }
            }
        }
        if (bySyntax.isEmpty()) {
            return "could not parse '" + document + "': " + firstLine(e);
        }
        if (looksLike.isPresent() && bySyntax.containsKey(looksLike.get().label)) {
            String syntax = looksLike.get().label;
            return "could not parse '" + document + "' as " + syntax + ": " + bySyntax.get(syntax);
        }
        Map.Entry<String, String> first = bySyntax.entrySet().iterator().next();
        return "'" + document + "' is not an ontology in any supported syntax (tried "
                + String.join(", ", new ArrayList<>(bySyntax.keySet())) + "); the " + first.getKey()
                + " parser says: " + first.getValue();
    }

    /** The syntax a parser reads, named as users know it (the OWL API and RDF4J name them differently). */
    private static String syntaxOf(OWLParser parser) {
        String key = parser.getSupportedFormat().getKey();
        return switch (key) {
            case "RDF/XML Syntax", "RDF/XML" -> "RDF/XML";
            case "OWL/XML Syntax" -> "OWL/XML";
            case "OWL Functional Syntax" -> "Functional";
            case "Turtle Syntax", "Turtle" -> "Turtle";
            case "Manchester OWL Syntax" -> "Manchester";
            default -> key;
        };
    }

    private static String clean(OWLParserException failure) {
        String message = firstLine(failure);
        Matcher position = SAX_POSITION.matcher(message);
        if (position.find()) {
            message = position.replaceFirst("") + " (line " + position.group(1) + ", column " + position.group(2) + ")";
        }
        String previous;
        do {
            previous = message;
            message = JAVA_PREFIX.matcher(message).replaceFirst("");
        } while (!message.equals(previous));
        return cap(message);
    }

    /** An exception's message on one line, without the OWL API's preamble, capped. */
    static String firstLine(Throwable e) {
        String message = String.valueOf(e.getMessage()).strip();
        return cap(message.replaceAll("\\s+", " "));
    }

    private static String cap(String text) {
        return text.length() > MAX_CHARS ? text.substring(0, MAX_CHARS) + " ..." : text;
    }
}
