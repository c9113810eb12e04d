// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.reference.Reference;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.apache.jena.graph.Graph;
import org.apache.jena.graph.GraphUtil;
import org.apache.jena.query.QueryExecution;
import org.apache.jena.query.QueryExecutionFactory;
import org.apache.jena.query.QueryFactory;
import org.apache.jena.query.ResultSet;
import org.apache.jena.rdf.model.Model;
import org.apache.jena.rdf.model.ModelFactory;
import org.apache.jena.sparql.graph.GraphFactory;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.AddAxiom;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyManager;

/**
 * The in-process side of the LUBM SPARQL benchmark (bench/lubm.py), in one JVM:
 * <ul>
 *   <li>{@code armor_core}: the 14 queries through {@link ArmorCore#execute} (dispatch, lock,
 *       parsing, the kept graph, evaluation, rendering; no socket, no ROS), rows checked;</li>
 *   <li>{@code bare_jena}: the same queries with plain Jena ARQ over a plain in-memory copy of the
 *       same graph, results consumed but not rendered: the floor;</li>
 *   <li>{@code change}: one new fact (a new graduate student) added through the core, then the
 *       first query (query 6, whose answer grows by that student: a Student by inference) and the
 *       next one;</li>
 *   <li>{@code graph}: on a reference opened beside the core, the time to build the graph afresh
 *       and to derive it after one fact, with the reasoner's own share (flush, realisation).</li>
 * </ul>
 * A main method in the test sources (package-private access to the graph classes); the benchmark
 * runs it with {@code java -cp core/target/test-classes:core/target/armor-core.jar:core/target/lib/*}.
 *
 * <pre>
 * LubmBench ONTOLOGY QUERIES_JSON REASONER ROUNDS WARMUP_ROUNDS CHANGES
 * </pre>
 * Prints one JSON object on stdout; logging goes to stderr.
 */
public final class LubmBench {
    private static final String UB = "http://swat.cse.lehigh.edu/onto/univ-bench.owl#";
    private static final String DEPARTMENT = "http://www.Department0.University0.edu";
    private static final int GROWING_QUERY = 6;

    private LubmBench() {}

    private record LubmQuery(int number, int expectedRows, String sparql) {}

    public static void main(String[] args) throws Exception {
        if (args.length != 6) {
            System.err.println("usage: LubmBench ONTOLOGY QUERIES_JSON REASONER ROUNDS WARMUP_ROUNDS CHANGES");
            System.exit(2);
        }
        Path ontology = Path.of(args[0]).toAbsolutePath();
        List<LubmQuery> queries = queries(Path.of(args[1]));
        String reasoner = args[2];
        int rounds = Integer.parseInt(args[3]);
        int warmupRounds = Integer.parseInt(args[4]);
        int changes = Integer.parseInt(args[5]);

        Map<String, Object> result = new LinkedHashMap<>();
        result.put("reasoner", reasoner);
        ArmorCore core = new ArmorCore(CoreConfig.defaults(ontology.getParent()));
        long start = System.nanoTime();
        ok(core.execute(Directive.of("bench", "lubm", "LOAD", "FILE", "", ontology.toString(), "", "false", reasoner,
                "false")));
        result.put("load_ms", ms(start));
        start = System.nanoTime();
        ok(core.execute(Directive.of("bench", "lubm", "REASON", "", "")));
        result.put("reason_ms", ms(start));
        start = System.nanoTime();
        int[] rows = new int[queries.size()];
        for (int i = 0; i < queries.size(); i++) {
            rows[i] = query(core, queries.get(i).sparql()).queriedObjects().size();
            if (i == 0) {
                result.put("first_query_ms", ms(start));
            }
        }
        result.put("rows", rows);
        result.put("expected_rows", queries.stream().mapToInt(LubmQuery::expectedRows).toArray());
        result.put("rows_ok", Arrays.equals(rows, queries.stream().mapToInt(LubmQuery::expectedRows).toArray()));

        // The graph, on a reference opened beside the core from the same file with the same reasoner.
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        OWLOntology loaded = manager.loadOntologyFromOntologyDocument(new File(ontology.toString()));
        Reference reference = Reference.open("lubm", loaded, new Reference.Settings(ontology.toString(), "", reasoner,
                false, false), 0);
        reference.reason();
        start = System.nanoTime();
        Graph graph = InferredGraph.build(reference, reference.modificationCount()).graph();
        Map<String, Object> graphFigures = new LinkedHashMap<>();
        graphFigures.put("triples", graph.size());
        graphFigures.put("full_build_ms", ms(start));
        Graph copy = GraphFactory.createGraphMem();
        GraphUtil.addInto(copy, graph);
        Model bare = ModelFactory.createModelForGraph(copy);

        // Each query through the core, then on bare Jena, in turn: both see the same noise.
        double[] coreMs = new double[queries.size()];
        double[] bareMs = new double[queries.size()];
        for (int round = -warmupRounds; round < rounds; round++) {
            for (int i = 0; i < queries.size(); i++) {
                long t = System.nanoTime();
                Response answer = query(core, queries.get(i).sparql());
                double elapsed = ms(t);
                if (answer.queriedObjects().size() != rows[i]) {
                    throw new IllegalStateException("query " + queries.get(i).number() + " changed its answer");
                }
                t = System.nanoTime();
                int found = bareJena(bare, queries.get(i).sparql());
                double bareElapsed = ms(t);
                if (found != rows[i]) {
                    throw new IllegalStateException("bare Jena: query " + queries.get(i).number() + " answered "
                            + found + " rows, the core " + rows[i]);
                }
                if (round >= 0) {
                    coreMs[i] += elapsed / rounds;
                    bareMs[i] += bareElapsed / rounds;
                }
            }
        }
        result.put("armor_core", perQuery(coreMs, rounds));
        result.put("bare_jena", perQuery(bareMs, rounds));

        result.put("change", change(core, queries.get(GROWING_QUERY - 1), rows[GROWING_QUERY - 1], changes));
        graphFigures.putAll(derivation(reference, loaded, changes));
        result.put("graph", graphFigures);
        Gson gson = new GsonBuilder().serializeSpecialFloatingPointValues().create();
        System.out.println(gson.toJson(result));
        core.close();
        System.exit(0);
    }

    private static List<LubmQuery> queries(Path file) throws Exception {
        List<LubmQuery> queries = new ArrayList<>();
        for (JsonElement element : JsonParser.parseString(Files.readString(file)).getAsJsonArray()) {
            JsonObject query = element.getAsJsonObject();
            queries.add(new LubmQuery(query.get("query").getAsInt(), query.get("expected_rows").getAsInt(),
                    query.get("sparql").getAsString()));
        }
        return queries;
    }

    private static Response query(ArmorCore core, String sparql) {
        return ok(core.execute(Directive.of("bench", "lubm", "QUERY", "SPARQL", "", sparql)));
    }

    private static Response ok(Response response) {
        if (!response.success()) {
            throw new IllegalStateException(response.exitCode() + " " + response.errorDescription());
        }
        return response;
    }

    private static double ms(long startNanos) {
        return (System.nanoTime() - startNanos) / 1e6;
    }

    private static Map<String, Object> perQuery(double[] meanMs, int rounds) {
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("rounds", rounds);
        figures.put("per_query_ms", meanMs);
        figures.put("mean_ms", Arrays.stream(meanMs).average().orElse(Double.NaN));
        return figures;
    }

    /** Plain ARQ over a plain copy of the graph: parse, evaluate, consume every row; the row count. */
    private static int bareJena(Model model, String sparql) {
        int found = 0;
        try (QueryExecution execution = QueryExecutionFactory.create(QueryFactory.create(sparql), model)) {
            ResultSet results = execution.execSelect();
            while (results.hasNext()) {
                results.next();
                found++;
            }
        }
        return found;
    }

    /** One new fact at a time through the core: the ADD, the first query after it, the one after that. */
    private static Map<String, Object> change(ArmorCore core, LubmQuery growing, int rowsBefore, int changes) {
        double[] addMs = new double[changes];
        double[] firstMs = new double[changes];
        double[] nextMs = new double[changes];
        boolean complete = true;
        for (int k = 0; k < changes; k++) {
            String student = "<" + DEPARTMENT + "/BenchStudent" + k + ">";
            long t = System.nanoTime();
            ok(core.execute(Directive.of("bench", "lubm", "ADD", "IND", "CLASS", student,
                    "<" + UB + "GraduateStudent>")));
            addMs[k] = ms(t);
            t = System.nanoTime();
            int first = query(core, growing.sparql()).queriedObjects().size();
            firstMs[k] = ms(t);
            t = System.nanoTime();
            query(core, growing.sparql());
            nextMs[k] = ms(t);
            complete &= first == rowsBefore + k + 1;
        }
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("changes", changes);
        figures.put("query", growing.number());
        figures.put("answers_include_each_change", complete);
        figures.put("add_ms", addMs);
        figures.put("first_query_ms", firstMs);
        figures.put("next_query_ms", nextMs);
        return figures;
    }

    /**
     * The graph's own part of a change, on the reference beside the core: the reasoner brought up
     * to date (what ADD does), the graph derived from the last one, and its share spent
     * realising (Openllet: asked once before the derivation, so the derivation alone remains).
     */
    private static Map<String, Object> derivation(Reference reference, OWLOntology ontology, int changes) {
        OWLDataFactory factory = ontology.getOWLOntologyManager().getOWLDataFactory();
        double[] changeMs = new double[changes];
        double[] deriveMs = new double[changes];
        double[] realiseMs = new double[changes];
        SparqlGraphs.current(reference);
        for (int k = 0; k < changes; k++) {
            long t = System.nanoTime();
            reference.change(List.of(new AddAxiom(ontology, factory.getOWLClassAssertionAxiom(
                    factory.getOWLClass(IRI.create(UB + "GraduateStudent")),
                    factory.getOWLNamedIndividual(IRI.create(DEPARTMENT + "/DerivedStudent" + k))))));
            changeMs[k] = ms(t);
            t = System.nanoTime();
            reference.reasonerForQuery().precomputeInferences(org.semanticweb.owlapi.reasoner.InferenceType
                    .CLASS_ASSERTIONS);
            realiseMs[k] = ms(t);
            t = System.nanoTime();
            SparqlGraphs.current(reference);
            deriveMs[k] = ms(t);
        }
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("change_ms", changeMs);
        figures.put("realise_ms", realiseMs);
        figures.put("derive_ms", deriveMs);
        return figures;
    }
}
