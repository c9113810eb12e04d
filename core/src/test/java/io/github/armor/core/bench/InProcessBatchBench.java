// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.bench;

import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.reference.ReasonerRegistry;
import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.reasoner.OWLReasoner;

/**
 * The in-process limit of the batch-throughput benchmark (bench/batch_throughput.py): the same
 * directive lists the benchmark sends to {@code armor_interface_serialized_srv}, run in this JVM
 * with no service around them, along two paths:
 * <ul>
 *   <li>{@code armor_core}: {@link ArmorCore#executeList} (dispatch, naming, atomic lists), no
 *       socket, no JSON, no ROS, no journal;</li>
 *   <li>{@code owlapi}: the same axioms added straight through the OWL API, one change per
 *       directive, with the reasoner kept up to date exactly as a reference does.</li>
 * </ul>
 * A main method, not a JUnit test: Maven compiles it with the tests so it cannot rot, and the
 * benchmark runs it with {@code java -cp core/target/test-classes:core/target/classes:core/target/lib/*}.
 *
 * <pre>
 * InProcessBatchBench ONTOLOGY LIST_SIZE LISTS WARMUP_LISTS REASONER BUFFERED_REASONER MAX_SECONDS
 * </pre>
 * Prints one JSON object per path on stdout; logging goes to stderr. After its lists (untimed) each
 * path must hold every agent they added as a RobotInRoom, an inference from both kinds of directive,
 * or the run fails: a figure of lists that did not do their work measures nothing.
 */
public final class InProcessBatchBench {
    private static final String NS = "http://www.example.org/robotics#";
    private static final String[] ROOMS = {"kitchen", "bedroom"};

    private InProcessBatchBench() {}

    /** What one path achieved. */
    private record Result(String path, int listSize, int lists, double seconds, double[] listSeconds) {
        String json() {
            double[] sorted = listSeconds.clone();
            Arrays.sort(sorted);
            return String.format(Locale.ROOT, "{\"path\": \"%s\", \"list_size\": %d, \"lists\": %d, "
                            + "\"directives\": %d, \"seconds\": %.6f, \"per_s\": %.1f, \"list_ms_p50\": %.3f}",
                    path, listSize, lists, listSize * lists, seconds, listSize * lists / seconds,
                    sorted[sorted.length / 2] * 1000);
        }
    }

    public static void main(String[] args) throws Exception {
        if (args.length != 7) {
            System.err.println("usage: InProcessBatchBench ONTOLOGY LIST_SIZE LISTS WARMUP_LISTS REASONER "
                    + "BUFFERED_REASONER MAX_SECONDS");
            System.exit(2);
        }
        Path ontology = Path.of(args[0]).toAbsolutePath();
        int listSize = Integer.parseInt(args[1]);
        int lists = Integer.parseInt(args[2]);
        int warmupLists = Integer.parseInt(args[3]);
        String reasoner = args[4];
        boolean bufferedReasoner = Boolean.parseBoolean(args[5]);
        double maxSeconds = Double.parseDouble(args[6]);
        System.out.println(armorCore(ontology, listSize, lists, warmupLists, reasoner, bufferedReasoner, maxSeconds)
                .json());
        System.out.println(owlApi(ontology, listSize, lists, warmupLists, reasoner, bufferedReasoner, maxSeconds)
                .json());
    }

    /**
     * The directives of list {@code list}: pairs of "a new agent is a Robot" and "it is in a room",
     * the same names bench/batch_throughput.py sends (two directives per agent).
     */
    static List<Directive> directives(String reference, int list, int listSize) {
        List<Directive> directives = new ArrayList<>(listSize);
        for (int i = 0; i < listSize; i++) {
            String agent = agent(list, i / 2);
            directives.add(i % 2 == 0
                    ? Directive.of("bench", reference, "ADD", "IND", "CLASS", agent, "Robot")
                    : Directive.of("bench", reference, "ADD", "OBJECTPROP", "IND", "isIn", agent, ROOMS[(i / 2) % 2]));
        }
        return directives;
    }

    private static String agent(int list, int index) {
        return "agent" + list + "_" + index;
    }

    /** robotics.owl's robot1 and the agents of {@code lists} lists: the RobotInRoom members they leave. */
    private static Set<String> robotsInRooms(int lists, int listSize) {
        Set<String> expected = new TreeSet<>(Set.of(NS + "robot1"));
        for (int list = 0; list < lists; list++) {
            for (int i = 0; i < listSize / 2; i++) {
                expected.add(NS + agent(list, i));
            }
        }
        return expected;
    }

    private static void check(String path, Set<String> found, int lists, int listSize) {
        Set<String> expected = robotsInRooms(lists, listSize);
        if (!found.equals(expected)) {
            throw new IllegalStateException(path + ": " + found.size() + " robots in rooms after " + lists
                    + " lists, expected " + expected.size());
        }
    }

    private static Result armorCore(Path ontology, int listSize, int lists, int warmupLists, String reasoner,
                                    boolean bufferedReasoner, double maxSeconds) {
        ArmorCore core = new ArmorCore(CoreConfig.defaults(ontology.getParent()));
        Response loaded = core.execute(Directive.of("bench", "batch", "LOAD", "FILE", "", ontology.toString(), "",
                "false", reasoner, String.valueOf(bufferedReasoner)));
        if (!loaded.success()) {
            throw new IllegalStateException("LOAD failed: " + loaded.exitCode() + " " + loaded.errorDescription());
        }
        Timer timer = new Timer(lists, maxSeconds);
        for (int list = 0; timer.more(list, warmupLists); list++) {
            List<Directive> directives = directives("batch", list, listSize);
            long start = System.nanoTime();
            ListResponse answer = core.executeList(directives);
            timer.record(list, warmupLists, start);
            if (!answer.success()) {
                throw new IllegalStateException("list " + list + " failed: " + answer.responses());
            }
        }
        core.execute(Directive.of("bench", "batch", "REASON", "", ""));
        Response robots = core.execute(Directive.of("bench", "batch", "QUERY", "IND", "CLASS", "RobotInRoom"));
        check("armor_core", robots.queriedObjects().stream().map(iri -> iri.replaceAll("^<|>$", ""))
                .collect(Collectors.toCollection(TreeSet::new)), timer.listsRun(), listSize);
        return timer.result("armor_core", listSize);
    }

    private static Result owlApi(Path ontologyPath, int listSize, int lists, int warmupLists, String reasonerName,
                                 boolean bufferedReasoner, double maxSeconds) throws OWLOntologyCreationException {
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        OWLOntology ontology = manager.loadOntologyFromOntologyDocument(new File(ontologyPath.toString()));
        OWLDataFactory factory = manager.getOWLDataFactory();
        OWLReasoner reasoner = ReasonerRegistry.factory(reasonerName).createReasoner(ontology);
        reasoner.isConsistent();
        Timer timer = new Timer(lists, maxSeconds);
        for (int list = 0; timer.more(list, warmupLists); list++) {
            long start = System.nanoTime();
            for (int i = 0; i < listSize; i++) {
                var agent = factory.getOWLNamedIndividual(IRI.create(NS + agent(list, i / 2)));
                OWLAxiom axiom = i % 2 == 0
                        ? factory.getOWLClassAssertionAxiom(factory.getOWLClass(IRI.create(NS + "Robot")), agent)
                        : factory.getOWLObjectPropertyAssertionAxiom(factory.getOWLObjectProperty(IRI.create(NS + "isIn")),
                        agent, factory.getOWLNamedIndividual(IRI.create(NS + ROOMS[(i / 2) % 2])));
                manager.addAxiom(ontology, axiom);
                if (!bufferedReasoner) {
                    // What a reference with a non-buffered reasoner does after every enacted change.
                    reasoner.flush();
                    reasoner.isConsistent();
                }
            }
            timer.record(list, warmupLists, start);
        }
        reasoner.flush();
        check("owlapi", reasoner.getInstances(factory.getOWLClass(IRI.create(NS + "RobotInRoom")), false)
                .entities().map(i -> i.getIRI().toString()).collect(Collectors.toCollection(TreeSet::new)),
                timer.listsRun(), listSize);
        reasoner.dispose();
        return timer.result("owlapi", listSize);
    }

    /** Runs warm-up lists, then measured lists until the count or the wall-clock budget runs out. */
    private static final class Timer {
        private final int lists;
        private final long budgetNanos;
        private final List<Double> listSeconds = new ArrayList<>();
        private long deadline;
        private int listsRun;

        Timer(int lists, double maxSeconds) {
            this.lists = lists;
            this.budgetNanos = (long) (maxSeconds * 1e9);
        }

        boolean more(int list, int warmupLists) {
            if (list < warmupLists) {
                return true;
            }
            if (list == warmupLists) {
                deadline = System.nanoTime() + budgetNanos;
            }
            // At least one measured list, however slow, so there is always a figure.
            return listSeconds.isEmpty() || (listSeconds.size() < lists && System.nanoTime() < deadline);
        }

        void record(int list, int warmupLists, long startNanos) {
            listsRun++;
            if (list >= warmupLists) {
                listSeconds.add((System.nanoTime() - startNanos) / 1e9);
            }
        }

        /** Lists run so far, warm-up lists included. */
        int listsRun() {
            return listsRun;
        }

        Result result(String path, int listSize) {
            double[] seconds = listSeconds.stream().mapToDouble(Double::doubleValue).toArray();
            return new Result(path, listSize, seconds.length, Arrays.stream(seconds).sum(), seconds);
        }
    }
}
