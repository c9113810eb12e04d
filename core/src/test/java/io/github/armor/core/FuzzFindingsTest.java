// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.assertFails;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import io.github.armor.core.api.Response;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Directives the million-directive fuzz run (tests/integration/fuzz.py) answered with 220, an
 * internal error: each is now refused with the code of its fault, or answered, and a refusal
 * changes nothing.
 */
class FuzzFindingsTest {
    @TempDir
    Path scratch;

    private CoreFixture robotics(String reasoner, boolean buffered) {
        CoreFixture f = new CoreFixture(scratch);
        f.loadRobotics("map", reasoner, buffered);
        return f;
    }

    private static String digest(CoreFixture f) {
        return f.ok("map", "GET REF DIGEST").queriedObjects().get(0);
    }

    private static void refusedUnchanged(CoreFixture f, int code, String words, String... args) {
        String before = digest(f);
        assertFails(f.run("map", words, args), code);
        assertEquals(before, digest(f), words + " " + List.of(args) + " changed the reference");
    }

    /**
     * SameIndividual of one individual named twice held one operand, which no OWL syntax writes:
     * every SPARQL query and explanation after it rendered the ontology and failed.
     */
    @Test
    void anIndividualSameAsItselfIsRefusedAndQueriesGoOn() {
        CoreFixture f = robotics("PELLET", false);
        refusedUnchanged(f, 207, "ADD IND SAME", "kitchen", "kitchen");
        refusedUnchanged(f, 207, "REMOVE IND SAME", "kitchen", "kitchen");
        refusedUnchanged(f, 207, "DISJOINT IND", "alice", "alice");
        refusedUnchanged(f, 207, "ADD AXIOM", "SameIndividual(:kitchen :kitchen)");
        refusedUnchanged(f, 207, "ADD AXIOM", "DifferentIndividuals(:alice :alice)");
        assertEquals(List.of("true"), f.ok("map", "QUERY SPARQL", "ASK { ?s ?p ?o }").queriedObjects());
        String before = digest(f);
        f.ok("map", "ADD IND SAME", "kitchen", "kitchen", "bedroom");
        assertNotEquals(before, digest(f));
        assertEquals(List.of("true"), f.ok("map", "QUERY SPARQL", "ASK { ?s ?p ?o }").queriedObjects());
    }

    /** The data factory refused DisjointClasses(owl:Thing) with a runtime exception. */
    @Test
    void owlThingDisjointFromItselfIsRefused() {
        CoreFixture f = robotics("HERMIT", false);
        refusedUnchanged(f, 207, "DISJOINT CLASS", "owl:Thing", "owl:Thing");
        refusedUnchanged(f, 207, "DISJOINT CLASS", "Robot", "Robot");
        refusedUnchanged(f, 208, "ADD AXIOM", "DisjointClasses(owl:Thing)");
        f.ok("map", "DISJOINT CLASS", "Robot", "Room", "Robot");
    }

    /** The OWL API's Manchester tokenizer read past the end of a text ending in a backslash. */
    @Test
    void aTextEndingInAnEscapeIsASyntaxError() {
        CoreFixture f = robotics("PELLET", false);
        for (String text : List.of("\\", "Robot\\", "isIn some \\")) {
            refusedUnchanged(f, 208, "ADD AXIOM", text);
            refusedUnchanged(f, 208, "REMOVE AXIOM", text);
            refusedUnchanged(f, 208, "ADD CLASS EQUIVALENT", "OccupiedRoom", text);
            refusedUnchanged(f, 208, "ADD SWRL", "rule", text);
            refusedUnchanged(f, 208, "REMOVE SWRL", "rule", text);
            Response query = f.run("map", "QUERY IND DL", text);
            assertFails(query, 208);
            assertEquals(true, query.errorDescription().contains("escape"), query.errorDescription());
        }
    }

    /** The subject and the object were put in Set.of, which refuses a duplicate. */
    @Test
    void anIndividualRelatedToItselfIsExplained() {
        CoreFixture f = robotics("HERMIT", false);
        assertFails(f.run("map", "EXPLAIN OBJECTPROP IND", "isIn", "corridor1", "corridor1"), 227);
        f.ok("map", "ADD OBJECTPROP IND", "connectedTo", "corridor1", "corridor1");
        Response why = f.ok("map", "EXPLAIN OBJECTPROP IND", "connectedTo", "corridor1", "corridor1");
        assertNotEquals(List.of(), why.queriedObjects());
    }

    /**
     * Such IRIs were taken, then refused as not durable (the checkpoint could not be read back);
     * a relative one failed first with 220 (its profile violation has no axiom, and the OWL API
     * throws when asked for it: ReasonerCoverage now asks last).
     */
    @Test
    void aCreatedOntologyIriHoldingWhatNoIriHoldsIsASyntaxError() {
        CoreFixture f = new CoreFixture(scratch);
        for (String iri : List.of("http://127.0.0.1:1/x.owl>", "http://x/a b", "<http://x/a>", "http://x/\\",
                "robot9", "BOOL")) {
            assertFails(f.run("made", "CREATE", iri, "false", "HERMIT", "true"), 208);
            assertEquals(List.of(), f.ok("", "GET ALL REFS").queriedObjects());
        }
        f.ok("made", "CREATE", "urn:armor:made", "false", "HERMIT", "true");
    }
    /**
     * A buffered Openllet reference whose changes made it inconsistent, not yet reasoned: the
     * explanation's search asked Openllet about subsets holding the contradiction, and Openllet
     * throws rather than answer that an inconsistent set entails the fact. (Facts the reasoner
     * holds, some answered by the told path, one by the search.)
     */
    @Test
    void anExplanationOverAContradictionNotYetReasonedIsAnswered() {
        CoreFixture f = robotics("PELLET", true);
        f.ok("map", "ADD IND SAME", "kitchen", "bedroom");
        f.ok("map", "DISJOINT IND", "kitchen", "bedroom");
        for (String[] question : List.of(new String[] {"EXPLAIN CLASS CLASS", "Robot", "Agent"},
                new String[] {"EXPLAIN IND CLASS", "kitchen", "Room"},
                new String[] {"EXPLAIN IND CLASS", "robot1", "Agent"},
                new String[] {"EXPLAIN IND CLASS", "kitchen", "OccupiedRoom"})) {
            Response answer = f.run("map", question[0], question[1], question[2]);
            assertEquals(0, answer.exitCode(), question[0] + " " + question[1] + " " + answer.errorDescription());
            assertNotEquals(List.of(), answer.queriedObjects(), question[0] + " " + question[1]);
        }
    }
}
