// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.assertFails;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.Response;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * REPLACE and REMOVE of a literal stored with another datatype than the directive's type word
 * (issue 11 item 1): the stored value is removed, or the answer is an error naming the values;
 * a property is never left with two values quietly. Asserted values do not depend on the
 * reasoner, but every reasoner must answer the query afterwards with the one value.
 */
class LiteralValuesTest {
    private static final String NS = "http://www.example.org/values#";

    @TempDir
    Path scratch;

    private CoreFixture load(String reasoner) throws IOException {
        Path file = Files.writeString(scratch.resolve("values.ttl"), String.join("\n",
                "@prefix : <" + NS + "> .",
                "@prefix owl: <http://www.w3.org/2002/07/owl#> .",
                "@prefix xsd: <http://www.w3.org/2001/XMLSchema#> .",
                "<http://www.example.org/values> a owl:Ontology .",
                ":Robot a owl:Class .",
                ":batteryLevel a owl:DatatypeProperty, owl:FunctionalProperty .",
                ":name a owl:DatatypeProperty .", ":charging a owl:DatatypeProperty .",
                ":speed a owl:DatatypeProperty .", ":load a owl:DatatypeProperty .",
                ":robot1 a owl:NamedIndividual, :Robot ; :batteryLevel \"100\"^^xsd:long ;",
                "  :name \"kitchen\"@en ; :charging \"1\"^^xsd:boolean ; :speed \"0.5\"^^xsd:float ;",
                "  :load \"7\"^^xsd:long, \"7.0\"^^xsd:decimal .", ""));
        CoreFixture f = new CoreFixture(scratch);
        f.ok("values", "LOAD FILE", file.toString(), "http://www.example.org/values", "false", reasoner, "false");
        return f;
    }

    private static List<String> values(CoreFixture f, String property) {
        return f.ok("values", "QUERY DATAPROP IND", property, "robot1").queriedObjects();
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT", "ELK"})
    void replaceAndRemoveFindTheStoredValueWhateverItsDatatype(String reasoner) throws IOException {
        CoreFixture f = load(reasoner);
        f.ok("values", "REPLACE DATAPROP IND", "batteryLevel", "robot1", "INT", "80", "100");
        assertEquals(List.of("\"80\"^^xsd:integer"), values(f, "batteryLevel"));
        f.ok("values", "REPLACE DATAPROP IND", "speed", "robot1", "DOUBLE", "0.75", "0.50");
        assertEquals(List.of("\"0.75\"^^xsd:double"), values(f, "speed"));
        f.ok("values", "REPLACE DATAPROP IND", "charging", "robot1", "BOOL", "false", "true");
        assertEquals(List.of("\"false\"^^xsd:boolean"), values(f, "charging"));
        f.ok("values", "REMOVE DATAPROP IND", "name", "robot1", "STRING", "kitchen");
        assertEquals(List.of(), values(f, "name"));
        assertTrue(f.ok("values", "QUERY CONSISTENCY").isConsistent());
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT", "ELK"})
    void severalEqualValuesAreAnErrorNamingThemAndNothingChanges(String reasoner) throws IOException {
        CoreFixture f = load(reasoner);
        Response refused = f.run("values", "REPLACE DATAPROP IND", "load", "robot1", "INT", "9", "7");
        assertFails(refused, 207);
        assertTrue(refused.errorDescription().contains("\"7\"^^xsd:long")
                && refused.errorDescription().contains("\"7.0\"^^xsd:decimal"), refused.errorDescription());
        assertEquals(List.of("\"7\"^^xsd:long", "\"7.0\"^^xsd:decimal"), values(f, "load").stream().sorted().toList());
        f.ok("values", "REMOVE DATAPROP IND", "load", "robot1", "xsd:decimal", "7.0");
        assertEquals(List.of("\"7\"^^xsd:long"), values(f, "load"));
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT", "ELK"})
    void anOldValueThatIsNotStoredIsSaidWhenOtherValuesStay(String reasoner) throws IOException {
        CoreFixture f = load(reasoner);
        Response replaced = f.ok("values", "REPLACE DATAPROP IND", "batteryLevel", "robot1", "INT", "60", "55");
        assertTrue(replaced.errorDescription().contains("\"55\"^^xsd:integer was not stored")
                && replaced.errorDescription().contains("\"100\"^^xsd:long"), replaced.errorDescription());
        Response first = f.ok("values", "REPLACE DATAPROP IND", "speed", "robot1", "FLOAT", "1.5", "0.5");
        assertEquals("", first.errorDescription());
    }
}
