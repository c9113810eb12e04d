// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.assertFails;
import static io.github.armor.core.CoreFixture.iris;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.api.SizeLimits;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;

/**
 * What a request may cost (issue 20 items 2, 5, 7): size limits refused with 221 before any
 * work, SPARQL SERVICE refused with 223, and SPARQL evaluated within its time limit without
 * holding its reference.
 */
class RequestLimitsTest {
    // Five unconstrained triple patterns, a filter that needs all five: nothing prunes the join.
    static final String CROSS_JOIN = "SELECT (COUNT(*) AS ?n) WHERE { ?a ?b ?c . ?d ?e ?f . ?g ?h ?i . ?j ?k ?l ."
            + " ?m ?n2 ?o FILTER(STRLEN(CONCAT(STR(?a), STR(?d), STR(?g), STR(?j), STR(?m))) < 0) }";

    private static CoreFixture fixture(long sparqlTimeoutMs, boolean federated, long lockWaitMs) {
        return new CoreFixture(new CoreConfig(true, "HERMIT", List.of(CoreFixture.ONTOLOGIES), false, lockWaitMs, 0, 0,
                CoreConfig.Durability.NONE, new CoreConfig.Safeguards(sparqlTimeoutMs, federated, false)));
    }

    @Test
    void oversizedArgumentsDirectivesNamesAndListsAre221AndChangeNothing() {
        CoreFixture f = fixture(30_000, false, 30_000);
        f.loadRobotics("map", "HERMIT", false);
        String argument = "x".repeat(SizeLimits.ARGUMENT_BYTES + 1);
        Response refused = f.run("map", "ADD IND CLASS", argument, "Robot");
        assertFails(refused, 221);
        assertTrue(refused.errorDescription().startsWith("argument 0 of ADD IND CLASS is 1,048,577 bytes"),
                refused.errorDescription());
        // Multi-byte characters count as the bytes they take on the wire.
        assertFails(f.run("map", "ADD IND CLASS", "é".repeat(SizeLimits.ARGUMENT_BYTES / 2 + 1), "Robot"), 221);
        String nearlyOneMiB = "n".repeat(SizeLimits.ARGUMENT_BYTES - 10);
        assertFails(f.run("map", "DISJOINT IND", nearlyOneMiB + 1, nearlyOneMiB + 2, nearlyOneMiB + 3,
                nearlyOneMiB + 4, nearlyOneMiB + 5), 221);
        assertFails(f.runAs("c".repeat(SizeLimits.NAME_BYTES + 1), "map", "ADD IND CLASS", "robot9", "Robot"), 221);
        List<Directive> tooMany = Collections.nCopies(SizeLimits.LIST_DIRECTIVES + 1,
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot9", "Robot"));
        ListResponse list = f.core.executeList(tooMany);
        assertFalse(list.success());
        assertEquals(tooMany.size(), list.responses().size());
        assertTrue(list.responses().stream().allMatch(r -> r.exitCode() == 221));
        List<Directive> tooBig = new ArrayList<>();
        for (int i = 0; i < 9; i++) {
            tooBig.add(Directive.of("c", "map", "ADD", "IND", "CLASS", nearlyOneMiB + i, "Robot"));
        }
        assertTrue(f.core.executeList(tooBig).responses().stream().allMatch(r -> r.exitCode() == 221));
        assertEquals(iris("robot1"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());
        // Just inside the limits is answered.
        assertEquals(List.of(), f.ok("map", "QUERY IND CLASS", "C".repeat(SizeLimits.ARGUMENT_BYTES)).queriedObjects());
    }

    @Test
    void anAnswerLargerThanTheLimitIs221() {
        CoreFixture f = fixture(0, false, 30_000);
        f.loadRobotics("map", "HERMIT", false);
        Response refused = f.run("map", "QUERY SPARQL", "SELECT * WHERE { ?a ?b ?c . ?d ?e ?f . ?g ?h ?i }");
        assertFails(refused, 221);
        assertTrue(refused.errorDescription().contains("LIMIT"), refused.errorDescription());
    }

    @Test
    void serviceClausesAre223UnlessFederatedQueriesAreAllowed() throws Exception {
        try (ServerSocket endpoint = new ServerSocket(0, 50, InetAddress.getLoopbackAddress())) {
            String service = "<http://127.0.0.1:" + endpoint.getLocalPort() + "/sparql>";
            CoreFixture f = fixture(30_000, false, 30_000);
            f.loadRobotics("map", "HERMIT", false);
            for (String query : List.of(
                    "SELECT * WHERE { SERVICE " + service + " { ?s ?p ?o } }",
                    "SELECT * WHERE { SERVICE SILENT " + service + " { ?s ?p ?o } }",
                    "SELECT * WHERE { ?s a ?t OPTIONAL { SERVICE SILENT " + service + " { ?s ?p ?o } } }",
                    "SELECT * WHERE { { SELECT ?s WHERE { SERVICE " + service + " { ?s ?p ?o } } } }",
                    "ASK { ?s ?p ?o FILTER NOT EXISTS { SERVICE SILENT " + service + " { ?s ?p ?o } } }",
                    "SELECT * WHERE { ?x ?y ?z } ORDER BY (EXISTS { SERVICE SILENT " + service + " { ?s ?p ?o } })",
                    "SELECT (COUNT(EXISTS { SERVICE SILENT " + service + " { ?s ?p ?o } }) AS ?c) WHERE { ?x ?y ?z }",
                    "SELECT * WHERE { BIND(" + service + " AS ?e) SERVICE SILENT ?e { ?s ?p ?o } }")) {
                Response refused = f.run("map", "QUERY SPARQL", query);
                assertFails(refused, 223);
                assertTrue(refused.errorDescription().contains("sparql_federated"), refused.errorDescription());
            }
            endpoint.close();
            // Allowed: the (now closed) endpoint cannot be reached; SILENT answers one empty row for it.
            CoreFixture federated = fixture(30_000, true, 30_000);
            federated.loadRobotics("map", "HERMIT", false);
            assertEquals(List.of("s=; p=; o="), federated.ok("map", "QUERY SPARQL",
                    "SELECT * WHERE { SERVICE SILENT " + service + " { ?s ?p ?o } }").queriedObjects());
        }
    }

    @Test
    void aQueryStopsAtItsLimitAndHoldsNoLockWhileItRuns() throws Exception {
        // Writers wait at most 2 s for the reference; the query runs up to 3 s.
        CoreFixture f = fixture(3_000, false, 2_000);
        f.loadRobotics("map", "HERMIT", false);
        CompletableFuture<Response> query = CompletableFuture.supplyAsync(() -> f.run("map", "QUERY SPARQL", CROSS_JOIN));
        int writesWhileRunning = 0;
        for (int i = 0; !query.isDone(); i++) {
            f.ok("map", "ADD IND CLASS", "visitor" + i, "Person");
            writesWhileRunning += query.isDone() ? 0 : 1;
        }
        Response answer = query.get();
        assertTrue(answer.success() && answer.timeout(), answer.errorDescription());
        assertTrue(writesWhileRunning > 0, "no change was answered while the query ran");
        // The query's own limit applies when it is shorter than the node's.
        Response own = f.run("map", "QUERY SPARQL", "SELECT ?r WHERE { { ?r a <" + CoreFixture.NS + "Robot> } UNION "
                + CROSS_JOIN.substring(CROSS_JOIN.indexOf("WHERE") + 5) + " }", "300");
        assertTrue(own.success() && own.timeout(), own.errorDescription());
        assertEquals(List.of(CoreFixture.iri("robot1")), own.queriedObjects());
    }
}
