// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import org.semanticweb.owlapi.util.SAXParsers;
import org.xml.sax.Attributes;
import org.xml.sax.SAXException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * The {@code catalog-v001.xml} Protégé writes beside an ontology (an OASIS XML catalog): its
 * {@code <uri name="imported IRI" uri="document"/>} entries, also inside {@code <group>}s, with
 * relative documents resolved against the catalog's folder and any {@code xml:base}.
 */
final class ImportCatalog {
    static final String FILE_NAME = "catalog-v001.xml";
    private static final String XML = "http://www.w3.org/XML/1998/namespace";

    private final Path file;
    private final Map<String, URI> entries;

    private ImportCatalog(Path file, Map<String, URI> entries) {
        this.file = file;
        this.entries = entries;
    }

    Path file() {
        return file;
    }

    /** The document the catalog names for an imported IRI. */
    Optional<URI> document(String importedIri) {
        return Optional.ofNullable(entries.get(importedIri));
    }

    /** Reads a catalog file, already confined and known to be a regular file. */
    static ImportCatalog read(Path file) throws IOException {
        Map<String, URI> entries = new LinkedHashMap<>();
        Deque<URI> bases = new ArrayDeque<>();
        bases.push(file.toUri());
        DefaultHandler handler = new DefaultHandler() {
            @Override
            public void startElement(String uri, String local, String qName, Attributes attributes) {
                String base = attributes.getValue(XML, "base");
                URI current = bases.peek();
                bases.push(base == null || base.isEmpty() ? current : current.resolve(base));
                String name = attributes.getValue("name");
                String document = attributes.getValue("uri");
                if (local.equals("uri") && name != null && document != null) {
                    entries.putIfAbsent(name.strip(), bases.peek().resolve(document.strip()));
                }
            }

            @Override
            public void endElement(String uri, String local, String qName) {
                bases.pop();
            }
        };
        try (InputStream in = Files.newInputStream(file)) {
            SAXParsers.initParserWithOWLAPIStandards(null, "64000").parse(in, handler);
        } catch (SAXException | IllegalArgumentException e) {
            throw new IOException("unreadable catalog " + file + ": " + e.getMessage(), e);
        }
        return new ImportCatalog(file, entries);
    }
}
