// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 21 item 6: the subclasses of owl:Nothing (or of any unsatisfiable class or expression)
 * are the unsatisfiable named classes, with all four reasoners; owl:Nothing is never listed.
 */
class UnsatisfiableClassesTest {
    private static final String NS = "http://www.example.org/unsat#";
    // Bad is a Robot and a Location, which are disjoint; Worse is a Bad; Void is owl:Nothing by definition.
    private static final String ONTOLOGY = """
            @prefix : <http://www.example.org/unsat#> .
            @prefix owl: <http://www.w3.org/2002/07/owl#> .
            @prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
            <http://www.example.org/unsat> a owl:Ontology .
            :Agent a owl:Class . :Robot a owl:Class ; rdfs:subClassOf :Agent .
            :Location a owl:Class . :Room a owl:Class ; rdfs:subClassOf :Location .
            :Robot owl:disjointWith :Location .
            :Bad a owl:Class ; rdfs:subClassOf :Robot, :Location .
            :Worse a owl:Class ; rdfs:subClassOf :Bad .
            :Void a owl:Class ; owl:equivalentClass owl:Nothing .
            :r1 a :Robot .
            """;

    @TempDir
    Path scratch;

    private CoreFixture load(String reasoner) throws IOException {
        Path file = Files.writeString(scratch.resolve("unsat.ttl"), ONTOLOGY);
        CoreFixture f = new CoreFixture(scratch);
        f.ok("u", "LOAD FILE", file.toString(), "http://www.example.org/unsat", "false", reasoner, "false");
        return f;
    }

    private static List<String> names(String... shortNames) {
        return Stream.of(shortNames).map(n -> "<" + NS + n + ">").sorted().toList();
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT", "ELK"})
    void theSubclassesOfNothingAreTheUnsatisfiableClasses(String reasoner) throws IOException {
        CoreFixture f = load(reasoner);
        List<String> unsatisfiable = names("Bad", "Void", "Worse");
        assertEquals(unsatisfiable, f.ok("u", "QUERY CLASS DL", "owl:Nothing").queriedObjects());
        assertEquals(unsatisfiable, f.ok("u", "QUERY CLASS CLASS", "owl:Nothing").queriedObjects());
        assertEquals(unsatisfiable, f.ok("u", "QUERY CLASS CLASS", "<http://www.w3.org/2002/07/owl#Nothing>")
                .queriedObjects());
        assertEquals(unsatisfiable, f.ok("u", "QUERY CLASS EQUIVALENT", "owl:Nothing").queriedObjects());
        // An unsatisfiable expression or class has the same subclasses (but never itself).
        assertEquals(unsatisfiable, f.ok("u", "QUERY CLASS DL", "Robot and Location").queriedObjects());
        assertEquals(names("Void", "Worse"), f.ok("u", "QUERY CLASS CLASS", "Bad").queriedObjects());
        assertEquals(List.of(), f.ok("u", "QUERY IND DL", "owl:Nothing").queriedObjects());
    }

    /** An unsatisfiable class is a subclass of every class: every reasoner says so, owl:Nothing never listed. */
    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT", "ELK"})
    void unsatisfiableClassesAreUnderEveryClassAndNothingIsNeverAnAnswer(String reasoner) throws IOException {
        CoreFixture f = load(reasoner);
        assertEquals(names("Bad", "Robot", "Void", "Worse"), f.ok("u", "QUERY CLASS CLASS", "Agent").queriedObjects());
        assertEquals(names("Bad", "Void", "Worse"), f.ok("u", "QUERY CLASS CLASS", "Room").queriedObjects());
        List<String> everything = f.ok("u", "QUERY CLASS CLASS", "owl:Thing").queriedObjects();
        assertEquals(names("Agent", "Bad", "Location", "Robot", "Room", "Void", "Worse"), everything);
        for (String answer : f.ok("u", "QUERY CLASS SUPER", "Worse").queriedObjects()) {
            assertFalse(answer.contains("Nothing"), answer);
        }
        assertTrue(f.ok("u", "QUERY CLASS IND", "r1").queriedObjects().contains("<" + NS + "Robot>"));
    }
}
