// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.reference.ReasonerRegistry;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.io.StringDocumentSource;
import org.semanticweb.owlapi.model.AddAxiom;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.RemoveAxiom;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;

/**
 * The modular reasoner against the truth: random change sequences on a robotics ABox, and after
 * every change each answer it gives (consistency, every class's instances, every individual's
 * types and direct types) compared with a fresh reasoner of the same kind on the whole ontology.
 *
 * <p>The schema and the changes are the shapes robot ontologies have, chosen to give modules
 * something to get wrong: a transitive part-of tree and a symmetric adjacency that nothing
 * observes (they must tie nothing), an inverse property in a defined class, a cardinality, a
 * universal restriction, a functional property (merges), a transitive property a class observes,
 * a property chain, a range that types the other end of a split edge, disjoint properties and
 * classes (inconsistency), a data range, a hasValue class over an individual of the ABox and an
 * enumeration of individuals only the schema names (nominals: the hub). Changes: class
 * assertions on named classes and on class expressions, property assertions and negative ones,
 * data values, new and removed individuals, sameness, difference (pairs and every individual at
 * once), subclass axioms, property characteristics, hierarchy, inverses, chains and disjointness,
 * and a nominal the ABox reaches (whole-ontology reasoning until it goes).
 *
 * <p>It checks too that the reasoning was modular: while the schema's properties are as loaded,
 * every ABox change must leave most individuals outside the modules it reasons on again, and the
 * ABox must stay in many modules. Seeds: fixed ones, and one per run and reasoner printed (rerun
 * one with {@code -Darmor.seed=N}).
 */
class ModularEquivalenceTest {
    private static final String NS = "http://www.example.org/robotics#";
    private static final String SCHEMA = """
            Prefix(:=<http://www.example.org/robotics#>)
            Prefix(xsd:=<http://www.w3.org/2001/XMLSchema#>)
            Ontology(<http://www.example.org/robotics>
            SubClassOf(:Room :Location) SubClassOf(:Corridor :Location) DisjointClasses(:Room :Corridor)
            SubClassOf(:Zone :Location) SubClassOf(:Robot :Agent) SubClassOf(:Person :Agent)
            DisjointClasses(:Robot :Person)
            EquivalentClasses(:OccupiedRoom ObjectIntersectionOf(:Room ObjectSomeValuesFrom(:contains :Agent)))
            EquivalentClasses(:RobotInRoom ObjectIntersectionOf(:Robot ObjectSomeValuesFrom(:isIn :Room)))
            EquivalentClasses(:Crowded ObjectIntersectionOf(:Room ObjectMinCardinality(2 :contains :Agent)))
            EquivalentClasses(:Building ObjectSomeValuesFrom(:hasPart :Room))
            SubClassOf(:RobotOnly ObjectAllValuesFrom(:contains :Robot))
            EquivalentClasses(:LowBattery ObjectIntersectionOf(:Robot
                DataSomeValuesFrom(:batteryLevel DatatypeRestriction(xsd:integer xsd:maxExclusive "20"^^xsd:integer))))
            EquivalentClasses(:Loaded ObjectSomeValuesFrom(:carries owl:Thing))
            EquivalentClasses(:AtDock ObjectIntersectionOf(:Agent ObjectHasValue(:isIn :dock)))
            EquivalentClasses(:Shift ObjectOneOf(:morning :evening)) SubClassOf(:Shift :Period)
            ObjectPropertyRange(:onShift :Shift)
            Declaration(Class(:Charger)) Declaration(Class(:Watched))
            ObjectPropertyDomain(:isIn :Agent) ObjectPropertyRange(:isIn :Location)
            InverseObjectProperties(:contains :isIn)
            SymmetricObjectProperty(:connectedTo) ObjectPropertyDomain(:connectedTo :Location)
            ObjectPropertyRange(:connectedTo :Location)
            TransitiveObjectProperty(:partOf) ObjectPropertyDomain(:partOf :Location)
            ObjectPropertyRange(:partOf :Location)
            SymmetricObjectProperty(:adjacentTo)
            SubObjectPropertyOf(ObjectPropertyChain(:isIn :partOf) :within)
            FunctionalObjectProperty(:carries)
            TransitiveObjectProperty(:hasPart)
            DisjointObjectProperties(:carries :watchedBy)
            ObjectPropertyRange(:watchedBy :Watcher) SubClassOf(:Watcher :Robot)
            Declaration(ObjectProperty(:near))
            DataPropertyDomain(:batteryLevel :Robot) DataPropertyRange(:batteryLevel xsd:integer)
            )""";
    private static final List<String> CLASSES = List.of("Location", "Room", "Corridor", "Zone", "Agent", "Robot",
            "Person", "Charger", "Watched", "RobotOnly", "Watcher", "Building");
    private static final List<String> PROPERTIES = List.of("isIn", "contains", "connectedTo", "carries", "hasPart",
            "watchedBy", "near", "partOf", "adjacentTo", "within");
    /** Property axioms a step adds or takes away: characteristics, hierarchy, inverses, chains, disjointness. */
    private static final List<String> PROPERTY_AXIOMS = List.of(
            "FunctionalObjectProperty(:adjacentTo)", "TransitiveObjectProperty(:near)",
            "AsymmetricObjectProperty(:carries)", "IrreflexiveObjectProperty(:adjacentTo)",
            "InverseFunctionalObjectProperty(:carries)", "SymmetricObjectProperty(:near)",
            "SubObjectPropertyOf(:adjacentTo :near)", "SubObjectPropertyOf(:partOf :hasPart)",
            "InverseObjectProperties(:partOf :hasPart)", "ObjectPropertyDomain(:within :Zone)",
            "SubObjectPropertyOf(ObjectPropertyChain(:adjacentTo :partOf) :near)",
            "DisjointObjectProperties(:adjacentTo :connectedTo)", "EquivalentObjectProperties(:watchedBy :guardedBy)",
            "SubClassOf(:Watched ObjectSomeValuesFrom(:near :Room))");
    private static final long[] FIXED = {1, 2, 3, 4, 5};
    /** The nominals of the schema: JFact reasons on the whole ontology with them (ModularReasoner says why). */
    private static final List<String> NOMINAL_LINES = List.of(
            "EquivalentClasses(:AtDock ObjectIntersectionOf(:Agent ObjectHasValue(:isIn :dock)))",
            "EquivalentClasses(:Shift ObjectOneOf(:morning :evening)) SubClassOf(:Shift :Period)",
            "ObjectPropertyRange(:onShift :Shift)");

    private static String schema(String reasonerName) {
        String schema = SCHEMA;
        if (reasonerName.equals("JFACT")) {
            for (String line : NOMINAL_LINES) {
                schema = schema.replace(line, "");
            }
        }
        return schema;
    }

    private final Random random = new Random();
    private OWLOntologyManager manager;
    private OWLDataFactory factory;
    private OWLOntology ontology;
    private final List<OWLNamedIndividual> individuals = new ArrayList<>();
    private final List<OWLNamedIndividual> rooms = new ArrayList<>();
    private final List<OWLNamedIndividual> agents = new ArrayList<>();
    private final List<OWLAxiom> propertyAxioms = new ArrayList<>();
    private final List<OWLAxiom> passing = new ArrayList<>();
    private int fresh;

    static Stream<Arguments> seeds() {
        long perRun = Long.getLong("armor.seed", System.nanoTime() % 1_000_000);
        System.out.println("ModularEquivalenceTest: per-run seed " + perRun + " (rerun with -Darmor.seed=" + perRun
                + ")");
        return Stream.of(Arguments.of("HERMIT", FIXED[0], 75), Arguments.of("PELLET", FIXED[1], 75),
                Arguments.of("HERMIT", FIXED[2], 75), Arguments.of("JFACT", FIXED[4], 40),
                Arguments.of("HERMIT", perRun, 75), Arguments.of("PELLET", perRun + 1, 75));
    }

    @ParameterizedTest(name = "{0}, seed {1}, {2} changes")
    @MethodSource("seeds")
    void everyAnswerEqualsAFreshReasonerOnTheWholeOntology(String reasonerName, long seed, int steps)
            throws Exception {
        random.setSeed(seed);
        manager = OWLManager.createOWLOntologyManager();
        factory = manager.getOWLDataFactory();
        ontology = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(schema(reasonerName)));
        for (String axiom : PROPERTY_AXIOMS) {
            propertyAxioms.add(parse(axiom));
        }
        loadMap();
        OWLReasonerFactory reasonerFactory = ReasonerRegistry.factory(reasonerName);
        ModularReasoner modular = new ModularReasoner(reasonerName, reasonerFactory, ontology,
                new SimpleConfiguration());
        String run = reasonerName + " seed " + seed;
        compare(reasonerFactory, modular, run + ", the loaded ABox");
        ModularReasoner loaded = modular;
        assertTrue(loaded.handlesRemovals(), () -> run + ": the loaded map must be modular: " + loaded.wholeBecause());
        assertTrue(loaded.lastUpdate().modules() >= individuals.size() / 4,
                () -> run + ": the map must be cut into many modules, not " + loaded.lastUpdate());
        Set<OWLObjectProperty> loadedLinks = loaded.linkingProperties();
        int modularSteps = 0;
        int baseSteps = 0;
        int manyModules = 0;
        java.util.Map<String, Integer> wholeBecause = new java.util.TreeMap<>();
        int localSteps = 0;
        List<String> overRemade = new ArrayList<>();
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
            String after = run + ", step " + step + " " + changes;
            compare(reasonerFactory, modular, after);
            assertTrue(!modular.wholeBecause().startsWith("a module failed"), modular.wholeBecause());
            if (!modular.handlesRemovals()) {
                wholeBecause.merge(modular.wholeBecause().replaceAll("\\(.*", ""), 1, Integer::sum);
                continue;
            }
            modularSteps++;
            ModularReasoner.LastUpdate update = modular.lastUpdate();
            // A change that names most individuals (a DifferentIndividuals of all) reasons on them all.
            long named = changes.stream().flatMap(c -> c.getAxiom().individualsInSignature()).distinct().count();
            boolean baseLinks = modular.linkingProperties().equals(loadedLinks);
            baseSteps += baseLinks ? 1 : 0;
            if (baseLinks && !update.everything() && named * 2 <= update.individuals()) {
                // A step may rightly remake a big module (a zone and its rooms removed at once);
                // what must hold is that such steps are rare, as a whole-ABox fallback never is.
                localSteps++;
                if (update.remade() * 2 > update.individuals()) {
                    overRemade.add(update + " after " + after);
                }
            }
            manyModules += baseLinks && update.modules() >= update.individuals() / 4 ? 1 : 0;
        }
        int local = localSteps;
        assertTrue(overRemade.size() * 10 <= localSteps, () -> run + ": most individuals must stay outside the"
                + " modules reasoned on again, on all but a tenth of " + local + " steps; not on " + overRemade);
        int modularDone = modularSteps;
        assertTrue(modularSteps > steps * 2 / 3, () -> run + ": most steps must exercise the modules, not the"
                + " fallback: " + modularDone + "; whole because " + wholeBecause);
        int many = manyModules;
        int base = baseSteps;
        assertTrue(baseSteps > steps / 3, () -> run + ": most steps must keep the loaded links: " + base);
        assertTrue(manyModules > baseSteps * 2 / 3, () -> run + ": the ABox must stay in many modules: " + many
                + " of " + base + " modular steps with the loaded links");
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
        ontology = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(schema(reasonerName)));
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

    /** The course's topological map with its rules, and more rules over the property hierarchy and a defined class. */
    private static final String RULES_SCHEMA = """
            Prefix(:=<http://www.example.org/robotics#>)
            Prefix(xsd:=<http://www.w3.org/2001/XMLSchema#>)
            Prefix(swrlb:=<http://www.w3.org/2003/11/swrlb#>)
            Prefix(var:=<urn:swrl:var#>)
            Ontology(<http://www.example.org/robotics>
            SubClassOf(:Room :Location) SubClassOf(:Corridor :Location) DisjointClasses(:Room :Corridor :Door :Robot)
            ObjectPropertyDomain(:hasDoor :Location) ObjectPropertyRange(:hasDoor :Door)
            FunctionalDataProperty(:now) FunctionalDataProperty(:visitedAt) SubClassOf(:URGENT :Room)
            EquivalentClasses(:Occupied ObjectIntersectionOf(:Location ObjectSomeValuesFrom(ObjectInverseOf(:isIn) :Robot)))
            SubObjectPropertyOf(:isIn :at) InverseObjectProperties(:connectedTo :connectedFrom)
            ObjectPropertyDomain(:canReach :Robot) DataPropertyDomain(:lastSeen :Robot) SubClassOf(:Watched :Location)
            DLSafeRule(Body(ClassAtom(:Location Variable(var:a)) ClassAtom(:Location Variable(var:b))
                ObjectPropertyAtom(:hasDoor Variable(var:a) Variable(var:d)) ObjectPropertyAtom(:hasDoor Variable(var:b) Variable(var:d))
                DifferentIndividualsAtom(Variable(var:a) Variable(var:b)))
                Head(ObjectPropertyAtom(:connectedTo Variable(var:a) Variable(var:b))))
            DLSafeRule(Body(ClassAtom(:Robot Variable(var:r)) ObjectPropertyAtom(:at Variable(var:r) Variable(var:a))
                ObjectPropertyAtom(:connectedTo Variable(var:a) Variable(var:b)))
                Head(ObjectPropertyAtom(:canReach Variable(var:r) Variable(var:b))))
            DLSafeRule(Body(ClassAtom(:Robot Variable(var:r)) DataPropertyAtom(:now Variable(var:r) Variable(var:t))
                DataPropertyAtom(:urgencyThreshold Variable(var:r) Variable(var:k)) ClassAtom(:Room Variable(var:l))
                DataPropertyAtom(:visitedAt Variable(var:l) Variable(var:v))
                %s)
                Head(ClassAtom(:URGENT Variable(var:l))))
            DLSafeRule(Body(ClassAtom(:Occupied Variable(var:l)) ObjectPropertyAtom(:connectedFrom Variable(var:l) Variable(var:c))
                ClassAtom(:Corridor Variable(var:c)))
                Head(ClassAtom(:Watched Variable(var:c))))
            DLSafeRule(Body(ClassAtom(:Robot Variable(var:r)) DataPropertyAtom(:now Variable(var:r) Variable(var:t))
                BuiltInAtom(swrlb:lessThanOrEqual Variable(var:t) "1200"^^xsd:integer))
                Head(DataPropertyAtom(:lastSeen Variable(var:r) Variable(var:t))))
            )""";

    /** The built-ins of the URGENT rule, one per seed: the course's, and the same test written otherwise. */
    private static final List<String> URGENCY_TESTS = List.of(
            "BuiltInAtom(swrlb:subtract Variable(var:age) Variable(var:t) Variable(var:v))"
                    + " BuiltInAtom(swrlb:greaterThan Variable(var:age) Variable(var:k))",
            "BuiltInAtom(swrlb:subtract Variable(var:age) Variable(var:t) Variable(var:v))"
                    + " BuiltInAtom(swrlb:lessThanOrEqual Variable(var:k) Variable(var:age))",
            "BuiltInAtom(swrlb:add Variable(var:due) Variable(var:v) Variable(var:k))"
                    + " BuiltInAtom(swrlb:lessThan Variable(var:due) Variable(var:t))",
            "BuiltInAtom(swrlb:subtract Variable(var:age) Variable(var:t) Variable(var:v))"
                    + " BuiltInAtom(swrlb:multiply Variable(var:twice) Variable(var:age) \"2\"^^xsd:integer)"
                    + " BuiltInAtom(swrlb:greaterThanOrEqual Variable(var:twice) Variable(var:k))");

    /**
     * SWRL rules with built-ins beside the modules, against Openllet on the whole ontology (the
     * reference for rules with built-ins; HermiT has no built-ins): the students' loop (the robot
     * moves, time passes, rooms are visited), doors that come and go, rooms that stop being rooms
     * (a conclusion URGENT ⊑ Room must not keep itself), new and removed rooms, the threshold.
     */
    @ParameterizedTest(name = "{0}, seed {1}, {2} changes")
    @CsvSource({"PELLET, 21, 40", "HERMIT, 22, 40", "PELLET, 24, 30"})
    void rulesWithBuiltInsMatchOpenlletOnTheWholeOntology(String reasonerName, long seed, int steps) throws Exception {
        random.setSeed(seed);
        manager = OWLManager.createOWLOntologyManager();
        factory = manager.getOWLDataFactory();
        String urgency = URGENCY_TESTS.get((int) (seed % URGENCY_TESTS.size()));
        ontology = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(RULES_SCHEMA.formatted(urgency)));
        CourseMap map = new CourseMap();
        map.load();
        OWLReasonerFactory openllet = ReasonerRegistry.factory("PELLET");
        ModularReasoner modular = new ModularReasoner(reasonerName, ReasonerRegistry.factory(reasonerName), ontology,
                new SimpleConfiguration());
        String run = reasonerName + " seed " + seed + " (" + urgency + ")";
        modular.isConsistent();
        assertTrue(modular.handlesRemovals(), () -> run + ": rules must be evaluated beside the modules: "
                + modular.wholeBecause());
        compare(openllet, modular, run + ", the loaded map");
        int urgentSeen = 0;
        for (int step = 0; step < steps; step++) {
            List<OWLOntologyChange> changes = map.randomChanges();
            manager.applyChanges(changes);
            modular.flush();
            String after = run + ", step " + step + " " + changes;
            assertTrue(modular.handlesRemovals(), () -> "rules must stay beside the modules: " + modular.wholeBecause()
                    + " after " + after);
            compare(openllet, modular, after);
            urgentSeen += modular.getInstances(cls("URGENT"), false).nodes().count() > 0 ? 1 : 0;
        }
        int seen = urgentSeen;
        assertTrue(urgentSeen > steps / 4, () -> run + ": rooms must be urgent in many steps, not " + seen);
        modular.dispose();
    }

    /**
     * The clock's ticks reach only the rooms whose comparison flips (an ordered index of the
     * visits, and the value ranges where the URGENT rule's built-ins differ before and after):
     * ticks that flip some rooms and not others, a tick backwards, a tick onto a value that
     * equals a room's visit plus the threshold, two rooms visited at once, a tick that changes
     * nothing, and a threshold that moves; each of the URGENT rule's forms, against Openllet on
     * the whole ontology.
     */
    @ParameterizedTest(name = "URGENT written as form {0}")
    @CsvSource({"0", "1", "2", "3"})
    void clockTicksMatchOpenlletOnTheWholeOntology(int form) throws Exception {
        random.setSeed(form);
        manager = OWLManager.createOWLOntologyManager();
        factory = manager.getOWLDataFactory();
        String urgency = URGENCY_TESTS.get(form);
        ontology = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(RULES_SCHEMA.formatted(urgency)));
        CourseMap map = new CourseMap();
        map.load();
        // now = 1000, threshold 100: rooms on, just past, and before the boundary; two visited at once.
        int[] visits = {900, 899, 901, 950, 860, 901};
        for (int i = 0; i < rooms.size(); i++) {
            manager.applyChanges(map.replace("visitedAt", rooms.get(i), visits[i]));
        }
        OWLReasonerFactory openllet = ReasonerRegistry.factory("PELLET");
        ModularReasoner modular = new ModularReasoner("PELLET", ReasonerRegistry.factory("PELLET"), ontology,
                new SimpleConfiguration());
        modular.isConsistent();
        compare(openllet, modular, form + ", the loaded map");
        Set<Set<String>> urgentSets = new HashSet<>();
        // Each is the clock's new value, but 51 and 100, which are the threshold's.
        for (int value : new int[] {1001, 1040, 1050, 1050, 999, 51, 960, 100, 1100, 700, 1300}) {
            List<OWLOntologyChange> tick = value <= 100 ? map.replace("urgencyThreshold", map.robot, value)
                    : map.replace("now", map.robot, value);
            manager.applyChanges(tick);
            modular.flush();
            String after = form + ", after " + tick;
            assertTrue(modular.handlesRemovals(), () -> "rules must stay beside the modules: " + modular.wholeBecause()
                    + " " + after);
            compare(openllet, modular, after);
            urgentSets.add(WholeOntologyAnswers.names(modular.getInstances(cls("URGENT"), false).entities()));
        }
        // The ticks must have moved URGENT both ways, through no room, some rooms and others.
        assertTrue(urgentSets.size() >= 3 && urgentSets.contains(Set.of())
                && urgentSets.stream().anyMatch(set -> !set.isEmpty() && set.size() < rooms.size()),
                () -> "URGENT took only " + urgentSets);
        modular.dispose();
    }

    /**
     * Modules alike but for the values of a data property the schema only calls functional share
     * one reasoned result; values the schema reads (here through a super-property with a facet)
     * keep modules apart.
     */
    @Test
    void modulesAlikeButForValuesTheSchemaCannotReadShareAResult() throws Exception {
        manager = OWLManager.createOWLOntologyManager();
        factory = manager.getOWLDataFactory();
        StringBuilder document = new StringBuilder("""
                Prefix(:=<http://www.example.org/robotics#>)
                Prefix(xsd:=<http://www.w3.org/2001/XMLSchema#>)
                Ontology(<http://www.example.org/robotics>
                FunctionalDataProperty(:now) DataPropertyDomain(:now :Robot) SubDataPropertyOf(:reading :level)
                EquivalentClasses(:High DataSomeValuesFrom(:level DatatypeRestriction(xsd:integer
                    xsd:minExclusive "50"^^xsd:integer)))
                """);
        int[] readings = {40, 40, 60, 60, 45, 45};
        for (int i = 0; i < readings.length; i++) {
            document.append("ClassAssertion(:Robot :r%d) DataPropertyAssertion(:now :r%d \"%d\"^^xsd:integer)"
                    .formatted(i, i, 1000 + 10 * i)).append(" DataPropertyAssertion(:reading :r%d \"%d\"^^xsd:integer)\n"
                    .formatted(i, readings[i]));
        }
        ontology = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(document + ")"));
        ModularReasoner modular = new ModularReasoner("PELLET", ReasonerRegistry.factory("PELLET"), ontology,
                new SimpleConfiguration());
        modular.isConsistent();
        compare(ReasonerRegistry.factory("PELLET"), modular, "the loaded robots");
        assertEquals(Set.of("r2", "r3"), WholeOntologyAnswers.names(modular.getInstances(cls("High"), false).entities()));
        assertTrue(modular.reusedShapes() >= 3, () -> "robots alike but for the clock must share a result, not "
                + modular.reusedShapes());
        modular.dispose();
    }

    /** The topological map of {@link #RULES_SCHEMA}: corridors in a row, rooms with a door each, a robot, a clock. */
    private final class CourseMap {
        private final OWLNamedIndividual robot = named("robot");
        private final List<OWLNamedIndividual> corridors = new ArrayList<>();
        private final List<OWLNamedIndividual> doors = new ArrayList<>();
        private int now = 1000;
        private int threshold = 100;

        void load() {
            List<OWLAxiom> abox = new ArrayList<>(List.of(factory.getOWLClassAssertionAxiom(cls("Robot"), robot),
                    value("now", robot, now), value("urgencyThreshold", robot, threshold)));
            for (int i = 0; i < 3; i++) {
                OWLNamedIndividual corridor = named("corridor" + i);
                corridors.add(corridor);
                abox.add(factory.getOWLClassAssertionAxiom(cls("Corridor"), corridor));
                if (i > 0) {
                    abox.addAll(door(corridors.get(i - 1), corridor));
                }
            }
            for (int i = 0; i < 6; i++) {
                abox.addAll(room("room" + i, now - random.nextInt(250)));
            }
            abox.add(edge("isIn", robot, corridors.get(0)));
            individuals.add(robot);
            individuals.addAll(corridors);
            individuals.addAll(doors);
            abox.add(factory.getOWLDifferentIndividualsAxiom(Set.copyOf(individuals)));
            manager.addAxioms(ontology, abox.stream());
        }

        private List<OWLAxiom> door(OWLNamedIndividual one, OWLNamedIndividual other) {
            OWLNamedIndividual door = named("door" + doors.size());
            doors.add(door);
            return List.of(factory.getOWLClassAssertionAxiom(cls("Door"), door), edge("hasDoor", one, door),
                    edge("hasDoor", other, door));
        }

        private List<OWLAxiom> room(String name, int visited) {
            OWLNamedIndividual room = named(name);
            rooms.add(room);
            individuals.add(room);
            List<OWLAxiom> axioms = new ArrayList<>(List.of(factory.getOWLClassAssertionAxiom(cls("Room"), room),
                    value("visitedAt", room, visited)));
            axioms.addAll(door(room, corridors.get(random.nextInt(corridors.size()))));
            return axioms;
        }

        private OWLAxiom value(String property, OWLNamedIndividual individual, int value) {
            return factory.getOWLDataPropertyAssertionAxiom(factory.getOWLDataProperty(IRI.create(NS + property)),
                    individual, value);
        }

        /** A replaced functional value: the old one goes, the new one comes. */
        private List<OWLOntologyChange> replace(String property, OWLNamedIndividual individual, int value) {
            List<OWLOntologyChange> changes = new ArrayList<>(ontology.dataPropertyAssertionAxioms(individual)
                    .filter(a -> a.getProperty().asOWLDataProperty().getIRI().getShortForm().equals(property))
                    .map(a -> (OWLOntologyChange) new RemoveAxiom(ontology, a)).toList());
            changes.add(new AddAxiom(ontology, value(property, individual, value)));
            return changes;
        }

        List<OWLOntologyChange> randomChanges() {
            int kind = random.nextInt(100);
            if (kind < 40) {
                // The students' loop: the robot moves to a room or corridor, time passes, a room is visited.
                OWLNamedIndividual place = random.nextBoolean() ? pick(rooms) : corridors.get(random.nextInt(3));
                List<OWLOntologyChange> changes = new ArrayList<>(ontology.objectPropertyAssertionAxioms(robot)
                        .map(a -> (OWLOntologyChange) new RemoveAxiom(ontology, a)).toList());
                changes.add(new AddAxiom(ontology, edge("isIn", robot, place)));
                now += 10 + random.nextInt(60);
                changes.addAll(replace("now", robot, now));
                if (rooms.contains(place)) {
                    changes.addAll(replace("visitedAt", place, now));
                }
                return changes;
            }
            if (kind < 52) {
                // A door closes (its edges go) or a new one opens between a room and a corridor.
                List<OWLObjectPropertyAssertionAxiom> doorEdges = ontology.axioms(AxiomType.OBJECT_PROPERTY_ASSERTION)
                        .filter(a -> a.getProperty().equals(property("hasDoor"))).toList();
                if (random.nextBoolean() && !doorEdges.isEmpty()) {
                    return List.of(new RemoveAxiom(ontology, doorEdges.get(random.nextInt(doorEdges.size()))));
                }
                OWLNamedIndividual door = pick(doors);
                return List.of(new AddAxiom(ontology, edge("hasDoor", pick(rooms), door)));
            }
            if (kind < 64) {
                // A room stops being a room, or is one again: URGENT must go with it, not keep itself.
                return List.of(toggle(factory.getOWLClassAssertionAxiom(cls("Room"), pick(rooms))));
            }
            if (kind < 70) {
                threshold = 50 + random.nextInt(150);
                return replace("urgencyThreshold", robot, threshold);
            }
            if (kind < 76) {
                // A second robot appears in a room, or goes (a defined class the rules read: Occupied).
                OWLNamedIndividual other = named("robot2");
                List<OWLOntologyChange> gone = ontology.referencingAxioms(other)
                        .filter(a -> a.isOfType(AxiomType.ABoxAxiomTypes) && !a.isOfType(AxiomType.DIFFERENT_INDIVIDUALS))
                        .map(a -> (OWLOntologyChange) new RemoveAxiom(ontology, a)).toList();
                if (!gone.isEmpty()) {
                    return gone;
                }
                return List.of(new AddAxiom(ontology, factory.getOWLClassAssertionAxiom(cls("Robot"), other)),
                        new AddAxiom(ontology, edge("isIn", other, pick(rooms))),
                        new AddAxiom(ontology, value("now", other, now + 500)));
            }
            if (kind < 84 && rooms.size() > 3) {
                // A room is taken off the map (every assertion about it, its difference kept).
                OWLNamedIndividual gone = rooms.remove(random.nextInt(rooms.size()));
                return ontology.referencingAxioms(gone).filter(a -> a.isOfType(AxiomType.ABoxAxiomTypes)
                                && !a.isOfType(AxiomType.DIFFERENT_INDIVIDUALS))
                        .map(a -> (OWLOntologyChange) new RemoveAxiom(ontology, a)).toList();
            }
            if (kind < 90) {
                // A new room, different from everyone (what the students' DISJOINT IND does).
                List<OWLOntologyChange> changes = new ArrayList<>(room("room" + (individuals.size() + 100),
                        now - random.nextInt(250)).stream().map(a -> (OWLOntologyChange) new AddAxiom(ontology, a))
                        .toList());
                individuals.addAll(doors.subList(doors.size() - 1, doors.size()));
                changes.add(new AddAxiom(ontology, factory.getOWLDifferentIndividualsAxiom(Set.copyOf(individuals))));
                return changes;
            }
            // Time passes alone.
            now += 30 + random.nextInt(90);
            return replace("now", robot, now);
        }
    }

    private void compare(OWLReasonerFactory reasonerFactory, ModularReasoner modular, String after) {
        WholeOntologyAnswers.assertSameAnswers(reasonerFactory, ontology, modular, after);
    }

    /** Rooms in zones of one building (a part-of tree), adjacent rooms in a row, agents in rooms, the dock. */
    private void loadMap() {
        List<OWLAxiom> abox = new ArrayList<>();
        OWLNamedIndividual building = named("building");
        abox.add(factory.getOWLClassAssertionAxiom(cls("Location"), building));
        List<OWLNamedIndividual> zones = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            OWLNamedIndividual zone = named("zone" + i);
            abox.add(factory.getOWLClassAssertionAxiom(cls("Zone"), zone));
            abox.add(edge("partOf", zone, building));
            zones.add(zone);
        }
        for (int i = 0; i < 12; i++) {
            OWLNamedIndividual room = named(i == 0 ? "dock" : "room" + i);
            abox.add(factory.getOWLClassAssertionAxiom(cls(i % 5 == 4 ? "Corridor" : "Room"), room));
            abox.add(edge("partOf", room, zones.get(i % 3)));
            if (i > 0) {
                abox.add(edge("adjacentTo", room, rooms.get(i - 1)));
            }
            rooms.add(room);
        }
        for (int i = 0; i < 24; i++) {
            OWLNamedIndividual agent = named("agent" + i);
            abox.add(factory.getOWLClassAssertionAxiom(cls(i % 4 == 0 ? "Person" : "Robot"), agent));
            abox.add(edge("isIn", agent, rooms.get(random.nextInt(rooms.size()))));
            agents.add(agent);
        }
        individuals.add(building);
        individuals.addAll(zones);
        individuals.addAll(rooms);
        individuals.addAll(agents);
        manager.addAxioms(ontology, abox.stream());
    }

    private List<OWLOntologyChange> randomChanges() {
        // What reshapes links stays one step: the next step takes it away (the map's links are as loaded most steps).
        if (!passing.isEmpty()) {
            List<OWLOntologyChange> undo = passing.stream().filter(ontology::containsAxiom)
                    .map(a -> (OWLOntologyChange) new RemoveAxiom(ontology, a)).toList();
            passing.clear();
            if (!undo.isEmpty()) {
                return undo;
            }
        }
        // A nominal the ABox reaches (Charger is asserted): whole-ontology reasoning while it is there.
        OWLAxiom nominal = factory.getOWLSubClassOfAxiom(cls("Charger"),
                factory.getOWLObjectHasValue(property("near"), individuals.get(0)));
        int kind = random.nextInt(100);
        if (kind < 16) {
            return List.of(toggle(factory.getOWLClassAssertionAxiom(owlClass(), individual())));
        }
        if (kind < 21) {
            return passing(factory.getOWLClassAssertionAxiom(classExpression(), individual()));
        }
        if (kind < 52) {
            return edgeChange();
        }
        if (kind < 55) {
            return passing(factory.getOWLNegativeObjectPropertyAssertionAxiom(randomProperty(), individual(),
                    individual()));
        }
        if (kind < 60) {
            return List.of(toggle(factory.getOWLDataPropertyAssertionAxiom(
                    factory.getOWLDataProperty(IRI.create(NS + "batteryLevel")), individual(), random.nextInt(40))));
        }
        if (kind < 65) {
            return addIndividual();
        }
        if (kind < 68 && individuals.size() > 30) {
            OWLNamedIndividual gone = individuals.remove(1 + random.nextInt(individuals.size() - 1));
            rooms.remove(gone);
            agents.remove(gone);
            return ontology.referencingAxioms(gone).filter(a -> a.isOfType(AxiomType.ABoxAxiomTypes))
                    .map(a -> (OWLOntologyChange) new RemoveAxiom(ontology, a)).toList();
        }
        if (kind < 70) {
            return List.of(toggle(factory.getOWLSameIndividualAxiom(individual(), individual())));
        }
        if (kind < 73) {
            // Difference: a pair, or every individual at once (what DISJOINT IND of a whole map gives).
            return List.of(toggle(random.nextBoolean() ? factory.getOWLDifferentIndividualsAxiom(individual(),
                    individual()) : factory.getOWLDifferentIndividualsAxiom(Set.copyOf(individuals))));
        }
        if (kind < 78) {
            return List.of(toggle(factory.getOWLSubClassOfAxiom(owlClass(), owlClass())));
        }
        if (kind < 93) {
            return passing(propertyAxioms.get(random.nextInt(propertyAxioms.size())));
        }
        if (kind < 95) {
            // An edge into the enumeration only the schema names: its range makes the target one of them.
            return passing(edge("onShift", individual(), individual()));
        }
        return passing(nominal);
    }

    /** Half the time an existing edge goes, else one of the map's shapes is added: the density stays. */
    private List<OWLOntologyChange> edgeChange() {
        List<OWLObjectPropertyAssertionAxiom> edges = ontology.axioms(AxiomType.OBJECT_PROPERTY_ASSERTION)
                .filter(e -> !e.getProperty().getNamedProperty().getIRI().getShortForm().equals("onShift")).toList();
        // Edges off the map's own shapes (random properties between random individuals) go first.
        List<OWLObjectPropertyAssertionAxiom> odd = edges.stream().filter(e -> !List.of("isIn", "partOf",
                "adjacentTo").contains(e.getProperty().getNamedProperty().getIRI().getShortForm())).toList();
        if (!odd.isEmpty() && random.nextBoolean()) {
            return List.of(new RemoveAxiom(ontology, odd.get(random.nextInt(odd.size()))));
        }
        if (random.nextBoolean() && !edges.isEmpty()) {
            return List.of(new RemoveAxiom(ontology, edges.get(random.nextInt(edges.size()))));
        }
        if (random.nextInt(8) < 3) {
            return move();
        }
        return List.of(switch (random.nextInt(5)) {
            case 0 -> new AddAxiom(ontology, edge("partOf", pick(rooms), individual()));
            case 1 -> new AddAxiom(ontology, edge("adjacentTo", pick(rooms), pick(rooms)));
            case 2 -> new AddAxiom(ontology, edge("carries", pick(agents), individual()));
            default -> new AddAxiom(ontology, edge(PROPERTIES.get(random.nextInt(PROPERTIES.size())), individual(),
                    individual()));
        });
    }

    /** An agent moves: every room it is in is replaced by another (the robot's own workload). */
    private List<OWLOntologyChange> move() {
        OWLNamedIndividual agent = pick(agents);
        List<OWLOntologyChange> changes = new ArrayList<>(ontology.objectPropertyAssertionAxioms(agent)
                .filter(e -> e.getProperty().equals(property("isIn")))
                .map(e -> (OWLOntologyChange) new RemoveAxiom(ontology, e)).toList());
        changes.add(new AddAxiom(ontology, edge("isIn", agent, pick(rooms))));
        return changes;
    }

    private OWLClassExpression classExpression() {
        return switch (random.nextInt(5)) {
            case 0 -> factory.getOWLObjectSomeValuesFrom(property("partOf"), cls("Room"));
            case 1 -> factory.getOWLObjectAllValuesFrom(property("contains"), cls("Robot"));
            case 2 -> factory.getOWLObjectHasValue(property("isIn"), rooms.get(0));
            case 3 -> factory.getOWLObjectMaxCardinality(1, property("adjacentTo"));
            default -> factory.getOWLObjectComplementOf(cls("Watched"));
        };
    }

    /** An axiom that reshapes links, added for one step (the next takes it away). */
    private List<OWLOntologyChange> passing(OWLAxiom axiom) {
        if (ontology.containsAxiom(axiom)) {
            return List.of(new RemoveAxiom(ontology, axiom));
        }
        passing.add(axiom);
        return List.of(new AddAxiom(ontology, axiom));
    }

    private OWLOntologyChange toggle(OWLAxiom axiom) {
        return ontology.containsAxiom(axiom) ? new RemoveAxiom(ontology, axiom) : new AddAxiom(ontology, axiom);
    }

    private List<OWLOntologyChange> addIndividual() {
        OWLNamedIndividual individual = named("thing" + fresh++);
        String kind = List.of("Room", "Room", "Corridor", "Robot", "Robot", "Robot", "Person").get(random.nextInt(7));
        List<OWLOntologyChange> changes = new ArrayList<>();
        changes.add(new AddAxiom(ontology, factory.getOWLClassAssertionAxiom(cls(kind), individual)));
        if (kind.equals("Room") || kind.equals("Corridor")) {
            changes.add(new AddAxiom(ontology, edge("partOf", individual, individuals.get(0))));
            rooms.add(individual);
        } else {
            changes.add(new AddAxiom(ontology, edge("isIn", individual, pick(rooms))));
            agents.add(individual);
        }
        individuals.add(individual);
        return changes;
    }

    private OWLAxiom parse(String axiom) throws Exception {
        OWLOntology parsed = OWLManager.createOWLOntologyManager().loadOntologyFromOntologyDocument(
                new StringDocumentSource("Prefix(:=<" + NS + ">) Ontology(" + axiom + ")"));
        return parsed.logicalAxioms().findFirst().orElseThrow();
    }

    private OWLObjectPropertyAssertionAxiom edge(String property, OWLNamedIndividual from, OWLNamedIndividual to) {
        return factory.getOWLObjectPropertyAssertionAxiom(property(property), from, to);
    }

    private OWLNamedIndividual named(String name) {
        return factory.getOWLNamedIndividual(IRI.create(NS + name));
    }

    private OWLNamedIndividual pick(List<OWLNamedIndividual> from) {
        return from.isEmpty() ? individual() : from.get(random.nextInt(from.size()));
    }

    private OWLObjectProperty property(String name) {
        return factory.getOWLObjectProperty(IRI.create(NS + name));
    }

    private OWLObjectProperty randomProperty() {
        return property(PROPERTIES.get(random.nextInt(PROPERTIES.size())));
    }

    private OWLClass owlClass() {
        return cls(CLASSES.get(random.nextInt(CLASSES.size())));
    }

    private OWLClass cls(String name) {
        return factory.getOWLClass(IRI.create(NS + name));
    }

    private OWLNamedIndividual individual() {
        return individuals.get(random.nextInt(individuals.size()));
    }
}
