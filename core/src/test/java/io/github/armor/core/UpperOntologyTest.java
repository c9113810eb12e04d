// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Response;
import io.github.armor.core.reasoning.ClassifiedSchema;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.util.SimpleIRIMapper;

/**
 * A reference over an upper ontology (issue 36, SOMA's shape in small): its schema is classified
 * once and the classification kept across ABox changes and restarts; its modules are realised
 * against its own classes and those asked about, not every class of the upper ontology; LOAD
 * says what the schema cost. Every answer is checked against the reasoner on the whole ontology.
 */
class UpperOntologyTest {
    private static final String UPPER = "http://www.example.org/upper";
    private static final String KITCHEN = "http://www.example.org/kitchen";
    // Containment is transitive and only its inverse is asserted; State names individuals (nominals).
    private static final String UPPER_ONTOLOGY = """
            Prefix(:=<http://www.example.org/upper#>)
            Ontology(<http://www.example.org/upper>
            Declaration(Class(:PhysicalObject)) Declaration(Class(:Container)) Declaration(Class(:Drawer))
            Declaration(Class(:Cupboard)) Declaration(Class(:Tableware)) Declaration(Class(:Cup))
            Declaration(Class(:Plate)) Declaration(Class(:Filled)) Declaration(Class(:State))
            Declaration(Class(:Agent)) Declaration(Class(:Robot))
            Declaration(ObjectProperty(:isInsideOf)) Declaration(ObjectProperty(:containsObject))
            Declaration(NamedIndividual(:active)) Declaration(NamedIndividual(:paused))
            SubClassOf(:Container :PhysicalObject) SubClassOf(:Drawer :Container) SubClassOf(:Cupboard :Container)
            SubClassOf(:Tableware :PhysicalObject) SubClassOf(:Cup :Tableware) SubClassOf(:Plate :Tableware)
            SubClassOf(:Robot :Agent) DisjointClasses(:Agent :Tableware)
            EquivalentClasses(:Filled ObjectIntersectionOf(:Container ObjectSomeValuesFrom(:containsObject owl:Thing)))
            EquivalentClasses(:State ObjectOneOf(:active :paused))
            ClassAssertion(:State :active) ClassAssertion(:State :paused)
            TransitiveObjectProperty(:isInsideOf) InverseObjectProperties(:isInsideOf :containsObject)
            ObjectPropertyDomain(:isInsideOf :PhysicalObject) ObjectPropertyRange(:isInsideOf :PhysicalObject)
            )
            """;
    private static final String KITCHEN_ONTOLOGY = """
            Prefix(:=<http://www.example.org/kitchen#>)
            Prefix(u:=<http://www.example.org/upper#>)
            Ontology(<http://www.example.org/kitchen>
            Import(<http://www.example.org/upper>)
            Declaration(Class(:ContainerWithCup))
            EquivalentClasses(:ContainerWithCup ObjectIntersectionOf(u:Container ObjectSomeValuesFrom(u:containsObject u:Cup)))
            ClassAssertion(u:Cupboard :cupboard1) ClassAssertion(u:Drawer :drawer1) ClassAssertion(u:Drawer :drawer2)
            ClassAssertion(u:Drawer :drawer3) ClassAssertion(u:Cup :cup1) ClassAssertion(u:Cup :cup2)
            ClassAssertion(u:Plate :plate1) ClassAssertion(u:Robot :robot1)
            ObjectPropertyAssertion(u:isInsideOf :drawer1 :cupboard1) ObjectPropertyAssertion(u:isInsideOf :cup1 :drawer1)
            ObjectPropertyAssertion(u:isInsideOf :cup2 :drawer3) ObjectPropertyAssertion(u:isInsideOf :plate1 :drawer2)
            )
            """;

    @TempDir
    Path scratch;

    private final List<ArmorCore> cores = new ArrayList<>();

    @AfterEach
    void closeCores() {
        cores.forEach(ArmorCore::close);
    }

    private Path write() throws IOException {
        Files.writeString(scratch.resolve("upper.ofn"), UPPER_ONTOLOGY);
        return Files.writeString(scratch.resolve("kitchen.ofn"), KITCHEN_ONTOLOGY);
    }

    private CoreFixture fixture() {
        CoreFixture fixture = new CoreFixture(scratch);
        cores.add(fixture.core);
        return fixture;
    }

    /** A core on the state directory, the previous ones closed first (a restart), reading files in scratch. */
    private CoreFixture restart(Path state) {
        cores.forEach(ArmorCore::close);
        cores.clear();
        ArmorCore core = new ArmorCore(new CoreConfig(true, "HERMIT", List.of(scratch), false, 30_000, 0, 0,
                new CoreConfig.Durability(state, true, false, 1000, 3600)));
        core.restoreState();
        cores.add(core);
        return new CoreFixture(core);
    }

    private static Set<String> shortNames(Response response) {
        return response.queriedObjects().stream().map(iri -> iri.substring(iri.lastIndexOf('#') + 1, iri.length() - 1))
                .collect(Collectors.toCollection(TreeSet::new));
    }

    /** What the reasoner on the whole ontology (the files as they are plus the moves made) answers. */
    private Set<String> whole(String reasoner, List<String[]> moves,
                              Function<WholeOntology, Stream<? extends OWLEntity>> question) throws Exception {
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        manager.getIRIMappers().add(new SimpleIRIMapper(IRI.create(UPPER), IRI.create(scratch.resolve("upper.ofn")
                .toFile())));
        OWLOntology ontology = manager.loadOntologyFromOntologyDocument(scratch.resolve("kitchen.ofn").toFile());
        OWLDataFactory data = manager.getOWLDataFactory();
        for (String[] move : moves) {
            var inside = data.getOWLObjectProperty(IRI.create(UPPER + "#isInsideOf"));
            manager.removeAxiom(ontology, data.getOWLObjectPropertyAssertionAxiom(inside, kitchen(data, move[0]),
                    kitchen(data, move[2])));
            manager.addAxiom(ontology, data.getOWLObjectPropertyAssertionAxiom(inside, kitchen(data, move[0]),
                    kitchen(data, move[1])));
        }
        OWLReasonerFactory factory = reasoner.equals("HERMIT") ? new org.semanticweb.HermiT.ReasonerFactory()
                : openllet.owlapi.OpenlletReasonerFactory.getInstance();
        OWLReasoner plain = factory.createReasoner(ontology);
        try {
            return question.apply(new WholeOntology(plain, data)).filter(e -> !e.isBuiltIn())
                    .map(e -> e.getIRI().getShortForm()).collect(Collectors.toCollection(TreeSet::new));
        } finally {
            plain.dispose();
        }
    }

    private record WholeOntology(OWLReasoner reasoner, OWLDataFactory data) {
        org.semanticweb.owlapi.model.OWLClass upper(String name) {
            return data.getOWLClass(IRI.create(UPPER + "#" + name));
        }

        org.semanticweb.owlapi.model.OWLClass own(String name) {
            return data.getOWLClass(IRI.create(KITCHEN + "#" + name));
        }
    }

    private static org.semanticweb.owlapi.model.OWLNamedIndividual kitchen(OWLDataFactory data, String name) {
        return data.getOWLNamedIndividual(IRI.create(KITCHEN + "#" + name));
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void aMoveDoesNotClassifyAgainAndEveryAnswerIsTheWholeOntologyReasoners(String reasoner) throws Exception {
        Path file = write();
        CoreFixture f = fixture();
        ClassifiedSchema.forgetKept();
        long before = ClassifiedSchema.classifications();
        String loaded = f.ok("k", "LOAD FILE", file.toString(), "", "false", reasoner, "false").errorDescription();
        // Over an upper ontology the schema is classified in the background; it may be done already.
        assertTrue(loaded.matches("profile: OWL 2 DL; 12 classes, (classified in|being classified in the background)"
                + " [^;]+; reasoning in modules: .*"), loaded);

        List<String[]> moves = new ArrayList<>();
        assertEquals(whole(reasoner, moves, w -> w.reasoner().getInstances(w.own("ContainerWithCup")).entities()),
                shortNames(f.ok("k", "QUERY IND CLASS", "ContainerWithCup")));
        assertEquals(Set.of("cupboard1", "drawer1", "drawer3"), shortNames(f.ok("k", "QUERY IND CLASS",
                "ContainerWithCup")), "transitive containment through the inverse");

        String[] move = {"cup2", "drawer2", "drawer3"};
        moves.add(move);
        f.ok("k", "REPLACE OBJECTPROP IND", "<" + UPPER + "#isInsideOf>", move[0], move[1], move[2]);
        f.ok("k", "REASON");
        assertEquals(whole(reasoner, moves, w -> w.reasoner().getInstances(w.own("ContainerWithCup")).entities()),
                shortNames(f.ok("k", "QUERY IND CLASS", "ContainerWithCup")));
        // A class of the upper ontology, asked for the first time: realised from now on.
        assertEquals(whole(reasoner, moves, w -> w.reasoner().getInstances(w.upper("Filled")).entities()),
                shortNames(f.ok("k", "QUERY IND CLASS", "<" + UPPER + "#Filled>")));
        // Every type of one individual, and the hierarchy, from the classification kept.
        assertEquals(whole(reasoner, moves, w -> w.reasoner().getTypes(kitchen(w.data(), "drawer2")).entities()),
                shortNames(f.ok("k", "QUERY CLASS IND", "drawer2")));
        assertEquals(whole(reasoner, moves, w -> w.reasoner().getTypes(kitchen(w.data(), "drawer2"), true).entities()),
                shortNames(f.ok("k", "QUERY CLASS IND", "drawer2", "true")));
        assertEquals(whole(reasoner, moves, w -> w.reasoner().getSuperClasses(w.own("ContainerWithCup")).entities()),
                shortNames(f.ok("k", "QUERY CLASS SUPER", "ContainerWithCup")));
        assertTrue(f.ok("k", "LOAD FILE", file.toString(), "", "false", reasoner, "false").errorDescription()
                .contains("12 classes, classified in"), "a class question waits for the classification");
        assertEquals(whole(reasoner, moves, w -> w.reasoner().getSubClasses(w.upper("Container")).entities()),
                shortNames(f.ok("k", "QUERY CLASS CLASS", "<" + UPPER + "#Container>")));
        assertEquals(before + 1, ClassifiedSchema.classifications(), "ABox changes keep the classification");

        f.ok("k", "ADD CLASS CLASS", "Mug", "<" + UPPER + "#Cup>");
        assertEquals(Set.of("Mug"), shortNames(f.ok("k", "QUERY CLASS CLASS", "<" + UPPER + "#Cup>")));
        assertEquals(before + 2, ClassifiedSchema.classifications(), "a schema change classifies again");
    }

    @Test
    void aRestartReadsTheClassificationBesideTheCheckpointInsteadOfClassifying() throws Exception {
        Path file = write();
        Path state = scratch.resolve("state");
        ClassifiedSchema.forgetKept();
        CoreFixture f = restart(state);
        f.ok("k", "LOAD FILE", file.toString(), "", "false", "HERMIT", "false");
        f.ok("k", "QUERY CLASS SUPER", "ContainerWithCup"); // waits for the classification in the background
        // The next change writes it beside the checkpoint.
        f.ok("k", "REPLACE OBJECTPROP IND", "<" + UPPER + "#isInsideOf>", "cup2", "drawer2", "drawer3");
        Set<String> answer = shortNames(f.ok("k", "QUERY IND CLASS", "ContainerWithCup"));

        long before = ClassifiedSchema.classifications();
        ClassifiedSchema.forgetKept(); // what a new core process knows
        CoreFixture restored = restart(state);
        assertEquals(answer, shortNames(restored.ok("k", "QUERY IND CLASS", "ContainerWithCup")));
        assertEquals(Set.of("Container", "Filled", "PhysicalObject"), shortNames(restored.ok("k", "QUERY CLASS SUPER",
                "ContainerWithCup")));
        assertEquals(before, ClassifiedSchema.classifications(), "the restart classified again");

        // Without the sidecar the restart must classify: what the check above relies on.
        try (Stream<Path> files = Files.walk(state)) {
            for (Path sidecar : files.filter(p -> p.getFileName().toString().equals("classified-schema.json"))
                    .toList()) {
                Files.delete(sidecar);
            }
        }
        ClassifiedSchema.forgetKept();
        CoreFixture again = restart(state);
        assertEquals(answer, shortNames(again.ok("k", "QUERY IND CLASS", "ContainerWithCup")));
        assertEquals(before + 1, ClassifiedSchema.classifications());
    }
}
