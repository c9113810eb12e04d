// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.bench;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonParser;
import io.github.armor.core.reasoning.ModularReasoner;
import io.github.armor.core.reference.ReasonerRegistry;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.AddAxiom;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.RemoveAxiom;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;

/**
 * The directions of issue 15 side by side, in this JVM with no service around them: the robot's
 * cycle (an agent moves, then "which rooms are occupied") kept up to date by each way of
 * reasoning under ABox changes, every answer checked.
 * <ul>
 *   <li>{@code rebuild:R}: reasoner R on the whole ontology, replaced after a removal (the
 *       service before issue 15, for reasoners that keep removed inferences);</li>
 *   <li>{@code openllet-incremental}: Openllet's incremental consistency checking and deletion
 *       ({@code USE_INCREMENTAL_CONSISTENCY}, {@code USE_INCREMENTAL_DELETION}), flushed;</li>
 *   <li>{@code flush:R}: reasoner R on the whole ontology, only flushed (HermiT updates its ABox;
 *       ELK updates incrementally but misses what is outside OWL 2 EL);</li>
 *   <li>{@code modular:R}: {@link ModularReasoner} over R.</li>
 * </ul>
 * A main method, compiled with the tests; bench/robot_speed.py runs it, one JVM per direction
 * (Openllet's options are global).
 *
 * <pre>ReasoningDirectionsBench ONTOLOGY MOVES_JSON CYCLES DIRECTION</pre>
 * MOVES_JSON: [[agent, new room, old room, [occupied rooms after the move]], ...]. Prints one
 * JSON object on stdout.
 */
public final class ReasoningDirectionsBench {
    private static final String NS = "http://www.example.org/robotics#";

    private ReasoningDirectionsBench() {}

    public static void main(String[] args) throws Exception {
        File ontologyFile = new File(args[0]);
        JsonArray moves = JsonParser.parseString(Files.readString(Path.of(args[1]))).getAsJsonArray();
        int cycles = Math.min(Integer.parseInt(args[2]), moves.size());
        String direction = args[3];
        String reasonerName = direction.contains(":") ? direction.substring(direction.indexOf(':') + 1) : "PELLET";
        if (direction.equals("openllet-incremental")) {
            openllet.core.OpenlletOptions.USE_INCREMENTAL_CONSISTENCY = true;
            openllet.core.OpenlletOptions.USE_INCREMENTAL_DELETION = true;
        }
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        OWLOntology ontology = manager.loadOntologyFromOntologyDocument(ontologyFile);
        OWLDataFactory factory = manager.getOWLDataFactory();
        OWLClass occupied = factory.getOWLClass(IRI.create(NS + "OccupiedRoom"));
        OWLObjectProperty isIn = factory.getOWLObjectProperty(IRI.create(NS + "isIn"));
        OWLReasonerFactory reasonerFactory = ReasonerRegistry.factory(reasonerName);

        long start = System.nanoTime();
        OWLReasoner reasoner = direction.startsWith("modular:")
                ? new ModularReasoner(reasonerName, reasonerFactory, ontology, new SimpleConfiguration())
                : reasonerFactory.createReasoner(ontology);
        reasoner.isConsistent();
        occupants(reasoner, occupied);
        double firstMs = (System.nanoTime() - start) / 1e6;

        List<Double> cycleMs = new ArrayList<>();
        int wrong = 0;
        for (int i = 0; i < cycles; i++) {
            JsonArray move = moves.get(i).getAsJsonArray();
            OWLNamedIndividual agent = individual(factory, move.get(0).getAsString());
            long cycleStart = System.nanoTime();
            manager.applyChanges(List.of(
                    new RemoveAxiom(ontology, factory.getOWLObjectPropertyAssertionAxiom(isIn, agent,
                            individual(factory, move.get(2).getAsString()))),
                    new AddAxiom(ontology, factory.getOWLObjectPropertyAssertionAxiom(isIn, agent,
                            individual(factory, move.get(1).getAsString())))));
            if (direction.startsWith("rebuild:")) {
                reasoner.dispose();
                reasoner = reasonerFactory.createReasoner(ontology);
            } else {
                reasoner.flush();
            }
            boolean consistent = reasoner.isConsistent();
            Set<String> answer = occupants(reasoner, occupied);
            cycleMs.add((System.nanoTime() - cycleStart) / 1e6);
            Set<String> expected = new TreeSet<>();
            for (JsonElement room : move.get(3).getAsJsonArray()) {
                expected.add(room.getAsString());
            }
            if (!consistent || !answer.equals(expected)) {
                wrong++;
            }
        }
        Collections.sort(cycleMs);
        Runtime runtime = Runtime.getRuntime();
        System.gc();
        System.out.printf(Locale.ROOT, "{\"direction\": \"%s\", \"first_ms\": %.1f, \"cycles\": %d, "
                        + "\"cycle_p50_ms\": %.3f, \"cycle_max_ms\": %.3f, \"wrong\": %d, \"heap_mib\": %d}%n",
                direction, firstMs, cycles, cycleMs.get(cycleMs.size() / 2), cycleMs.get(cycleMs.size() - 1), wrong,
                (runtime.totalMemory() - runtime.freeMemory()) >> 20);
        System.exit(0);
    }

    private static OWLNamedIndividual individual(OWLDataFactory factory, String name) {
        return factory.getOWLNamedIndividual(IRI.create(NS + name));
    }

    private static Set<String> occupants(OWLReasoner reasoner, OWLClass occupied) {
        return reasoner.getInstances(occupied, false).entities().map(i -> i.getIRI().getShortForm())
                .collect(Collectors.toCollection(TreeSet::new));
    }
}
