// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.semanticweb.owlapi.util.SAXParsers;
import org.xml.sax.Attributes;
import org.xml.sax.SAXException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * What the head of an ontology document says, read without parsing the whole document: the
 * syntax it is probably written in, and the ontology IRI it declares. Imports are matched to
 * the documents of a folder by that IRI, whatever the syntax (the OWL API's own folder mapper
 * reads RDF/XML with an xml:base and .ofn/.omn files only).
 */
final class OntologyHeaders {
    /** The declaration is in the first lines of every document written by a tool; this is plenty. */
    static final int HEAD_BYTES = 64 * 1024;

    private static final String OWL = "http://www.w3.org/2002/07/owl#";
    private static final String RDF = "http://www.w3.org/1999/02/22-rdf-syntax-ns#";
    private static final String XML = "http://www.w3.org/XML/1998/namespace";

    private static final Pattern XML_ROOT = Pattern.compile(
            "^(?:<\\?xml[^>]*>|<!--.*?-->|<!DOCTYPE[^\\[>]*(?:\\[.*?\\])?\\s*>|\\s)*<([A-Za-z_][\\w.-]*:)?([A-Za-z_][\\w.-]*)[\\s>/]",
            Pattern.DOTALL);
    private static final Pattern FUNCTIONAL = Pattern.compile("(?m)^\\s*(?:Prefix|Ontology)\\s*\\(");
    private static final Pattern FUNCTIONAL_IRI = Pattern.compile("(?m)^\\s*Ontology\\s*\\(\\s*<([^>\\s]+)>");
    private static final Pattern MANCHESTER = Pattern.compile("(?m)^\\s*(?:Prefix|Ontology)\\s*:");
    private static final Pattern MANCHESTER_IRI = Pattern.compile("(?m)^\\s*Ontology\\s*:\\s*<([^>\\s]+)>");
    private static final Pattern TURTLE = Pattern.compile("(?mi)^\\s*(?:@prefix|@base|prefix\\s|base\\s|<[^>\\s]*>\\s+)");
    private static final Pattern TURTLE_IRI = Pattern.compile("<([^>\\s]+)>\\s+(?:a|rdf:type|<" + Pattern.quote(RDF)
            + "type>)\\s+(?:owl:Ontology|<" + Pattern.quote(OWL) + "Ontology>)");

    /** The syntaxes the parsers report, as users know them. */
    enum Syntax {
        RDF_XML("RDF/XML"), OWL_XML("OWL/XML"), FUNCTIONAL("Functional"), TURTLE("Turtle"),
        MANCHESTER("Manchester");

        final String label;

        Syntax(String label) {
            this.label = label;
        }
    }

    private OntologyHeaders() {}

    /** The syntax a document's head looks like, if it looks like one. */
    static Optional<Syntax> likelySyntax(Path document) {
        try {
            return likelySyntax(head(document));
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    static Optional<Syntax> likelySyntax(String head) {
        Matcher xml = XML_ROOT.matcher(head);
        if (xml.lookingAt()) {
            return Optional.of(xml.group(2).equals("Ontology") ? Syntax.OWL_XML : Syntax.RDF_XML);
        }
        if (FUNCTIONAL.matcher(head).find()) {
            return Optional.of(Syntax.FUNCTIONAL);
        }
        if (MANCHESTER.matcher(head).find()) {
            return Optional.of(Syntax.MANCHESTER);
        }
        if (TURTLE.matcher(head).find()) {
            return Optional.of(Syntax.TURTLE);
        }
        return Optional.empty();
    }

    /** The ontology IRI a local document declares in its head, in any of the syntaxes above. */
    static Optional<String> declaredIri(Path document) throws IOException {
        String head = head(document);
        Optional<Syntax> syntax = likelySyntax(head);
        if (syntax.isEmpty()) {
            return Optional.empty();
        }
        return switch (syntax.get()) {
            case RDF_XML, OWL_XML -> xmlDeclaredIri(head, document.toUri());
            case FUNCTIONAL -> first(FUNCTIONAL_IRI, head);
            case MANCHESTER -> first(MANCHESTER_IRI, head);
            case TURTLE -> first(TURTLE_IRI, head);
        };
    }

    private static Optional<String> first(Pattern pattern, String head) {
        Matcher matcher = pattern.matcher(head);
        return matcher.find() ? Optional.of(matcher.group(1)) : Optional.empty();
    }

    private static String withoutFragment(URI uri) {
        String text = uri.toString();
        int hash = text.indexOf('#');
        return hash < 0 ? text : text.substring(0, hash);
    }

    static String head(Path document) throws IOException {
        byte[] bytes;
        try (InputStream in = Files.newInputStream(document)) {
            bytes = in.readNBytes(HEAD_BYTES);
        }
        String text = new String(bytes, StandardCharsets.UTF_8);
        return text.startsWith("\uFEFF") ? text.substring(1) : text;
    }

    /**
     * owl:Ontology's rdf:about (RDF/XML, resolved against xml:base) or Ontology's ontologyIRI
     * (OWL/XML), read by the OWL API's hardened SAX parser: no external entity, no DTD fetched.
     */
    private static Optional<String> xmlDeclaredIri(String head, URI documentUri) {
        String[] found = new String[1];
        Deque<URI> bases = new ArrayDeque<>();
        bases.push(documentUri);
        DefaultHandler handler = new DefaultHandler() {
            @Override
            public void startElement(String uri, String local, String qName, Attributes attributes)
                    throws SAXException {
                String xmlBase = attributes.getValue(XML, "base");
                URI current = bases.peek();
                bases.push(xmlBase == null || xmlBase.isEmpty() ? current : current.resolve(xmlBase));
                if (!OWL.equals(uri) || !local.equals("Ontology")) {
                    return;
                }
                String declared = attributes.getValue("ontologyIRI");
                if (declared == null) {
                    String about = attributes.getValue(RDF, "about");
                    // URI.resolve("") answers the base's folder, not the base itself.
                    declared = about == null || about.isEmpty() ? withoutFragment(bases.peek())
                            : bases.peek().resolve(about).toString();
                }
                found[0] = declared;
                throw new SAXException("found");
            }

            @Override
            public void endElement(String uri, String local, String qName) {
                bases.pop();
            }
        };
        try {
            SAXParsers.initParserWithOWLAPIStandards(null, "64000").parse(
                    new ByteArrayInputStream(head.getBytes(StandardCharsets.UTF_8)), handler);
        } catch (SAXException | IOException | RuntimeException e) {
            // found it (stopped on purpose), or the head ends mid-document, or it is no XML
        }
        return Optional.ofNullable(found[0]);
    }
}
