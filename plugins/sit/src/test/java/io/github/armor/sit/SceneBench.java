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
 *   java -cp ... io.github.armor.sit.SceneBench OUTPUT_DIR SIZES REASONERS SAMPLES [SEED [BUFFERED]]
 * </pre>
 *
 * For each memory size it writes {@code memory-N.ofn}: N scene classes as SIT SCENE learns them,
 * from N generated table tops of 3 to 8 primitives (writing them is quicker than learning them one
 * by one, and gives the same classes), and {@code probes-N.json}: SAMPLES of those scenes to show
 * again (each is recognised, nothing is learned) and SAMPLES new ones (each is learned). Then, for
 * each reasoner, it loads the memory into an ArmorCore with this plugin and times SIT SCENE on the
 * probes, the reference's reasoner brought up to date after each change (or, with BUFFERED "true",
 * only when asked: as ROS 1 SIT loaded its ontology). Prints the figures as JSON.
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

        @Override
        public String render(OWLClass owlClass) {
            return owlClass.getIRI().toString();
        }

        @Override
        public boolean replaying() {
            return false;
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

    public static void main(String[] args) throws Exception {
        Path output = Path.of(args[0]);
        int[] sizes = Arrays.stream(args[1].split(",")).mapToInt(Integer::parseInt).toArray();
        String[] reasoners = args[2].split(",");
        int samples = Integer.parseInt(args[3]);
        long seed = args.length > 4 ? Long.parseLong(args[4]) : 32;
        boolean buffered = args.length > 5 && Boolean.parseBoolean(args[5]);
        Files.createDirectories(output);
        JsonObject result = new JsonObject();
        JsonArray rows = new JsonArray();
        for (int size : sizes) {
            Random random = new Random(seed + size);
            List<String> memory = new ArrayList<>();
            for (int i = 0; i < size; i++) {
                memory.add(generated(random));
            }
            Path file = output.resolve("memory-" + size + ".ofn");
            writeMemory(file, memory);
            List<String> known = new ArrayList<>();
            for (int i = 0; i < samples; i++) {
                known.add(memory.get(random.nextInt(memory.size())));
            }
            List<String> fresh = new ArrayList<>();
            for (int i = 0; i < samples; i++) {
                fresh.add(generated(random));
            }
            JsonObject probes = new JsonObject();
            probes.add("known", new Gson().toJsonTree(known));
            probes.add("new", new Gson().toJsonTree(fresh));
            Files.writeString(output.resolve("probes-" + size + ".json"), probes.toString());
            for (String reasoner : reasoners) {
                rows.add(measure(output, file, reasoner, buffered, size, known, fresh));
            }
        }
        result.add("rows", rows);
        System.out.println(new GsonBuilder().create().toJson(result));
    }

    private static JsonObject measure(Path scratch, Path file, String reasoner, boolean buffered, int size,
                                      List<String> known, List<String> fresh) {
        CommandTable table = CommandTable.load(SceneBench.class.getClassLoader());
        try (ArmorCore core = new ArmorCore(new CoreConfig(true, reasoner, List.of(scratch), false, 600_000, 0, 0,
                CoreConfig.Durability.NONE), table)) {
            long started = System.nanoTime();
            Response loaded = core.execute(Directive.of("bench", "memory", "LOAD", "FILE", "", file.toString(), "",
                    "false", reasoner, String.valueOf(buffered)));
            if (!loaded.success()) {
                throw new IllegalStateException("LOAD failed: " + loaded.errorDescription());
            }
            double loadMs = (System.nanoTime() - started) / 1e6;
            // The first scene also builds the reasoner's view of the classes: timed apart.
            started = System.nanoTime();
            sit(core, known.get(0), "0.9");
            double firstMs = (System.nanoTime() - started) / 1e6;
            List<Double> recognition = new ArrayList<>();
            List<Double> recognitionCpu = new ArrayList<>();
            for (String scene : known) {
                started = System.nanoTime();
                double cpu = cpuMs();
                Response response = sit(core, scene, "0.9");
                recognition.add((System.nanoTime() - started) / 1e6);
                recognitionCpu.add(cpuMs() - cpu);
                if (response.queriedObjects().stream().anyMatch(line -> line.startsWith("learned"))) {
                    throw new IllegalStateException("a known scene was learned again: " + scene);
                }
            }
            List<Double> learning = new ArrayList<>();
            List<Double> learningCpu = new ArrayList<>();
            for (String scene : fresh) {
                started = System.nanoTime();
                double cpu = cpuMs();
                sit(core, scene, "1.0");
                learning.add((System.nanoTime() - started) / 1e6);
                learningCpu.add(cpuMs() - cpu);
            }
            JsonObject row = new JsonObject();
            row.addProperty("reasoner", reasoner);
            row.addProperty("buffered_reasoner", buffered);
            row.addProperty("learned_scenes", size);
            row.addProperty("load_ms", loadMs);
            row.addProperty("first_scene_ms", firstMs);
            row.add("recognition", timings(recognition));
            row.add("learning", timings(learning));
            row.add("recognition_cpu", timings(recognitionCpu));
            row.add("learning_cpu", timings(learningCpu));
            System.err.printf(Locale.ROOT, "in the core: %s%s, %d learned: recognition p50 %.1f ms (CPU %.1f ms),"
                    + " learning p50 %.1f ms (CPU %.1f ms)%n", reasoner, buffered ? " buffered" : "", size,
                    timings(recognition).get("p50_ms").getAsDouble(), timings(recognitionCpu).get("p50_ms").getAsDouble(),
                    timings(learning).get("p50_ms").getAsDouble(), timings(learningCpu).get("p50_ms").getAsDouble());
            return row;
        }
    }
}
