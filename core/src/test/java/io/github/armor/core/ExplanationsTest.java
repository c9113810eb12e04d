// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Response;
import io.github.armor.core.answers.Syntax;
import io.github.armor.core.bench.JustificationCheck;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.semanticweb.HermiT.ReasonerFactory;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.reasoner.OWLReasoner;

/**
 * EXPLAIN: every justification a directive answers is checked against the ontology it came
 * from: each of its lines is an axiom of the ontology, the set entails the fact (HermiT, on the
 * set alone) and no axiom can be left out (removing any one breaks the entailment). The facts
 * are generated: a random map over the robotics schema, and every fact HermiT infers about it.
 */
class ExplanationsTest {
    private static final String NS = CoreFixture.NS;
    private static final int ROOMS = 6;
    private static final int AGENTS = 6;
    private static final int FACTS_PER_REASONER = 14;

    @TempDir
    Path dir;

    /** A map the robotics schema describes: rooms in a corridor, agents somewhere; the generated ontology's file. */
    private Path generatedMap(OWLOntology ontology) throws Exception {
        OWLDataFactory f = ontology.getOWLOntologyManager().getOWLDataFactory();
        Random random = new Random(31);
        OWLObjectProperty connected = f.getOWLObjectProperty(IRI.create(NS + "connectedTo"));
        OWLObjectProperty isIn = f.getOWLObjectProperty(IRI.create(NS + "isIn"));
        OWLNamedIndividual corridor = f.getOWLNamedIndividual(IRI.create(NS + "hall"));
        ontology.add(f.getOWLClassAssertionAxiom(f.getOWLClass(IRI.create(NS + "Corridor")), corridor));
        for (int i = 0; i < ROOMS; i++) {
            OWLNamedIndividual room = f.getOWLNamedIndividual(IRI.create(NS + "room" + i));
            ontology.add(f.getOWLClassAssertionAxiom(f.getOWLClass(IRI.create(NS + "Room")), room));
            ontology.add(f.getOWLObjectPropertyAssertionAxiom(connected, room, corridor));
        }
        for (int i = 0; i < AGENTS; i++) {
            OWLNamedIndividual agent = f.getOWLNamedIndividual(IRI.create(NS + "agent" + i));
            String kind = i % 2 == 0 ? "Robot" : "Person";
            ontology.add(f.getOWLClassAssertionAxiom(f.getOWLClass(IRI.create(NS + kind)), agent));
            ontology.add(f.getOWLObjectPropertyAssertionAxiom(isIn, agent,
                    f.getOWLNamedIndividual(IRI.create(NS + "room" + random.nextInt(ROOMS)))));
        }
        Path file = dir.resolve("map.owl");
        ontology.getOWLOntologyManager().saveOntology(ontology, IRI.create(file.toUri()));
        return file;
    }

    private static OWLOntology robotics() {
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        try {
            return manager.loadOntologyFromOntologyDocument(CoreFixture.ONTOLOGIES.resolve("robotics.owl").toFile());
        } catch (org.semanticweb.owlapi.model.OWLOntologyCreationException e) {
            throw new AssertionError(e);
        }
    }

    /** Inferred (not asserted) class assertions and object property values HermiT finds, in a stable order. */
    private static List<OWLAxiom> inferredFacts(OWLOntology ontology) {
        OWLDataFactory f = ontology.getOWLOntologyManager().getOWLDataFactory();
        OWLReasoner reasoner = new ReasonerFactory().createReasoner(ontology);
        List<OWLAxiom> facts = new ArrayList<>();
        ontology.individualsInSignature().sorted().forEach(individual -> {
            reasoner.getTypes(individual, false).entities().filter(c -> !c.isOWLThing()).sorted()
                    .forEach(c -> facts.add(f.getOWLClassAssertionAxiom(c, individual)));
            ontology.objectPropertiesInSignature().sorted().forEach(p -> reasoner.getObjectPropertyValues(individual, p)
                    .entities().sorted().forEach(o -> facts.add(f.getOWLObjectPropertyAssertionAxiom(p, individual, o))));
        });
        reasoner.dispose();
        facts.removeIf(fact -> ontology.containsAxiom(fact));
        return facts;
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT", "ELK"})
    void everyJustificationIsInTheOntologyEntailsTheFactAndIsMinimal(String reasoner) throws Exception {
        OWLOntology ontology = robotics();
        Path file = generatedMap(ontology);
        CoreFixture fixture = new CoreFixture(dir);
        fixture.ok("map", "LOAD FILE", file.toString(), "http://www.example.org/robotics", "false", reasoner, "false");
        List<OWLAxiom> facts = inferredFacts(ontology);
        // Spread over the kinds of facts: every k-th of them.
        int step = Math.max(1, facts.size() / FACTS_PER_REASONER);
        int explained = 0;
        for (int i = 0; i < facts.size(); i += step) {
            OWLAxiom fact = facts.get(i);
            Response response = fixture.run("map", words(fact), arguments(fact, "2"));
            if (reasoner.equals("ELK") && (response.exitCode() == 227 || response.exitCode() == 219)) {
                // ELK infers nothing beyond OWL 2 EL (227: nothing to explain) and lists no
                // property values at all (219, as QUERY OBJECTPROP IND answers on ELK)
                continue;
            }
            assertTrue(response.success(), () -> fact + ": " + response.exitCode() + " " + response.errorDescription());
            checkJustifications(ontology, fact, response.queriedObjects());
            explained++;
        }
        assertTrue(explained >= (reasoner.equals("ELK") ? 3 : FACTS_PER_REASONER / 2),
                reasoner + " explained only " + explained + " of " + facts.size() + " facts");
    }

    @Test
    void aSubsumptionIsExplainedByTheSchemaAlone() throws Exception {
        OWLOntology ontology = robotics();
        CoreFixture fixture = new CoreFixture(dir);
        fixture.loadRobotics("map", "HERMIT", false);
        OWLDataFactory f = ontology.getOWLOntologyManager().getOWLDataFactory();
        OWLAxiom fact = f.getOWLSubClassOfAxiom(cls(f, "RobotInRoom"), cls(f, "Agent"));
        List<String> lines = fixture.ok("map", "EXPLAIN CLASS CLASS", "RobotInRoom", "Agent", "3").queriedObjects();
        checkJustifications(ontology, fact, lines);
        assertTrue(lines.stream().allMatch(l -> l.split(" ")[1].equals("axiom")), () -> lines.toString());
    }

    @Test
    void aSubsumptionThroughToldLinksIsSearchedOnThoseLinksFirst() throws Exception {
        String ns = "http://www.example.org/kitchen#";
        // Cup -> Crockery -> Tableware = Dishware -> PhysicalObject, among axioms a STAR module keeps.
        Path file = dir.resolve("kitchen.ofn");
        java.nio.file.Files.writeString(file, "Prefix(:=<" + ns + ">) Ontology(<" + ns + "o>\n"
                + "SubClassOf(:Cup :Crockery) SubClassOf(:Crockery :Tableware)\n"
                + "EquivalentClasses(:Tableware :Dishware) SubClassOf(:Dishware :PhysicalObject)\n"
                + "SubClassOf(:Cup ObjectSomeValuesFrom(:hasPart :Handle)) SubClassOf(:Handle :PhysicalObject)\n"
                + "SubClassOf(:Crockery ObjectAllValuesFrom(:madeOf :Ceramic)) SubClassOf(:Glass :Tableware)\n"
                + "SubClassOf(ObjectSomeValuesFrom(:hasPart :PhysicalObject) :PhysicalObject)\n"
                + "DisjointClasses(:Ceramic :Handle))\n");
        // The four told links are searched, not the module that also holds the hasPart path.
        assertExplainedBy(file, ns, "searched 4 of 10 axioms", List.of("1 axiom Crockery SubClassOf Tableware",
                "1 axiom Cup SubClassOf Crockery", "1 axiom Dishware EquivalentTo Tableware",
                "1 axiom Dishware SubClassOf PhysicalObject"), "EXPLAIN CLASS CLASS", "Cup", "PhysicalObject", "1");
    }

    /** The directive's justification, each line without the namespace, sorted; what its description says it searched. */
    private void assertExplainedBy(Path file, String ns, String searched, List<String> lines, String words,
                                   String... args) {
        CoreFixture fixture = new CoreFixture(dir);
        fixture.ok("r", "LOAD FILE", file.toString(), ns + "o", "false", "HERMIT", "false");
        Response answer = fixture.ok("r", words, args);
        assertEquals(lines, answer.queriedObjects().stream().map(line -> line.replace("<" + ns, "")
                .replace(">", "")).sorted().toList());
        assertTrue(answer.errorDescription().contains(searched), answer.errorDescription());
    }

    @Test
    void aLinkOfATransitivePropertyIsSearchedOnItsChainFirst() throws Exception {
        String ns = "http://www.example.org/depot#";
        StringBuilder map = new StringBuilder("Prefix(:=<" + ns + ">) Ontology(<" + ns + "o>\n"
                + "TransitiveObjectProperty(:partOf) ObjectPropertyDomain(:partOf :Place)\n"
                + "ObjectPropertyAssertion(:partOf :floor0 :building) ObjectPropertyAssertion(:partOf :floor1 :building)\n");
        for (int zone = 0; zone < 6; zone++) {
            map.append("ObjectPropertyAssertion(:partOf :zone").append(zone).append(" :floor").append(zone % 2)
                    .append(")\n");
            for (int room = 0; room < 5; room++) {
                map.append("ObjectPropertyAssertion(:partOf :room").append(zone).append('_').append(room)
                        .append(" :zone").append(zone).append(") ClassAssertion(:Room :room").append(zone)
                        .append('_').append(room).append(")\n");
            }
        }
        Path file = dir.resolve("depot.ofn");
        java.nio.file.Files.writeString(file, map.append(")\n").toString());
        // The chain and the property's transitivity are searched, not the tree around the two.
        assertExplainedBy(file, ns, "searched 4 of ", List.of("1 asserted floor1 partOf building",
                "1 asserted room3_2 partOf zone3", "1 asserted zone3 partOf floor1", "1 axiom Transitive: partOf"),
                "EXPLAIN OBJECTPROP IND", "partOf", "room3_2", "building", "1");
    }

    @Test
    void anAssertedFactAnswersItselfAndAFactThatDoesNotHoldSaysSo() {
        CoreFixture fixture = new CoreFixture(dir);
        fixture.loadRobotics("map", "HERMIT", false);
        Response asserted = fixture.ok("map", "EXPLAIN OBJECTPROP IND", "isIn", "robot1", "kitchen");
        assertEquals(List.of("1 asserted " + CoreFixture.iri("robot1") + " " + CoreFixture.iri("isIn") + " "
                + CoreFixture.iri("kitchen")), asserted.queriedObjects());
        assertTrue(asserted.errorDescription().startsWith("asserted"), asserted.errorDescription());
        // Nobody is in the bedroom (robot1 is in the kitchen, which makes that one occupied).
        CoreFixture.assertFails(fixture.run("map", "EXPLAIN IND CLASS", "bedroom", "OccupiedRoom"), 227);
        CoreFixture.assertFails(fixture.run("map", "EXPLAIN CLASS CLASS", "Agent", "Robot"), 227);
        CoreFixture.assertFails(fixture.run("map", "EXPLAIN DATAPROP IND", "batteryLevel", "robot1", "INTEGER", "81"),
                227);
        CoreFixture.assertFails(fixture.run("map", "EXPLAIN IND CLASS", "robot1", "Agent", "0"), 207);
        CoreFixture.assertFails(fixture.run("map", "EXPLAIN IND CLASS", "robot1", "Agent", "two"), 207);
        CoreFixture.assertFails(fixture.run("map", "EXPLAIN INCONSISTENCY"), 227);
    }

    @Test
    void anInferredDataValueNamesTheAxiomsItComesFrom() {
        CoreFixture fixture = new CoreFixture(dir);
        fixture.loadRobotics("map", "HERMIT", false);
        fixture.ok("map", "ADD IND CLASS", "robot1", "FullRobot");
        fixture.ok("map", "ADD AXIOM", "FullRobot SubClassOf batteryLevel value 100");
        List<String> lines = fixture.ok("map", "EXPLAIN DATAPROP IND", "batteryLevel", "robot1", "INTEGER", "100")
                .queriedObjects();
        assertEquals(2, lines.size(), lines::toString);
        assertTrue(lines.get(0).startsWith("1 asserted ") && lines.get(1).startsWith("1 axiom "), lines::toString);
    }

    @Test
    void theInconsistencyIsExplainedTheSameWay() throws Exception {
        CoreFixture fixture = new CoreFixture(dir);
        fixture.loadRobotics("map", "PELLET", false);
        fixture.ok("map", "ADD IND CLASS", "kitchen", "Corridor");
        fixture.ok("map", "REASON");
        Response response = fixture.run("map", "EXPLAIN INCONSISTENCY");
        assertTrue(response.success(), response::errorDescription);
        assertFalse(response.isConsistent());
        List<String> lines = response.queriedObjects();
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("1 axiom ") && l.contains("DisjointWith")), lines::toString);
        assertTrue(lines.stream().anyMatch(l -> l.equals("1 asserted " + CoreFixture.iri("kitchen") + " Type "
                + CoreFixture.iri("Corridor"))), lines::toString);
        CoreFixture.assertFails(fixture.run("map", "EXPLAIN IND CLASS", "robot1", "Agent"), 217);
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET"})
    void aRuleNamesItselfAndTheBindingsThatFiredIt(String reasoner) {
        CoreFixture fixture = new CoreFixture(dir);
        fixture.loadRobotics("map", reasoner, false);
        fixture.ok("map", "ADD SWRL", "visitedByRobot", "Robot(?r), isIn(?r, ?l) -> Visited(?l)");
        fixture.ok("map", "REASON");
        List<String> lines = fixture.ok("map", "EXPLAIN IND CLASS", "kitchen", "Visited").queriedObjects();
        String rule = lines.stream().filter(l -> l.startsWith("1 rule ")).findFirst().orElse(null);
        assertNotNull(rule, lines::toString);
        assertTrue(rule.startsWith("1 rule visitedByRobot: "), rule);
        assertTrue(rule.endsWith(" | ?l=" + CoreFixture.iri("kitchen") + ", ?r=" + CoreFixture.iri("robot1")), rule);
    }

    @Test
    void severalJustificationsAreNumbered() {
        CoreFixture fixture = new CoreFixture(dir);
        fixture.loadRobotics("map", "HERMIT", false);
        // robot1 is an Agent as a Robot, and also as the subject of isIn (whose domain is Agent).
        List<String> lines = fixture.ok("map", "EXPLAIN IND CLASS", "robot1", "Agent", "5").queriedObjects();
        Set<String> numbers = lines.stream().map(l -> l.split(" ")[0]).collect(Collectors.toSet());
        assertTrue(numbers.containsAll(Set.of("1", "2")), lines::toString);
        OWLOntology ontology = robotics();
        OWLDataFactory f = ontology.getOWLOntologyManager().getOWLDataFactory();
        checkJustifications(ontology, f.getOWLClassAssertionAxiom(cls(f, "Agent"), ind(f, "robot1")), lines);
    }

    @Test
    void theCheckOfAnswersCatchesAWrongJustification() {
        CoreFixture fixture = new CoreFixture(dir);
        fixture.loadRobotics("map", "HERMIT", false);
        List<String> lines = fixture.ok("map", "EXPLAIN IND CLASS", "robot1", "Agent", "1").queriedObjects();
        OWLOntology ontology = robotics();
        OWLDataFactory f = ontology.getOWLOntologyManager().getOWLDataFactory();
        OWLAxiom fact = f.getOWLClassAssertionAxiom(cls(f, "Agent"), ind(f, "robot1"));
        JustificationCheck check = new JustificationCheck(ontology, true);
        assertEquals(new JustificationCheck.Verdict(1, List.of()), check.check(fact, lines));

        String unrelated = ontology.logicalAxioms().map(a -> "1 axiom " + Syntax.render(null, true, a))
                .filter(line -> !lines.contains(line)).findFirst().orElseThrow();
        List<String> withOneMore = new ArrayList<>(lines);
        withOneMore.add(unrelated);
        assertTrue(check.check(fact, withOneMore).problems().get(0).contains("is not minimal"));
        assertTrue(check.check(fact, lines.subList(0, lines.size() - 1)).problems().get(0)
                .contains("does not entail the fact"));
        assertTrue(check.check(fact, List.of("1 axiom Robot SubClassOf Nothing")).problems().get(0)
                .startsWith("not an axiom of the ontology"));
    }

    @Test
    void pastTheTimeLimitWhatWasFoundIsAnsweredMarkedPartial() {
        long limitMs = 4_000;
        CoreFixture fixture = new CoreFixture(new CoreConfig(true, "HERMIT", List.of(CoreFixture.ONTOLOGIES, dir),
                false, 30_000, limitMs, 0, CoreConfig.Durability.NONE));
        fixture.ok("map", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(),
                "http://www.example.org/robotics", "false", StallingChecksReasonerFactory.class.getName(), "false");
        OWLDataFactory f = OWLManager.getOWLDataFactory();
        OWLAxiom fact = f.getOWLClassAssertionAxiom(cls(f, "Agent"), ind(f, "robot1"));
        try {
            // How many checks the first of robot1's justifications takes (the second run: the
            // reference's own reasoner is made by then).
            fixture.ok("map", "EXPLAIN IND CLASS", "robot1", "Agent", "1");
            StallingChecksReasonerFactory.reset(Integer.MAX_VALUE);
            fixture.ok("map", "EXPLAIN IND CLASS", "robot1", "Agent", "1");
            int firstChecks = StallingChecksReasonerFactory.MADE.get();
            assertTrue(firstChecks > 0, "no entailment check made a reasoner");

            // robot1 has three justifications: the search for the others stalls past the limit.
            StallingChecksReasonerFactory.reset(firstChecks);
            Response partial = fixture.run("map", "EXPLAIN IND CLASS", "robot1", "Agent", "3");
            assertEquals(211, partial.exitCode(), partial::errorDescription);
            assertTrue(partial.timeout());
            assertFalse(partial.success());
            assertTrue(partial.errorDescription().startsWith("partial: 1 justification(s)"), partial.errorDescription());
            List<String> lines = partial.queriedObjects();
            assertTrue(lines.stream().allMatch(l -> l.startsWith("1 ")), lines::toString);
            checkJustifications(robotics(), fact, lines);

            // Stalled from the first check: partial with nothing found, never a set not checked.
            StallingChecksReasonerFactory.reset(0);
            Response nothing = fixture.run("map", "EXPLAIN IND CLASS", "robot1", "Agent", "3");
            assertEquals(211, nothing.exitCode(), nothing::errorDescription);
            assertTrue(nothing.timeout());
            assertEquals(List.of(), nothing.queriedObjects());
            assertTrue(nothing.errorDescription().startsWith("partial: 0 justification(s)"),
                    nothing.errorDescription());
        } finally {
            StallingChecksReasonerFactory.reset(Integer.MAX_VALUE);
        }
    }

    /** Each justification of the answer: its lines are axioms of the ontology, it entails the fact, it is minimal. */
    private static void checkJustifications(OWLOntology ontology, OWLAxiom fact, List<String> lines) {
        JustificationCheck.Verdict verdict = new JustificationCheck(ontology, true).check(fact, lines);
        assertTrue(verdict.problems().isEmpty(), () -> "explaining " + fact + ": " + verdict.problems());
        assertTrue(verdict.right() > 0, () -> "no justification of " + fact);
    }

    private static String words(OWLAxiom fact) {
        return switch (fact.getAxiomType().getName()) {
            case "ClassAssertion" -> "EXPLAIN IND CLASS";
            case "ObjectPropertyAssertion" -> "EXPLAIN OBJECTPROP IND";
            default -> throw new IllegalArgumentException(fact.toString());
        };
    }

    private static String[] arguments(OWLAxiom fact, String limit) {
        if (fact instanceof org.semanticweb.owlapi.model.OWLClassAssertionAxiom a) {
            return new String[] {iri(a.getIndividual().asOWLNamedIndividual()),
                    iri(a.getClassExpression().asOWLClass()), limit};
        }
        var a = (org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom) fact;
        return new String[] {iri(a.getProperty().asOWLObjectProperty()), iri(a.getSubject().asOWLNamedIndividual()),
                iri(a.getObject().asOWLNamedIndividual()), limit};
    }

    private static String iri(org.semanticweb.owlapi.model.OWLEntity entity) {
        return entity.getIRI().toString();
    }

    private static OWLClass cls(OWLDataFactory f, String name) {
        return f.getOWLClass(IRI.create(NS + name));
    }

    private static OWLNamedIndividual ind(OWLDataFactory f, String name) {
        return f.getOWLNamedIndividual(IRI.create(NS + name));
    }

}
