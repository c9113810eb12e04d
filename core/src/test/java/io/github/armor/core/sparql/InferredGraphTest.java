// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import io.github.armor.core.answers.Inferences;
import io.github.armor.core.reference.Reference;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import org.apache.jena.graph.Graph;
import org.apache.jena.graph.GraphUtil;
import org.apache.jena.graph.NodeFactory;
import org.apache.jena.graph.Triple;
import org.apache.jena.rdf.model.Model;
import org.apache.jena.rdf.model.ModelFactory;
import org.apache.jena.sparql.graph.GraphFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.formats.NTriplesDocumentFormat;
import org.semanticweb.owlapi.model.AddAxiom;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.RemoveAxiom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The SPARQL graph holds exactly the triples of the ontology saved with its inferences (the
 * graph SPARQL answered from before it was kept between queries), whether built afresh or
 * derived from the previous state's graph after changes.
 */
class InferredGraphTest {
    private static final Path ROBOTICS = Path.of("..", "ontologies", "robotics.owl").toAbsolutePath().normalize();
    private static final String NS = "http://www.example.org/robotics#";
    private static final Path LUBM = Path.of("..", "bench", "data", "lubm", "university0-department0.owl")
            .toAbsolutePath().normalize();

    private final OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
    private final OWLDataFactory factory = manager.getOWLDataFactory();

    private Reference open(OWLOntology ontology, String reasoner, boolean bufferedReasoner) {
        return Reference.open("graph-test", ontology, new Reference.Settings(null, "", reasoner, false,
                bufferedReasoner), 0);
    }

    private OWLOntology robotics() throws Exception {
        return manager.loadOntologyFromOntologyDocument(new File(ROBOTICS.toString()));
    }

    /** The graph as QUERY SPARQL built it for every query before: SAVE INFERENCE's copy, through N-Triples. */
    private static Graph savedWithInferences(Reference reference) throws Exception {
        OWLOntology inferred = Inferences.withInferences(reference);
        ByteArrayOutputStream triples = new ByteArrayOutputStream();
        inferred.getOWLOntologyManager().saveOntology(inferred, new NTriplesDocumentFormat(), triples);
        Model model = ModelFactory.createDefaultModel();
        model.read(new ByteArrayInputStream(triples.toByteArray()), null, "N-TRIPLES");
        return model.getGraph();
    }

    private static void assertSameTriples(Graph expected, Graph actual, String when) {
        Graph copy = GraphFactory.createGraphMem();
        GraphUtil.addInto(copy, actual);
        assertEquals(expected.size(), copy.size(), () -> when + ": triple counts differ; missing "
                + difference(expected, copy) + ", extra " + difference(copy, expected));
        assertTrue(expected.isIsomorphicWith(copy), () -> when + ": graphs differ; missing "
                + difference(expected, copy) + ", extra " + difference(copy, expected));
    }

    private static List<Triple> difference(Graph a, Graph b) {
        List<Triple> missing = new ArrayList<>();
        a.find().forEachRemaining(t -> {
            if (!t.getSubject().isBlank() && !t.getObject().isBlank() && !b.contains(t)) {
                missing.add(t);
            }
        });
        return missing.size() > 10 ? missing.subList(0, 10) : missing;
    }

    private OWLNamedIndividual individual(String name) {
        return factory.getOWLNamedIndividual(IRI.create(NS + name));
    }

    private OWLClass owlClass(String name) {
        return factory.getOWLClass(IRI.create(NS + name));
    }

    private OWLObjectProperty objectProperty(String name) {
        return factory.getOWLObjectProperty(IRI.create(NS + name));
    }

    private OWLDataProperty dataProperty(String name) {
        return factory.getOWLDataProperty(IRI.create(NS + name));
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT", "ELK"})
    void freshGraphHoldsTheOntologyWithItsInferences(String reasoner) throws Exception {
        Reference reference = open(robotics(), reasoner, false);
        reference.reason();
        assertSameTriples(savedWithInferences(reference), SparqlGraphs.current(reference).graph(), reasoner);
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void graphDerivedAfterAssertionsEqualsAFreshOne(String reasoner) throws Exception {
        OWLOntology ontology = robotics();
        Reference reference = open(ontology, reasoner, false);
        InferredGraph first = SparqlGraphs.current(reference);
        assertSame(first, SparqlGraphs.current(reference), "an unchanged reference keeps its graph");
        List<Function<OWLOntology, OWLOntologyChange>> steps = List.of(
                // a new individual in a room: the room becomes an OccupiedRoom, contains gets a value
                o -> new AddAxiom(o, factory.getOWLObjectPropertyAssertionAxiom(objectProperty("isIn"),
                        individual("bob"), individual("bedroom"))),
                o -> new AddAxiom(o, factory.getOWLClassAssertionAxiom(owlClass("Robot"), individual("bob"))),
                o -> new AddAxiom(o, factory.getOWLDataPropertyAssertionAxiom(dataProperty("batteryLevel"),
                        individual("bob"), 42)),
                o -> new AddAxiom(o, factory.getOWLDeclarationAxiom(individual("carol"))),
                // symmetric: both rooms change
                o -> new AddAxiom(o, factory.getOWLObjectPropertyAssertionAxiom(objectProperty("connectedTo"),
                        individual("kitchen"), individual("bedroom"))),
                // the only agent leaves the kitchen: it is no longer an OccupiedRoom
                o -> new RemoveAxiom(o, factory.getOWLObjectPropertyAssertionAxiom(objectProperty("isIn"),
                        individual("robot1"), individual("kitchen"))),
                // bob disappears altogether, one assertion at a time
                o -> new RemoveAxiom(o, factory.getOWLDataPropertyAssertionAxiom(dataProperty("batteryLevel"),
                        individual("bob"), 42)),
                o -> new RemoveAxiom(o, factory.getOWLClassAssertionAxiom(owlClass("Robot"), individual("bob"))),
                o -> new RemoveAxiom(o, factory.getOWLObjectPropertyAssertionAxiom(objectProperty("isIn"),
                        individual("bob"), individual("bedroom"))));
        for (int step = 0; step < steps.size(); step++) {
            OWLOntologyChange change = steps.get(step).apply(ontology);
            reference.change(List.of(change));
            InferredGraph derived = SparqlGraphs.current(reference);
            assertTrue(derived.derivable(), "a graph derived from assertions allows the next derivation");
            assertInstanceOf(LayeredGraph.class, derived.graph(), "step " + step + " (" + change
                    + ") derives the graph instead of building it");
            assertSameTriples(savedWithInferences(reference), derived.graph(), "after step " + step + " " + change);
        }
    }

    @Test
    void graphIsBuiltAfreshWhenTheClassHierarchyChanges() throws Exception {
        OWLOntology ontology = robotics();
        Reference reference = open(ontology, "HERMIT", false);
        SparqlGraphs.current(reference);
        reference.change(List.of(new AddAxiom(ontology, factory.getOWLSubClassOfAxiom(owlClass("Robot"),
                owlClass("Person")))));
        Graph graph = SparqlGraphs.current(reference).graph();
        assertFalse(graph instanceof LayeredGraph, "a schema change builds the graph afresh");
        assertTrue(graph.contains(NodeFactory.createURI(NS + "robot1"), RdfTerms.TYPE,
                NodeFactory.createURI(NS + "Person")));
        assertSameTriples(savedWithInferences(reference), graph, "after a subclass axiom");
    }

    /**
     * Value restrictions, functional and transitive properties let a reasoner conclude property
     * values between individuals that no assertion connects: each change asks about every value.
     */
    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void openOntologiesStayCompleteAfterChanges(String reasoner) throws Exception {
        OWLOntology ontology = robotics();
        OWLObjectProperty partOf = objectProperty("partOf");
        OWLObjectProperty poweredBy = objectProperty("poweredBy");
        List<OWLAxiom> schema = List.of(
                factory.getOWLTransitiveObjectPropertyAxiom(partOf),
                factory.getOWLFunctionalObjectPropertyAxiom(poweredBy),
                factory.getOWLSubClassOfAxiom(owlClass("Robot"), factory.getOWLObjectHasValue(poweredBy,
                        individual("battery1"))));
        schema.forEach(axiom -> manager.addAxiom(ontology, axiom));
        Reference reference = open(ontology, reasoner, false);
        SparqlGraphs.current(reference);
        List<OWLAxiom> assertions = List.of(
                factory.getOWLObjectPropertyAssertionAxiom(partOf, individual("kitchen"), individual("floor1")),
                factory.getOWLObjectPropertyAssertionAxiom(partOf, individual("floor1"), individual("house")),
                factory.getOWLClassAssertionAxiom(owlClass("Robot"), individual("bob")),
                factory.getOWLObjectPropertyAssertionAxiom(poweredBy, individual("robot1"), individual("cell7")));
        for (OWLAxiom assertion : assertions) {
            reference.change(List.of(new AddAxiom(ontology, assertion)));
            assertSameTriples(savedWithInferences(reference), SparqlGraphs.current(reference).graph(),
                    "after " + assertion);
        }
        Graph graph = SparqlGraphs.current(reference).graph();
        assertTrue(graph.contains(NodeFactory.createURI(NS + "kitchen"), RdfTerms.entity(partOf),
                NodeFactory.createURI(NS + "house")), "transitivity");
        assertTrue(graph.contains(NodeFactory.createURI(NS + "bob"), RdfTerms.entity(poweredBy),
                NodeFactory.createURI(NS + "battery1")), "value restriction");
    }

    /** One LUBM department: Openllet's knowledge base read directly, values asked only where they can be. */
    @Test
    void lubmDepartmentGraphHoldsTheOntologyWithItsInferences() throws Exception {
        String ub = "http://swat.cse.lehigh.edu/onto/univ-bench.owl#";
        String department = "http://www.Department0.University0.edu";
        OWLOntology ontology = manager.loadOntologyFromOntologyDocument(new File(LUBM.toString()));
        Reference reference = open(ontology, "PELLET", false);
        reference.reason();
        assertSameTriples(savedWithInferences(reference), SparqlGraphs.current(reference).graph(), "after REASON");
        reference.change(List.of(
                new AddAxiom(ontology, factory.getOWLObjectPropertyAssertionAxiom(
                        factory.getOWLObjectProperty(IRI.create(ub + "takesCourse")),
                        factory.getOWLNamedIndividual(IRI.create(department + "/UndergraduateStudent7")),
                        factory.getOWLNamedIndividual(IRI.create(department + "/GraduateCourse0")))),
                new AddAxiom(ontology, factory.getOWLClassAssertionAxiom(
                        factory.getOWLClass(IRI.create(ub + "Chair")),
                        factory.getOWLNamedIndividual(IRI.create(department + "/AssociateProfessor3"))))));
        Graph derived = SparqlGraphs.current(reference).graph();
        assertInstanceOf(LayeredGraph.class, derived);
        assertSameTriples(savedWithInferences(reference), derived, "after two assertions");
    }

    @Test
    void bufferedReasonerGraphFollowsReason() throws Exception {
        OWLOntology ontology = robotics();
        Reference reference = open(ontology, "PELLET", true);
        SparqlGraphs.current(reference);
        reference.change(List.of(new AddAxiom(ontology, factory.getOWLObjectPropertyAssertionAxiom(
                objectProperty("isIn"), individual("bob"), individual("bedroom")))));
        assertSameTriples(savedWithInferences(reference), SparqlGraphs.current(reference).graph(),
                "before REASON");
        reference.reason();
        Graph graph = SparqlGraphs.current(reference).graph();
        assertTrue(graph.contains(NodeFactory.createURI(NS + "bedroom"), RdfTerms.TYPE,
                NodeFactory.createURI(NS + "OccupiedRoom")));
        assertSameTriples(savedWithInferences(reference), graph, "after REASON");
    }
}
