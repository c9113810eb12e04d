// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.api.Response;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;

/**
 * The 14 LUBM queries on Department0 of University0 (bench/data/lubm, the benchmark's data)
 * answer every row the published benchmark expects, with Openllet, before and after changes,
 * from several threads at once.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class LubmQueriesTest {
    static final Path LUBM = Path.of("..", "bench", "data", "lubm").toAbsolutePath().normalize();
    private static final String DEPARTMENT = "http://www.Department0.University0.edu";
    private static final String UB = "http://swat.cse.lehigh.edu/onto/univ-bench.owl#";

    private record LubmQuery(int number, int expectedRows, String sparql) {}

    private final CoreFixture f = new CoreFixture(LUBM);
    private final List<LubmQuery> queries = new ArrayList<>();

    @BeforeAll
    void load() throws Exception {
        for (JsonElement element : JsonParser.parseString(Files.readString(LUBM.resolve("queries.json"))).getAsJsonArray()) {
            JsonObject query = element.getAsJsonObject();
            queries.add(new LubmQuery(query.get("query").getAsInt(), query.get("expected_rows").getAsInt(),
                    query.get("sparql").getAsString()));
        }
        assertEquals(14, queries.size());
        f.ok("lubm", "LOAD FILE", LUBM.resolve("university0-department0.owl").toString(), "", "false", "PELLET",
                "false");
        f.ok("lubm", "REASON");
    }

    private int rows(String sparql) {
        return f.ok("lubm", "QUERY SPARQL", sparql).queriedObjects().size();
    }

    private LubmQuery query(int number) {
        return queries.get(number - 1);
    }

    private void assertExpectedRows(String when) {
        for (LubmQuery query : queries) {
            assertEquals(query.expectedRows(), rows(query.sparql()), () -> "LUBM query " + query.number() + " " + when);
        }
    }

    @Test
    void everyQueryAnswersTheExpectedRows() {
        assertExpectedRows("after REASON");
        assertExpectedRows("asked again (the graph kept between queries)");
    }

    @Test
    void answersFollowAddedAndRemovedFacts() {
        String student = DEPARTMENT + "/UndergraduateStudentNew";
        // Takes a course: the reasoner concludes that it is a Student (query 6), and a Person
        // member of the department (query 5), but not an UndergraduateStudent (query 14).
        f.ok("lubm", "ADD OBJECTPROP IND", "<" + UB + "takesCourse>", "<" + student + ">", "<" + DEPARTMENT
                + "/Course0>");
        f.ok("lubm", "ADD OBJECTPROP IND", "<" + UB + "memberOf>", "<" + student + ">", "<" + DEPARTMENT + ">");
        assertEquals(query(6).expectedRows() + 1, rows(query(6).sparql()));
        assertEquals(query(5).expectedRows() + 1, rows(query(5).sparql()));
        assertEquals(query(14).expectedRows(), rows(query(14).sparql()));
        f.ok("lubm", "ADD IND CLASS", "<" + student + ">", "<" + UB + "UndergraduateStudent>");
        assertEquals(query(14).expectedRows() + 1, rows(query(14).sparql()));
        f.ok("lubm", "REMOVE IND CLASS", "<" + student + ">", "<" + UB + "UndergraduateStudent>");
        f.ok("lubm", "REMOVE OBJECTPROP IND", "<" + UB + "memberOf>", "<" + student + ">", "<" + DEPARTMENT + ">");
        f.ok("lubm", "REMOVE OBJECTPROP IND", "<" + UB + "takesCourse>", "<" + student + ">", "<" + DEPARTMENT
                + "/Course0>");
        assertExpectedRows("after the facts were removed again");
    }

    @Test
    void queriesFromSeveralThreadsAnswerTogether() throws Exception {
        List<CompletableFuture<Void>> clients = new ArrayList<>();
        for (int client = 0; client < 4; client++) {
            clients.add(CompletableFuture.runAsync(() -> assertExpectedRows("asked from several threads at once")));
        }
        for (CompletableFuture<Void> client : clients) {
            client.get(120, TimeUnit.SECONDS);
        }
    }

    @Test
    void aLongQueryDoesNotHoldUpTheNextOne() throws Exception {
        // Hours of work (a product of every student with itself, twice): cut at its 3 s limit.
        String endless = "PREFIX ub: <" + UB + "> SELECT ?a WHERE { ?a a ub:Student . ?b a ub:Student . "
                + "?c a ub:Student . FILTER(STR(?a) = CONCAT(STR(?b), STR(?c))) }";
        CompletableFuture<Response> slow = CompletableFuture.supplyAsync(() -> f.run("lubm", "QUERY SPARQL",
                endless, "3000"));
        Thread.sleep(300);
        assertEquals(query(1).expectedRows(), rows(query(1).sparql()));
        assertFalse(slow.isDone(), "the quick query was answered while the long one ran");
        Response cut = slow.get(60, TimeUnit.SECONDS);
        assertTrue(cut.success() && cut.timeout(), () -> "the long query ends at its limit: " + cut.exitCode() + " "
                + cut.errorDescription());
    }
}
