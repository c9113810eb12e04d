// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.reference.ReasonerRegistry;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.io.StringDocumentSource;
import org.semanticweb.owlapi.model.AddAxiom;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.RemoveAxiom;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;

/**
 * The modular reasoner against the truth: random change sequences on a robotics ABox, and after
 * every change each answer it gives (consistency, every class's instances and direct instances,
 * every individual's types and direct types) compared with a fresh reasoner of the same kind on
 * the whole ontology. The schema is chosen to give modules something to get wrong: an inverse
 * property in a defined class, a cardinality, a universal restriction, a functional property
 * (merges), a transitive one, a property whose range types the other end of a split edge, a
 * symmetric one, disjoint classes (inconsistency) and a data range. Some steps change the schema,
 * and some bring in a nominal, which makes the reasoner fall back to the whole ontology.
 */
class ModularEquivalenceTest {
    private static final String NS = "http://www.example.org/robotics#";
    private static final String SCHEMA = """
            Prefix(:=<http://www.example.org/robotics#>)
            Prefix(xsd:=<http://www.w3.org/2001/XMLSchema#>)
            Ontology(<http://www.example.org/robotics>
            SubClassOf(:Room :Location) SubClassOf(:Corridor :Location) DisjointClasses(:Room :Corridor)
            SubClassOf(:Robot :Agent) SubClassOf(:Person :Agent) DisjointClasses(:Robot :Person)
            EquivalentClasses(:OccupiedRoom ObjectIntersectionOf(:Room ObjectSomeValuesFrom(:contains :Agent)))
            EquivalentClasses(:RobotInRoom ObjectIntersectionOf(:Robot ObjectSomeValuesFrom(:isIn :Room)))
            EquivalentClasses(:Crowded ObjectIntersectionOf(:Room ObjectMinCardinality(2 :contains :Agent)))
            EquivalentClasses(:Building ObjectSomeValuesFrom(:hasPart :Room))
            SubClassOf(:RobotOnly ObjectAllValuesFrom(:contains :Robot))
            EquivalentClasses(:LowBattery ObjectIntersectionOf(:Robot
                DataSomeValuesFrom(:batteryLevel DatatypeRestriction(xsd:integer xsd:maxExclusive "20"^^xsd:integer))))
            EquivalentClasses(:Loaded ObjectSomeValuesFrom(:carries owl:Thing))
            Declaration(Class(:Charger)) Declaration(Class(:Watched))
            ObjectPropertyDomain(:isIn :Agent) ObjectPropertyRange(:isIn :Location)
            InverseObjectProperties(:contains :isIn)
            SymmetricObjectProperty(:connectedTo) ObjectPropertyDomain(:connectedTo :Location)
            ObjectPropertyRange(:connectedTo :Location)
            FunctionalObjectProperty(:carries)
            TransitiveObjectProperty(:hasPart)
            ObjectPropertyRange(:watchedBy :Watcher) SubClassOf(:Watcher :Robot)
            Declaration(ObjectProperty(:near))
            DataPropertyDomain(:batteryLevel :Robot) DataPropertyRange(:batteryLevel xsd:integer)
            )""";
    private static final List<String> CLASSES = List.of("Location", "Room", "Corridor", "Agent", "Robot", "Person",
            "Charger", "Watched", "RobotOnly", "Watcher", "Building");
    private static final List<String> PROPERTIES = List.of("isIn", "contains", "connectedTo", "carries", "hasPart",
            "watchedBy", "near");

    private final Random random = new Random();
    private OWLOntologyManager manager;
    private OWLDataFactory factory;
    private OWLOntology ontology;
    private final List<OWLNamedIndividual> individuals = new ArrayList<>();
    private int fresh;

    @ParameterizedTest(name = "{0}, seed {1}, {2} changes")
    @CsvSource({"HERMIT, 1, 120", "HERMIT, 2, 120", "PELLET, 3, 120", "PELLET, 4, 120", "JFACT, 5, 60"})
    void everyAnswerEqualsAFreshReasonerOnTheWholeOntology(String reasonerName, long seed, int steps)
            throws Exception {
        random.setSeed(seed);
        manager = OWLManager.createOWLOntologyManager();
        factory = manager.getOWLDataFactory();
        ontology = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(SCHEMA));
        for (int i = 0; i < 24; i++) {
            addIndividual();
        }
        OWLReasonerFactory reasonerFactory = ReasonerRegistry.factory(reasonerName);
        ModularReasoner modular = new ModularReasoner(reasonerName, reasonerFactory, ontology,
                new SimpleConfiguration());
        compare(reasonerFactory, modular, "the loaded ABox");
        int modularSteps = 0;
        for (int step = 0; step < steps; step++) {
            List<OWLOntologyChange> changes = randomChanges();
            List<? extends OWLOntologyChange> enacted = manager.applyChangesAndGetDetails(changes).getEnactedChanges();
            // What a reference does after a change: flush, or start afresh when removals are not handled.
            if (!modular.handlesRemovals() && enacted.stream().anyMatch(OWLOntologyChange::isRemoveAxiom)) {
                modular.dispose();
                modular = new ModularReasoner(reasonerName, reasonerFactory, ontology, new SimpleConfiguration());
            } else {
                modular.flush();
            }
            modularSteps += modular.handlesRemovals() ? 1 : 0;
            assertTrue(!modular.wholeBecause().startsWith("a module failed"), modular.wholeBecause());
            compare(reasonerFactory, modular, "step " + step + " " + changes);
        }
        assertTrue(modularSteps > steps / 2, "most steps must exercise the modules, not the fallback: " + modularSteps);
        modular.dispose();
    }

    /**
     * The robot's workload: rooms with agents in them, agents moving between rooms, some robots
     * low on battery; many modules share a shape, so most take an earlier module's result.
     */
    @ParameterizedTest(name = "{0}, seed {1}, {2} moves")
    @CsvSource({"HERMIT, 11, 80", "PELLET, 12, 80", "JFACT, 13, 40"})
    void agentsMovingBetweenRoomsMatchAFreshReasoner(String reasonerName, long seed, int moves) throws Exception {
        random.setSeed(seed);
        manager = OWLManager.createOWLOntologyManager();
        factory = manager.getOWLDataFactory();
        ontology = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(SCHEMA));
        OWLObjectProperty isIn = factory.getOWLObjectProperty(IRI.create(NS + "isIn"));
        OWLObjectProperty connectedTo = factory.getOWLObjectProperty(IRI.create(NS + "connectedTo"));
        List<OWLNamedIndividual> rooms = new ArrayList<>();
        List<OWLNamedIndividual> agents = new ArrayList<>();
        List<OWLAxiom> abox = new ArrayList<>();
        for (int i = 0; i < 12; i++) {
            OWLNamedIndividual room = factory.getOWLNamedIndividual(IRI.create(NS + "room" + i));
            abox.add(factory.getOWLClassAssertionAxiom(cls("Room"), room));
            if (i > 0) {
                abox.add(factory.getOWLObjectPropertyAssertionAxiom(connectedTo, room, rooms.get(i - 1)));
            }
            rooms.add(room);
        }
        for (int i = 0; i < 40; i++) {
            OWLNamedIndividual agent = factory.getOWLNamedIndividual(IRI.create(NS + "agent" + i));
            abox.add(factory.getOWLClassAssertionAxiom(cls(i % 4 == 0 ? "Person" : "Robot"), agent));
            abox.add(factory.getOWLObjectPropertyAssertionAxiom(isIn, agent, rooms.get(i % 6)));
            agents.add(agent);
        }
        manager.addAxioms(ontology, abox.stream());
        OWLReasonerFactory reasonerFactory = ReasonerRegistry.factory(reasonerName);
        ModularReasoner modular = new ModularReasoner(reasonerName, reasonerFactory, ontology,
                new SimpleConfiguration());
        compare(reasonerFactory, modular, "the loaded ABox");
        for (int move = 0; move < moves; move++) {
            OWLNamedIndividual agent = agents.get(random.nextInt(agents.size()));
            OWLAxiom from = ontology.objectPropertyAssertionAxioms(agent).findFirst().orElseThrow();
            List<OWLOntologyChange> changes = new ArrayList<>(List.of(new RemoveAxiom(ontology, from),
                    new AddAxiom(ontology, factory.getOWLObjectPropertyAssertionAxiom(isIn, agent,
                            rooms.get(random.nextInt(rooms.size()))))));
            if (random.nextInt(5) == 0) {
                changes.add(toggle(factory.getOWLDataPropertyAssertionAxiom(factory.getOWLDataProperty(
                        IRI.create(NS + "batteryLevel")), agents.get(random.nextInt(agents.size())), 10)));
            }
            if (random.nextInt(8) == 0) {
                changes.add(toggle(factory.getOWLClassAssertionAxiom(cls("RobotOnly"),
                        rooms.get(random.nextInt(rooms.size())))));
            }
            manager.applyChanges(changes);
            modular.flush();
            compare(reasonerFactory, modular, "move " + move + " " + changes);
        }
        assertTrue(modular.reusedShapes() > moves, "rooms alike must share results: " + modular.reusedShapes());
        modular.dispose();
    }

    private void compare(OWLReasonerFactory reasonerFactory, ModularReasoner modular, String after) {
        OWLReasoner truth = reasonerFactory.createReasoner(ontology);
        try {
            assertEquals(truth.isConsistent(), modular.isConsistent(), () -> "consistency after " + after);
            if (!truth.isConsistent()) {
                return;
            }
            Set<OWLClass> classes = ontology.classesInSignature(Imports.INCLUDED).collect(Collectors.toSet());
            classes.add(factory.getOWLThing());
            for (OWLClass owlClass : classes) {
                assertEquals(names(truth.getInstances(owlClass, false).entities()),
                        names(modular.getInstances(owlClass, false).entities()),
                        () -> "instances of " + owlClass + " after " + after);
            }
            for (OWLNamedIndividual individual : ontology.individualsInSignature(Imports.INCLUDED).toList()) {
                for (boolean direct : new boolean[] {false, true}) {
                    assertEquals(names(truth.getTypes(individual, direct).entities()),
                            names(modular.getTypes(individual, direct).entities()),
                            () -> (direct ? "direct " : "") + "types of " + individual + " after " + after);
                }
            }
        } finally {
            truth.dispose();
        }
    }

    private static Set<String> names(Stream<? extends OWLEntity> entities) {
        return entities.map(e -> e.getIRI().getShortForm()).collect(Collectors.toCollection(TreeSet::new));
    }

    private List<OWLOntologyChange> randomChanges() {
        // A nominal: the ontology cannot be split while it is there, for a few steps.
        OWLAxiom nominal = factory.getOWLSubClassOfAxiom(cls("Charger"),
                factory.getOWLObjectHasValue(factory.getOWLObjectProperty(IRI.create(NS + "near")),
                        individuals.get(0)));
        if (ontology.containsAxiom(nominal) && random.nextInt(4) == 0) {
            return List.of(new RemoveAxiom(ontology, nominal));
        }
        int kind = random.nextInt(100);
        if (kind < 22) {
            return List.of(toggle(factory.getOWLClassAssertionAxiom(owlClass(), individual())));
        }
        if (kind < 62) {
            return List.of(toggle(factory.getOWLObjectPropertyAssertionAxiom(property(), individual(), individual())));
        }
        if (kind < 70) {
            return List.of(toggle(factory.getOWLDataPropertyAssertionAxiom(
                    factory.getOWLDataProperty(IRI.create(NS + "batteryLevel")), individual(), random.nextInt(40))));
        }
        if (kind < 76) {
            return addIndividual();
        }
        if (kind < 80 && individuals.size() > 8) {
            OWLNamedIndividual gone = individuals.remove(1 + random.nextInt(individuals.size() - 1));
            return ontology.referencingAxioms(gone).map(a -> (OWLOntologyChange) new RemoveAxiom(ontology, a)).toList();
        }
        if (kind < 84) {
            return List.of(toggle(factory.getOWLSameIndividualAxiom(individual(), individual())));
        }
        if (kind < 88) {
            return List.of(toggle(factory.getOWLDifferentIndividualsAxiom(individual(), individual())));
        }
        if (kind < 97) {
            return List.of(toggle(factory.getOWLSubClassOfAxiom(owlClass(), owlClass())));
        }
        return List.of(new AddAxiom(ontology, nominal));
    }

    private OWLOntologyChange toggle(OWLAxiom axiom) {
        return ontology.containsAxiom(axiom) ? new RemoveAxiom(ontology, axiom) : new AddAxiom(ontology, axiom);
    }

    private List<OWLOntologyChange> addIndividual() {
        OWLNamedIndividual individual = factory.getOWLNamedIndividual(IRI.create(NS + "thing" + fresh++));
        individuals.add(individual);
        String kind = List.of("Room", "Room", "Corridor", "Robot", "Robot", "Robot", "Person").get(random.nextInt(7));
        List<OWLOntologyChange> changes = new ArrayList<>();
        changes.add(new AddAxiom(ontology, factory.getOWLClassAssertionAxiom(cls(kind), individual)));
        if (!kind.endsWith("Room") && !kind.equals("Corridor") && individuals.size() > 1) {
            changes.add(new AddAxiom(ontology, factory.getOWLObjectPropertyAssertionAxiom(
                    factory.getOWLObjectProperty(IRI.create(NS + "isIn")), individual, individual())));
        }
        manager.applyChanges(changes);
        return List.of();
    }

    private OWLClass owlClass() {
        return cls(CLASSES.get(random.nextInt(CLASSES.size())));
    }

    private OWLClass cls(String name) {
        return factory.getOWLClass(IRI.create(NS + name));
    }

    private OWLObjectProperty property() {
        return factory.getOWLObjectProperty(IRI.create(NS + PROPERTIES.get(random.nextInt(PROPERTIES.size()))));
    }

    private OWLNamedIndividual individual() {
        return individuals.get(random.nextInt(individuals.size()));
    }
}
