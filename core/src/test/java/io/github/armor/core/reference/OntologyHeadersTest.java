// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The ontology IRI a document declares, read from its head in every syntax (issue 21 item 3). */
class OntologyHeadersTest {
    private static final String IRI = "http://www.example.org/armor-test/declared";

    @TempDir
    Path scratch;

    private Optional<String> declared(String name, String text) throws IOException {
        return OntologyHeaders.declaredIri(Files.writeString(scratch.resolve(name), text));
    }

    @Test
    void everySyntaxDeclaresItsIri() throws IOException {
        String rdf = "xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\" "
                + "xmlns:owl=\"http://www.w3.org/2002/07/owl#\"";
        assertEquals(Optional.of(IRI), declared("a.owl", "<?xml version=\"1.0\"?>\n<!-- c -->\n<rdf:RDF " + rdf
                + "><owl:Ontology rdf:about=\"" + IRI + "\"/></rdf:RDF>"));
        assertEquals(Optional.of(IRI), declared("b.rdf", "<!DOCTYPE rdf:RDF [<!ENTITY base \"" + IRI + "\">]>\n"
                + "<rdf:RDF " + rdf + " xml:base=\"&base;\"><owl:Ontology rdf:about=\"\"/></rdf:RDF>"));
        assertEquals(Optional.of(IRI), declared("c.owx", "<?xml version=\"1.0\"?>\n<Ontology xmlns="
                + "\"http://www.w3.org/2002/07/owl#\" ontologyIRI=\"" + IRI + "\"><Declaration/></Ontology>"));
        assertEquals(Optional.of(IRI), declared("d.owl", "Prefix(:=<" + IRI + "#>)\n\nOntology(<" + IRI
                + "> <" + IRI + "/1.0>\nImport(<http://x/y>)\n)"));
        assertEquals(Optional.of(IRI), declared("e.omn", "Prefix: : <" + IRI + "#>\nOntology: <" + IRI + ">\n"));
        assertEquals(Optional.of(IRI), declared("f.ttl", "@prefix owl: <http://www.w3.org/2002/07/owl#> .\n<" + IRI
                + "> a owl:Ontology ;\n owl:imports <http://x/y> ."));
        assertEquals(Optional.empty(), declared("g.txt", "shopping list: milk, bread"));
        assertEquals(Optional.empty(), declared("h.owl", "<rdf:RDF this is not xml"));
    }
}
