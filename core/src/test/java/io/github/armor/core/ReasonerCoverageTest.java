// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 21 item 5: the axioms a reasoner will not use are said at LOAD (with the profile), and
 * every successful query of such a reference says its answer may be incomplete.
 */
class ReasonerCoverageTest {
    private static final String NS = "http://www.example.org/coverage#";
    // One axiom of each kind ELK skips (an inverse, a universal restriction, a cardinality, a
    // negation, a SWRL rule), each defining a class only it can fill, beside an EL definition.
    private static final String ONTOLOGY = """
            Prefix(:=<http://www.example.org/coverage#>)
            Ontology(<http://www.example.org/coverage>
            Declaration(Class(:Agent)) Declaration(Class(:Robot)) Declaration(Class(:Location))
            Declaration(Class(:Room)) Declaration(Class(:Corridor)) Declaration(Class(:SafeRobot))
            Declaration(Class(:Crowded)) Declaration(Class(:NotRoom)) Declaration(Class(:Visited))
            Declaration(Class(:Placed)) Declaration(ObjectProperty(:isIn)) Declaration(ObjectProperty(:contains))
            Declaration(NamedIndividual(:r1)) Declaration(NamedIndividual(:kitchen)) Declaration(NamedIndividual(:hall))
            SubClassOf(:Robot :Agent) SubClassOf(:Room :Location) SubClassOf(:Corridor :Location)
            DisjointClasses(:Room :Corridor)
            InverseObjectProperties(:contains :isIn)
            EquivalentClasses(:SafeRobot ObjectIntersectionOf(:Robot ObjectAllValuesFrom(:isIn :Room)))
            EquivalentClasses(:Crowded ObjectIntersectionOf(:Room ObjectMinCardinality(2 :contains :Agent)))
            EquivalentClasses(:NotRoom ObjectIntersectionOf(:Location ObjectComplementOf(:Room)))
            EquivalentClasses(:Placed ObjectIntersectionOf(:Robot ObjectSomeValuesFrom(:isIn :Location)))
            DLSafeRule(Body(ClassAtom(:Robot Variable(<urn:swrl:var#r>))
                ObjectPropertyAtom(:isIn Variable(<urn:swrl:var#r>) Variable(<urn:swrl:var#l>)))
                Head(ClassAtom(:Visited Variable(<urn:swrl:var#l>))))
            ClassAssertion(:Robot :r1) ClassAssertion(:Room :kitchen) ObjectPropertyAssertion(:isIn :r1 :kitchen)
            ClassAssertion(:Corridor :hall)
            )
            """;

    @TempDir
    Path scratch;

    private CoreFixture fixture() {
        return new CoreFixture(scratch);
    }

    private Response load(CoreFixture f, String reasoner) throws IOException {
        Path file = Files.writeString(scratch.resolve("coverage.ofn"), ONTOLOGY);
        return f.ok("c", "LOAD FILE", file.toString(), "http://www.example.org/coverage", "false", reasoner, "false");
    }

    private static List<String> names(String... shortNames) {
        return java.util.Arrays.stream(shortNames).map(n -> "<" + NS + n + ">").sorted().toList();
    }

    @Test
    void elkSaysAtLoadWhatItWillNotUseAndEveryQueryThatItMayBeIncomplete() throws IOException {
        CoreFixture f = fixture();
        String loaded = load(f, "ELK").errorDescription();
        assertTrue(loaded.startsWith("profile: outside OWL 2 EL; ELK does not use 5 axioms outside OWL 2 EL: "),
                loaded);
        for (String kind : List.of("universal restriction (only)", "cardinality", "negation (not)", "SWRL rule",
                "InverseObjectProperties axiom")) {
            assertTrue(loaded.contains("1 " + kind), kind + " missing from: " + loaded);
        }
        assertTrue(loaded.contains("answers may be incomplete; 10 classes; reasoning on the whole ontology"), loaded);

        Response placed = f.ok("c", "QUERY IND CLASS", "Placed");
        assertEquals(names("r1"), placed.queriedObjects());
        assertTrue(placed.errorDescription().startsWith("may be incomplete: ELK does not use 5 axioms"),
                placed.errorDescription());
        // And they are: what only the skipped axioms entail is missing.
        Response visited = f.ok("c", "QUERY IND CLASS", "Visited");
        assertEquals(List.of(), visited.queriedObjects());
        assertTrue(visited.errorDescription().contains("may be incomplete"), visited.errorDescription());
        assertEquals(List.of(), f.ok("c", "QUERY IND CLASS", "NotRoom").queriedObjects());
        assertTrue(f.ok("c", "QUERY SPARQL", "SELECT ?x WHERE { ?x a :Placed }").errorDescription()
                .contains("may be incomplete"));
        // Changes say nothing: only answers can be incomplete.
        assertEquals("", f.ok("c", "ADD IND CLASS", "r1", "Agent").errorDescription());
    }

    @Test
    void jfactSaysItDoesNotUseSwrlRules() throws IOException {
        CoreFixture f = fixture();
        String loaded = load(f, "JFACT").errorDescription();
        assertTrue(loaded.matches("profile: OWL 2 DL; JFACT does not use 1 axiom: 1 SWRL rule; answers may be incomplete;"
                + " 10 classes, classified in [^;]+; reasoning on the whole ontology: SWRL rules \\(JFact does not"
                + " evaluate them; PELLET and HERMIT references do\\)"), loaded);
        Response visited = f.ok("c", "QUERY IND CLASS", "Visited");
        assertEquals(List.of(), visited.queriedObjects());
        assertEquals("may be incomplete: JFACT does not use 1 axiom: 1 SWRL rule", visited.errorDescription());
        assertEquals(names("hall"), f.ok("c", "QUERY IND CLASS", "NotRoom").queriedObjects());
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void reasonersThatApplyRulesSayOnlyHowTheyReason(String reasoner) throws IOException {
        CoreFixture f = fixture();
        // Its SafeRobot (a universal restriction on the left of an equivalence) is not Horn: rules need the whole.
        String loaded = load(f, reasoner).errorDescription();
        assertTrue(loaded.matches("profile: OWL 2 DL; 10 classes, classified in [^;]+; reasoning on the whole ontology:"
                + " SWRL rules with an axiom that lets a model choose \\(not Horn\\): .*"), loaded);
        Response visited = f.ok("c", "QUERY IND CLASS", "Visited");
        assertEquals(names("kitchen"), visited.queriedObjects());
        assertEquals("", visited.errorDescription());
    }

    /** CREATE, then changes: the note follows what is added and removed, and what a failed list undid. */
    @ParameterizedTest
    @ValueSource(strings = {"ELK", "JFACT"})
    void changesAreFollowed(String reasoner) {
        CoreFixture f = fixture();
        assertEquals("", f.ok("s", "CREATE", "http://www.example.org/s", "false", reasoner, "false")
                .errorDescription());
        f.ok("s", "ADD IND CLASS", "r1", "Robot");
        assertEquals("", f.ok("s", "QUERY IND CLASS", "Robot").errorDescription());
        String rule = "Robot(?r) -> Agent(?r)";
        f.ok("s", "ADD SWRL", "agents", rule);
        String note = f.ok("s", "QUERY IND CLASS", "Robot").errorDescription();
        assertTrue(note.startsWith("may be incomplete: " + reasoner + " does not use 1 axiom") && note.contains(
                "1 SWRL rule"), note);
        f.ok("s", "REMOVE SWRL", "agents", rule);
        assertEquals("", f.ok("s", "QUERY IND CLASS", "Robot").errorDescription());

        ListResponse failed = f.core.executeList(List.of(
                Directive.of("test", "s", "ADD", "SWRL", "", "agents", rule),
                Directive.of("test", "s", "ADD", "IND", "CLASS", "r2")));
        assertFalse(failed.success());
        assertEquals("", f.ok("s", "QUERY IND CLASS", "Robot").errorDescription());
    }

    @Test
    void elkSaysWhichDatatypesItDoesNotUse() {
        CoreFixture f = fixture();
        f.ok("s", "CREATE", "http://www.example.org/s", "false", "ELK", "false");
        f.ok("s", "ADD DATAPROP IND", "level", "r1", "INTEGER", "80");
        assertEquals("", f.ok("s", "QUERY IND DATAPROP", "r1").errorDescription());
        f.ok("s", "ADD DATAPROP IND", "visitedAt", "r1", "LONG", "1700000000");
        f.ok("s", "ADD DATAPROP IND", "visitedAt", "r1", "LONG", "1700000001");
        assertEquals("may be incomplete: ELK does not use 2 axioms outside OWL 2 EL: 2 datatype xsd:long",
                f.ok("s", "QUERY IND DATAPROP", "r1").errorDescription());
        f.ok("s", "REMOVE DATAPROP IND", "visitedAt", "r1", "LONG", "1700000000");
        f.ok("s", "REMOVE DATAPROP IND", "visitedAt", "r1", "LONG", "1700000001");
        assertEquals("", f.ok("s", "QUERY IND DATAPROP", "r1").errorDescription());
    }
}
