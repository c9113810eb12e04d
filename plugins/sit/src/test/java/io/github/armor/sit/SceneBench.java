// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandTable;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.formats.FunctionalSyntaxDocumentFormat;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.OWLOntologyStorageException;

/**
 * The scene plugin inside the core, without ROS (bench/scenes.py runs it and measures the same
 * scenes over ROS 2 beside it):
 *
 * <pre>
 *   java -cp ... io.github.armor.sit.SceneBench OUTPUT_DIR ROWS SAMPLES BUDGET_S LOAD_BUDGET_S [SEED]
 *   (ROWS: REASONER:buffered|immediate:SIZE,...  e.g. PELLET:buffered:100,HERMIT:immediate:10)
 * </pre>
 *
 * For each memory size of the rows it writes {@code memory-N.ofn}: N scene classes as SIT SCENE learns them,
 * from N generated table tops of 3 to 8 primitives (writing them is quicker than learning them one
 * by one, and gives the same classes), and {@code probes-N.json}: SAMPLES of those scenes to show
 * again (each is recognised, nothing is learned) and SAMPLES new ones (each is learned). Then, for
 * each row, it loads the memory into an ArmorCore with this plugin and times SIT SCENE on the
 * probes within BUDGET_S (a LOAD gets LOAD_BUDGET_S of reasoning), the reference's reasoner brought up to date after every change
 * (immediate) or only when asked (buffered: as ROS 1 SIT loaded its ontology). Prints JSON.
 */
public final class SceneBench {
    static final String IRI_BASE = "http://www.emarolab.it/sit/simple";
    private static final Shape[] SHAPES = Shape.values();

    private SceneBench() {}

    /** A generated table top of 3 to 8 primitives as SIT SCENE's elements argument (text form). */
    static String generated(Random random) {
        return generated(random, 3 + random.nextInt(6));
    }

    /** A generated table top of {@code size} primitives. */
    static String generated(Random random, int size) {
        List<String> elements = new ArrayList<>();
        for (int i = 0; i < size; i++) {
            Shape shape = SHAPES[random.nextInt(SHAPES.length)];
            double[] centre = {mm(random.nextDouble() - 0.5), mm(random.nextDouble() - 0.5),
                    random.nextBoolean() ? 0.0 : mm(random.nextDouble() * 0.3)};
            StringBuilder text = new StringBuilder(shape.name());
            for (double v : centre) {
                text.append(' ').append(v);
            }
            if (shape.orientable() && random.nextDouble() < 0.7) {
                double[][] axes = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {mm(random.nextDouble() - 0.5), 0.5, 0.25}};
                for (double v : axes[random.nextInt(axes.length)]) {
                    text.append(' ').append(v);
                }
            }
            elements.add(text.toString());
        }
        return String.join("; ", elements);
    }

    private static double mm(double metres) {
        return Math.round(metres * 1000) / 1000.0;
    }

    /** An ontology without a reasoner: enough to write what SIT SCENE would learn. */
    private record OntologyOnly(OWLOntology ontology) implements SceneReference {
        @Override
        public OWLDataFactory factory() {
            return ontology.getOWLOntologyManager().getOWLDataFactory();
        }

        @Override
        public IRI iri(EntityType<?> type, String name) {
            return IRI.create(IRI_BASE + "#" + name);
        }

        @Override
        public void enact(List<OWLOntologyChange> changes) {
            ontology.getOWLOntologyManager().applyChanges(changes);
        }

        @Override
        public java.util.Set<OWLClass> types(OWLNamedIndividual individual) {
            throw new UnsupportedOperationException("no reasoner");
        }

        @Override
        public java.util.Set<OWLClass> superClasses(OWLClass owlClass) {
            throw new UnsupportedOperationException("no reasoner");
        }

        @Override
        public java.util.Set<OWLClass> equivalentClasses(OWLClass owlClass) {
            throw new UnsupportedOperationException("no reasoner");
        }

        @Override
        public boolean consistent() {
            return true;
        }

        @Override
        public org.semanticweb.owlapi.reasoner.OWLReasonerFactory reasonerFactory() {
            throw new UnsupportedOperationException("no reasoner");
        }

        @Override
        public Object identity() {
            return ontology;
        }

    }

    /** An ontology holding the vocabulary and one learned class per scene, as SIT SCENE writes them. */
    static void writeMemory(Path file, List<String> scenes) throws OWLOntologyCreationException,
            OWLOntologyStorageException, IOException {
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        OWLOntology ontology = manager.createOntology(IRI.create(IRI_BASE));
        OWLDataFactory factory = manager.getOWLDataFactory();
        SceneReference writer = new OntologyOnly(ontology);
        SceneVocabulary vocabulary = new SceneVocabulary(writer);
        List<OWLAxiom> axioms = new ArrayList<>(vocabulary.missing());
        int number = 0;
        for (String text : scenes) {
            Scene scene = Scene.parse(text, "0.03", "0.05");
            SceneDefinition definition = SceneDefinition.of(scene, SpatialRelations.of(scene));
            if (definition.restrictions().isEmpty()) {
                continue;
            }
            OWLClass learned = vocabulary.learnedClass(++number);
            List<OWLClassExpression> restrictions = new ArrayList<>();
            for (SceneDefinition.Restriction r : definition.restrictions()) {
                axioms.add(factory.getOWLDeclarationAxiom(vocabulary.property(r.property())));
                restrictions.add(factory.getOWLObjectMinCardinality(r.min(), vocabulary.property(r.property()),
                        vocabulary.shape(r.type())));
            }
            axioms.add(factory.getOWLDeclarationAxiom(learned));
            axioms.add(factory.getOWLSubClassOfAxiom(learned, vocabulary.scene()));
            axioms.add(factory.getOWLEquivalentClassesAxiom(learned, restrictions.size() == 1 ? restrictions.get(0)
                    : factory.getOWLObjectIntersectionOf(restrictions)));
        }
        axioms.add(vocabulary.counterAxiom(number));
        manager.addAxioms(ontology, axioms.stream());
        try (var out = Files.newOutputStream(file)) {
            manager.saveOntology(ontology, new FunctionalSyntaxDocumentFormat(), out);
        }
    }

    private static double percentile(List<Double> sorted, double fraction) {
        return sorted.get(Math.min(sorted.size() - 1, (int) Math.floor(fraction * (sorted.size() - 1) + 0.5)));
    }

    private static JsonObject timings(List<Double> millis) {
        List<Double> sorted = new ArrayList<>(millis);
        Collections.sort(sorted);
        JsonObject summary = new JsonObject();
        summary.addProperty("n", sorted.size());
        summary.addProperty("p50_ms", percentile(sorted, 0.5));
        summary.addProperty("p90_ms", percentile(sorted, 0.9));
        summary.addProperty("max_ms", sorted.get(sorted.size() - 1));
        return summary;
    }

    /** CPU time of the whole JVM, in ms: on a shared machine, what a call cost beside how long it took. */
    private static double cpuMs() {
        return ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory
                .getOperatingSystemMXBean()).getProcessCpuTime() / 1e6;
    }

    private static Response sit(ArmorCore core, String elements, String threshold) {
        Response response = core.execute(Directive.of("bench", "memory", "SIT", "SCENE", "", threshold, "0.03", "0.05",
                elements));
        if (!response.success()) {
            throw new IllegalStateException("SIT SCENE failed: " + response.exitCode() + " " + response.errorDescription());
        }
        return response;
    }

    /** One configuration to measure: a reasoner, brought up to date after every change or buffered, and a memory size. */
    record Row(String reasoner, boolean buffered, int size) {
        static Row parse(String text) {
            String[] parts = text.split(":");
            return new Row(parts[0], parts[1].equals("buffered"), Integer.parseInt(parts[2]));
        }
    }

    public static void main(String[] args) throws Exception {
        Path output = Path.of(args[0]);
        List<Row> rows = Arrays.stream(args[1].split(",")).map(Row::parse).toList();
        int samples = Integer.parseInt(args[2]);
        long budgetMs = Long.parseLong(args[3]) * 1000;
        long loadBudgetMs = Long.parseLong(args[4]) * 1000;
        long seed = args.length > 5 ? Long.parseLong(args[5]) : 32;
        Files.createDirectories(output);
        java.util.Map<Integer, List<List<String>>> probes = new java.util.TreeMap<>();
        for (int size : rows.stream().map(Row::size).distinct().toList()) {
            Random random = new Random(seed + size);
            List<String> memory = new ArrayList<>();
            for (int i = 0; i < size; i++) {
                memory.add(generated(random));
            }
            writeMemory(output.resolve("memory-" + size + ".ofn"), memory);
            List<String> known = new ArrayList<>();
            List<String> fresh = new ArrayList<>();
            for (int i = 0; i < samples; i++) {
                known.add(memory.get(random.nextInt(memory.size())));
                fresh.add(generated(random));
            }
            probes.put(size, List.of(known, fresh));
            JsonObject written = new JsonObject();
            written.add("known", new Gson().toJsonTree(known));
            written.add("new", new Gson().toJsonTree(fresh));
            Files.writeString(output.resolve("probes-" + size + ".json"), written.toString());
        }
        JsonArray measured = new JsonArray();
        for (Row row : rows) {
            measured.add(measure(output, row, probes.get(row.size()).get(0), probes.get(row.size()).get(1), budgetMs,
                    loadBudgetMs));
        }
        JsonObject result = new JsonObject();
        result.add("rows", measured);
        System.out.println(new GsonBuilder().create().toJson(result));
    }

    /**
     * LOAD the row's memory and time SIT SCENE on the probes: known scenes first (recognised),
     * then new ones (learned), as many as fit in the budget after the LOAD. A LOAD whose reasoning
     * exceeds the budget is reported as such (the core's reasoner time limit stops it).
     */
    private static JsonObject measure(Path scratch, Row row, List<String> known, List<String> fresh, long budgetMs,
                                      long loadBudgetMs) {
        JsonObject result = new JsonObject();
        result.addProperty("reasoner", row.reasoner());
        result.addProperty("buffered_reasoner", row.buffered());
        result.addProperty("learned_scenes", row.size());
        CommandTable table = CommandTable.load(SceneBench.class.getClassLoader());
        try (ArmorCore core = new ArmorCore(new CoreConfig(true, row.reasoner(), List.of(scratch), false, 600_000,
                loadBudgetMs, 0, CoreConfig.Durability.NONE), table)) {
            long started = System.nanoTime();
            double cpu = cpuMs();
            Response loaded = core.execute(Directive.of("bench", "memory", "LOAD", "FILE", "",
                    scratch.resolve("memory-" + row.size() + ".ofn").toString(), "", "false", row.reasoner(),
                    String.valueOf(row.buffered())));
            result.addProperty("load_ms", (System.nanoTime() - started) / 1e6);
            result.addProperty("load_cpu_ms", cpuMs() - cpu);
            if (!loaded.success()) {
                result.addProperty("failed", "LOAD: " + loaded.exitCode() + " " + loaded.errorDescription());
                System.err.println("in the core: " + row + ": " + result.get("failed").getAsString());
                return result;
            }
            long deadline = System.nanoTime() + budgetMs * 1_000_000;
            List<double[]> recognition = new ArrayList<>();
            List<double[]> learning = new ArrayList<>();
            try {
                // The first scene also builds what is kept about the reference: timed apart.
                started = System.nanoTime();
                sit(core, known.get(0), "0.9");
                result.addProperty("first_scene_ms", (System.nanoTime() - started) / 1e6);
                for (String scene : known) {
                    if (System.nanoTime() > deadline) {
                        break;
                    }
                    double[] timed = timed(core, scene, "0.9");
                    recognition.add(timed);
                }
                for (String scene : fresh) {
                    if (System.nanoTime() > deadline) {
                        break;
                    }
                    learning.add(timed(core, scene, "1.0"));
                }
            } catch (IllegalStateException e) {
                result.addProperty("failed", e.getMessage());
            }
            add(result, "recognition", recognition);
            add(result, "learning", learning);
            System.err.printf(Locale.ROOT, "in the core: %s: %d recognitions, p50 %s; %d learnings, p50 %s%n", row,
                    recognition.size(), p50(recognition), learning.size(), p50(learning));
            return result;
        }
    }

    /** Wall and CPU milliseconds of one SIT SCENE; a known scene must not be learned again. */
    private static double[] timed(ArmorCore core, String scene, String threshold) {
        long started = System.nanoTime();
        double cpu = cpuMs();
        Response response = sit(core, scene, threshold);
        double[] timed = {(System.nanoTime() - started) / 1e6, cpuMs() - cpu};
        if (threshold.equals("0.9") && response.queriedObjects().stream().anyMatch(l -> l.startsWith("learned"))) {
            throw new IllegalStateException("a known scene was learned again: " + scene);
        }
        return timed;
    }

    private static void add(JsonObject result, String name, List<double[]> timings) {
        if (timings.isEmpty()) {
            return;
        }
        result.add(name, timings(timings.stream().map(t -> t[0]).toList()));
        result.add(name + "_cpu", timings(timings.stream().map(t -> t[1]).toList()));
    }

    private static String p50(List<double[]> timings) {
        return timings.isEmpty() ? "-" : String.format(Locale.ROOT, "%.1f ms (CPU %.1f ms)",
                timings(timings.stream().map(t -> t[0]).toList()).get("p50_ms").getAsDouble(),
                timings(timings.stream().map(t -> t[1]).toList()).get("p50_ms").getAsDouble());
    }
}
