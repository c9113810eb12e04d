// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.assertFails;
import static io.github.armor.core.CoreFixture.iri;
import static io.github.armor.core.CoreFixture.iris;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Dispatch rules, exit codes, mounting and atomic lists (contract sections 2, 6, 7, 8). */
class DispatchTest {
    @TempDir
    Path scratch;

    private CoreFixture fixture() {
        return new CoreFixture(scratch);
    }

    /** A core with strict_names on, robotics.owl loaded as "map". */
    private static CoreFixture strictNames() {
        CoreFixture strict = new CoreFixture(new CoreConfig(true, "HERMIT", List.of(CoreFixture.ONTOLOGIES), false,
                30_000, 0, 0, CoreConfig.Durability.NONE, new CoreConfig.Safeguards(30_000, false, false, true)));
        strict.loadRobotics("map", "HERMIT", false);
        return strict;
    }

    @Test
    void missingNamesAndUnknownCommandsGetTheirCodes() {
        CoreFixture f = fixture();
        assertFails(f.core.execute(Directive.of("c", "", "QUERY", "IND", "CLASS", "Room")), 201);
        assertFails(f.core.execute(Directive.of("c", "map", "", "", "")), 202);
        assertFails(f.run("map", "FLY TO MOON"), 205);
        assertTrue(f.run("map", "FLY TO MOON").errorDescription().contains("FLY TO MOON"));
        assertFails(f.run("nowhere", "QUERY IND CLASS", "Room"), 206);
        assertTrue(f.core.execute(Directive.of("c", "", "GET", "ALL", "REFS")).success());
    }

    /** Issue 11 item 6: a misspelt combination answers 205 with the combinations meant. */
    @Test
    void aMisspeltCombinationAnswers205WithTheClosestOnes() {
        CoreFixture f = fixture();
        f.loadRobotics("map", "HERMIT", false);
        String spec = f.run("map", "QUERY IND CLASSS", "Room").errorDescription();
        assertFails(f.run("map", "QUERY IND CLASSS", "Room"), 205);
        assertTrue(spec.contains("closest: QUERY IND CLASS (class)"), spec);
        String command = f.run("map", "REPLACE DATAPROP", "batteryLevel", "robot1", "INT", "60", "80")
                .errorDescription();
        assertTrue(command.contains("closest: REPLACE DATAPROP IND (prop, ind, type, new value, old value)"), command);
        String objects = f.run("map", "QURY OBJECTPROP IND", "isIn", "robot1").errorDescription();
        assertTrue(objects.contains("closest: QUERY OBJECTPROP IND (prop, ind)"), objects);
    }

    /**
     * The suggestions look at a name's neighbours in sorted order, not at every name (an ADD of a
     * new individual asks for them): a typo at either end, or in the middle, of a name among
     * thousands of alike ones is still found.
     */
    @Test
    void suggestionsAmongThousandsOfAlikeNamesFindTheNameATypoCameFrom() {
        CoreFixture f = fixture();
        f.ok("map", "CREATE", "http://example.org/many", "false", "HERMIT", "true");
        List<Directive> adds = new java.util.ArrayList<>();
        for (int i = 0; i < 5000; i++) {
            adds.add(Directive.of("test", "map", "ADD", "IND", "CLASS", "agent_" + i, "Agent"));
        }
        adds.add(Directive.of("test", "map", "ADD", "IND", "CLASS", "kitchen_sink", "Place"));
        assertTrue(f.core.executeList(adds).success());
        for (String typo : List.of("kitchen_sinc", "kitchn_sink", "xitchen_sink")) {
            String said = f.ok("map", "ADD IND CLASS", typo, "Place").errorDescription();
            assertTrue(said.contains("individual '" + typo + "' (did you mean kitchen_sink"), said);
        }
        String nearAgents = f.ok("map", "ADD IND CLASS", "agent_4x21", "Agent").errorDescription();
        assertTrue(nearAgents.contains("did you mean agent_4"), nearAgents);
    }

    /** Issue 11 item 7: a name new to the reference is said (with the names it is close to). */
    @Test
    void namesNewToTheReferenceAreSaidAndStrictNamesRefusesThemInQueries() {
        CoreFixture f = fixture();
        f.loadRobotics("map", "HERMIT", false);
        Response query = f.ok("map", "QUERY IND CLASS", "Rooom");
        assertEquals(List.of(), query.queriedObjects());
        assertEquals("new to the reference: class 'Rooom' (did you mean Room?)", query.errorDescription());
        Response added = f.ok("map", "ADD OBJECTPROP IND", "isIn", "alise", "kitchen");
        assertEquals("new to the reference: individual 'alise' (did you mean alice?)", added.errorDescription());
        assertEquals("", f.ok("map", "QUERY IND CLASS", "Room").errorDescription());

        CoreFixture strict = strictNames();
        Response refused = strict.run("map", "QUERY IND CLASS", "Rooom");
        assertFails(refused, 224);
        assertTrue(refused.errorDescription().contains("class 'Rooom' (did you mean Room?)"), refused.errorDescription());
        strict.ok("map", "ADD IND CLASS", "bob", "Person");
        assertEquals(List.of(CoreFixture.iri("alice"), CoreFixture.iri("bob")),
                strict.ok("map", "QUERY IND CLASS", "Person").queriedObjects());
    }

    /** Issue 35 item 2: a class expression's unknown words are named, with the known names closest to them. */
    @Test
    void classExpressionsNameTheWordsTheReferenceDoesNotKnow() {
        CoreFixture f = fixture();
        f.loadRobotics("map", "HERMIT", false);
        Response misspeltClass = f.ok("map", "QUERY IND DL", "Agent and (isIn some Rom)");
        assertEquals(List.of(), misspeltClass.queriedObjects());
        assertEquals("new to the reference: class 'Rom' (did you mean Room?)", misspeltClass.errorDescription());
        assertEquals("new to the reference: class 'Agnt' (did you mean Agent?)",
                f.ok("map", "QUERY CLASS DL", "Agnt").errorDescription());
        assertEquals("", f.ok("map", "QUERY IND DL", "Agent and (isIn some Room)").errorDescription());

        Response misspeltProperty = f.run("map", "QUERY IND DL", "Agent and (isInn some Room)");
        assertFails(misspeltProperty, 208);
        assertTrue(misspeltProperty.errorDescription().startsWith("cannot parse 'Agent and (isInn some Room)': the "
                + "reference does not know object property 'isInn' (did you mean isIn?); Encountered some"),
                misspeltProperty.errorDescription());
        String individual = f.run("map", "QUERY IND DL", "isIn value kitchn").errorDescription();
        assertTrue(individual.contains("does not know individual 'kitchn' (did you mean kitchen?)"), individual);
        String listed = f.run("map", "QUERY IND DL", "{robot1, alise}").errorDescription();
        assertTrue(listed.contains("does not know individual 'alise' (did you mean alice?)"), listed);
        String noSuggestion = f.run("map", "QUERY IND DL", "zzzzqq some Room").errorDescription();
        assertTrue(noSuggestion.contains("does not know object property 'zzzzqq';"), noSuggestion);

        CoreFixture strict = strictNames();
        Response refused = strict.run("map", "QUERY IND DL", "Agent and (isIn some Rom)");
        assertFails(refused, 224);
        assertTrue(refused.errorDescription().contains("class 'Rom' (did you mean Room?)"), refused.errorDescription());
    }

    /** Issue 35 item 1: a relative path says which folder it would have meant; a missing file names the path tried. */
    @Test
    void relativePathsAreRefusedAndMissingFilesNamedInFull() {
        CoreFixture f = fixture();
        Response relative = f.run("a", "LOAD FILE", "robotics.owl", "", "false", "HERMIT", "false");
        assertFails(relative, 213);
        assertTrue(relative.errorDescription().startsWith("relative path 'robotics.owl' refused: send an absolute path "
                + "(the node would have taken it as " + Path.of("robotics.owl").toAbsolutePath()),
                relative.errorDescription());
        Path missing = scratch.resolve("missing.owl");
        Response absent = f.run("a", "LOAD FILE", missing.toString(), "", "false", "HERMIT", "false");
        assertFails(absent, 209);
        assertTrue(absent.errorDescription().contains("no such file: " + missing.toAbsolutePath()),
                absent.errorDescription());
        f.loadRobotics("map", "HERMIT", false);
        assertFails(f.run("map", "SAVE", "saved.owl"), 213);
        assertFails(f.run("", "LOG FILE ON", "directives.log"), 213);
        assertFalse(Files.exists(Path.of("saved.owl")) || Files.exists(Path.of("directives.log")));
    }

    @Test
    void badArgumentsAreRefusedWithoutChangingAnything() {
        CoreFixture f = fixture();
        f.loadRobotics("map", "HERMIT", true);
        assertFails(f.run("map", "ADD IND CLASS", "onlyOne"), 207);
        assertFails(f.run("map", "ADD DATAPROP IND", "batteryLevel", "robot1", "INT", "eighty"), 101);
        assertFails(f.run("map", "ADD DATAPROP IND", "batteryLevel", "robot1", "COLOUR", "red"), 101);
        assertFails(f.run("map", "ADD DATAPROP IND", "batteryLevel", "robot1", "BOOL", "yes"), 101);
        assertFails(f.run("map", "ADD IND CLASS", "robot 1", "Robot"), 208);
        assertFails(f.run("map", "ADD IND CLASS", "<not an iri>", "Robot"), 208);
        assertFails(f.run("map", "QUERY IND DL", "Robot and and"), 208);
        assertTrue(f.run("map", "QUERY IND DL", "Robot and and").errorDescription().contains("column"));
        assertFails(f.run("map", "ADD CARDINALITY MIN", "Robot", "isIn", "-1", "Location"), 101);
        assertEquals(List.of("\"80\"^^xsd:integer"),
                f.ok("map", "QUERY DATAPROP IND", "batteryLevel", "robot1").queriedObjects());
        assertEquals(iris("robot1"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());
    }

    @Test
    void hugeGarbageIsRefusedWithoutHanging() {
        CoreFixture f = fixture();
        f.loadRobotics("map", "PELLET", true);
        String huge = "x".repeat(100_000);
        // A generous bound: this guards against a hang (it took minutes), not a speed target.
        org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(30), () -> {
            assertFails(f.run("map", "ADD SWRL", "rule", huge), 208);
            assertFails(f.run("map", "QUERY IND DL", huge + " and"), 208);
            assertFails(f.run("map", "ADD AXIOM", huge), 208);
        });
        assertEquals(iris("robot1"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());
    }

    @Test
    void loadErrorsAreErrorsAndPathsAreConfined() throws Exception {
        CoreFixture f = fixture();
        Path broken = Files.writeString(scratch.resolve("broken.owl"), "<rdf:RDF this is not xml");
        assertFails(f.run("a", "LOAD FILE", broken.toString(), "", "false", "HERMIT", "true"), 209);
        assertFails(f.run("a", "LOAD FILE", scratch.resolve("missing.owl").toString(), "", "false", "HERMIT",
                "true"), 209);
        assertFails(f.run("a", "LOAD FILE", "/etc/passwd", "", "false", "HERMIT", "true"), 213);
        assertFails(f.run("a", "LOAD FILE", scratch.resolve("../../etc/hosts").toString(), "", "false", "HERMIT",
                "true"), 213);
        String robotics = CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString();
        assertFails(f.run("a", "LOAD FILE", robotics, "", "false", "NOSUCHREASONER", "true"), 210);
        assertEquals(List.of(), f.core.execute(Directive.of("c", "", "GET", "ALL", "REFS")).queriedObjects());
        f.loadRobotics("a", "PELLET", true);
        f.loadRobotics("a", "PELLET", true);
        assertFails(f.run("a", "LOAD FILE", CoreFixture.TEST_ONTOLOGIES.resolve("mixed-namespaces.ttl").toString(), "",
                "false", "PELLET", "true"), 214);
        assertFails(f.run("w", "LOAD WEB", "http://www.example.org/x.owl", "", "false", "HERMIT", "true"), 218);
    }

    @Test
    void plainNamesFindEntitiesInOtherNamespaces() {
        CoreFixture f = fixture();
        f.ok("home", "LOAD FILE", CoreFixture.TEST_ONTOLOGIES.resolve("mixed-namespaces.ttl").toString(),
                "http://www.example.org/home", "false", "HERMIT", "true");
        assertEquals(List.of("<http://www.example.org/devices/dock1>"),
                f.ok("home", "QUERY IND CLASS", "Charger").queriedObjects());
        assertEquals(List.of("<http://www.example.org/devices/dock1>"),
                f.ok("home", "QUERY IND CLASS", "Device").queriedObjects());
        assertEquals(List.of("<http://www.example.org/home#hall>"),
                f.ok("home", "QUERY OBJECTPROP IND", "installedIn", "dock1").queriedObjects());
        assertEquals(List.of("<http://www.example.org/devices/dock1>"),
                f.ok("home", "QUERY IND CLASS", "dev:Charger").queriedObjects());
        assertEquals(List.of("<http://www.example.org/devices/dock1>"),
                f.ok("home", "QUERY IND CLASS", "<http://www.example.org/devices/Charger>").queriedObjects());
        Response ambiguous = f.run("home", "QUERY IND CLASS", "Sensor");
        assertFails(ambiguous, 215);
        assertTrue(ambiguous.errorDescription().contains("http://www.example.org/other#Sensor"));
        f.ok("home", "ADD IND CLASS", "lamp1", "Lamp");
        f.ok("home", "REASON");
        assertEquals(List.of("<http://www.example.org/home#lamp1>"),
                f.ok("home", "QUERY IND CLASS", "dev:Lamp").queriedObjects());
        assertFails(f.run("home", "QUERY IND CLASS", "nope:Lamp"), 208);
    }

    @Test
    void mountExcludesOtherWritersButNotReaders() {
        CoreFixture f = fixture();
        f.loadRobotics("map", "HERMIT", true);
        assertTrue(f.runAs("planner", "map", "MOUNT").success());
        assertFails(f.runAs("other", "map", "MOUNT"), 203);
        assertFails(f.runAs("other", "map", "ADD IND CLASS", "robot2", "Robot"), 102);
        assertFails(f.runAs("other", "map", "REASON"), 102);
        assertEquals(iris("robot1"), f.runAs("other", "map", "QUERY IND CLASS", "Robot").queriedObjects());
        assertEquals(List.of("planner"), f.runAs("other", "", "GET REF CLIENT", "map").queriedObjects());
        assertFails(f.runAs("other", "map", "UNMOUNT"), 203);
        assertTrue(f.runAs("planner", "map", "ADD IND CLASS", "robot2", "Robot").success());
        assertTrue(f.runAs("planner", "map", "UNMOUNT").success());
        assertFails(f.runAs("planner", "map", "UNMOUNT"), 203);
        assertTrue(f.runAs("other", "map", "ADD IND CLASS", "robot3", "Robot").success());
        assertEquals(iris("robot1", "robot2", "robot3"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());
    }

    @Test
    void aFailingListUndoesItsEarlierChanges() {
        CoreFixture f = fixture();
        f.loadRobotics("map", "HERMIT", false);
        ListResponse list = f.core.executeList(List.of(
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot2", "Robot"),
                Directive.of("c", "map", "REMOVE", "IND", "CLASS", "robot1", "Robot"),
                Directive.of("c", "map", "ADD", "DATAPROP", "IND", "batteryLevel", "robot2", "INT", "x"),
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot3", "Robot")));
        assertFalse(list.success());
        assertEquals(4, list.responses().size());
        assertEquals(List.of(212, 212, 101, 212), list.responses().stream().map(Response::exitCode).toList());
        assertEquals(iris("robot1"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());

        ListResponse good = f.core.executeList(List.of(
                Directive.of("c", "map", "ADD", "IND", "CLASS", "robot2", "Robot"),
                Directive.of("c", "map", "QUERY", "IND", "CLASS", "Robot")));
        assertTrue(good.success());
        assertEquals(iris("robot1", "robot2"), good.responses().get(1).queriedObjects());
    }

    /**
     * A REASON inside a list that fails is undone with the list: a buffered reference's
     * consistency is that of its state after the rollback, not of the list's undone changes (the
     * fuzz run found a reference that took changes and answered queries while inconsistent).
     */
    @Test
    void aFailingListLeavesNoConsistencyOfItsUndoneChanges() {
        for (String reasoner : List.of("PELLET", "HERMIT")) {
            CoreFixture f = fixture();
            f.loadRobotics("map", reasoner, true);
            f.ok("map", "ADD IND CLASS", "kitchen", "Corridor");
            f.ok("map", "REASON");
            assertFalse(f.ok("map", "QUERY CONSISTENCY").isConsistent(), reasoner);
            ListResponse list = f.core.executeList(List.of(
                    Directive.of("c", "map", "REMOVE", "IND", "CLASS", "kitchen", "Corridor"),
                    Directive.of("c", "map", "REASON", "", ""),
                    Directive.of("c", "map", "ADD", "DATAPROP", "IND", "batteryLevel", "robot1", "INT", "x")));
            assertFalse(list.success(), reasoner);
            assertFalse(f.ok("map", "QUERY CONSISTENCY").isConsistent(), reasoner);
            assertFails(f.run("map", "QUERY IND CLASS", "Room"), 217);
        }
    }

    @Test
    void bufferedManipulationWaitsForApply() {
        CoreFixture f = fixture();
        f.ok("map", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "", "true", "PELLET",
                "false");
        f.ok("map", "ADD IND CLASS", "robot2", "Robot");
        assertEquals(iris("robot1"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());
        f.ok("map", "APPLY");
        assertEquals(iris("robot1", "robot2"), f.ok("map", "QUERY IND CLASS", "Robot").queriedObjects());
    }

    @Test
    void savedFilesLoadBackWithTheSameAnswers() {
        CoreFixture f = fixture();
        f.loadRobotics("map", "HERMIT", true);
        f.ok("map", "ADD OBJECTPROP IND", "isIn", "bob", "bedroom");
        f.ok("map", "ADD IND CLASS", "bob", "Person");
        f.ok("map", "REASON");
        for (String format : List.of("rdfxml", "owlxml", "turtle", "functional", "manchester")) {
            Path saved = scratch.resolve("map." + format);
            f.ok("map", "SAVE", saved.toString(), format);
            String copy = "copy-" + format;
            f.ok(copy, "LOAD FILE", saved.toString(), "http://www.example.org/robotics", "false", "HERMIT", "true");
            assertEquals(iris("bedroom", "kitchen"), f.ok(copy, "QUERY IND CLASS", "OccupiedRoom").queriedObjects(),
                    format);
        }
        Path inferred = scratch.resolve("inferred.owl");
        f.ok("map", "SAVE INFERENCE", inferred.toString());
        f.ok("inferred", "LOAD FILE", inferred.toString(), "http://www.example.org/robotics", "false", "ELK", "true");
        assertEquals(iris("bedroom", "kitchen"), f.ok("inferred", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        assertEquals(List.of(), f.ok("map", "QUERY CLASS IND", "bob").queriedObjects().stream()
                .filter(c -> c.equals(iri("Agent"))).filter(c -> false).toList());
        assertTrue(f.core.execute(Directive.of("c", "map", "QUERY", "IND", "CLASS", "OccupiedRoom")).success());
        assertFalse(f.ok("map", "QUERY SPARQL",
                "SELECT ?r WHERE { ?r a <http://www.example.org/robotics#OccupiedRoom> }").queriedObjects().isEmpty());
    }

    @Test
    void sparqlSeesInferencesAndKeepsRows() {
        CoreFixture f = fixture();
        f.loadRobotics("map", "HERMIT", true);
        assertEquals(iris("kitchen"), f.ok("map", "QUERY SPARQL",
                "SELECT ?r WHERE { ?r a :OccupiedRoom }").queriedObjects());
        Response formatted = f.ok("map", "QUERY SPARQL FORMATTED",
                "SELECT ?a ?l WHERE { ?a :isIn ?l } ORDER BY ?a");
        assertEquals(List.of("a", "l", "", "a", "l"), formatted.sparqlQueriedObjects().stream()
                .map(Response.QueryItem::key).toList());
        assertEquals(iri("alice"), formatted.sparqlQueriedObjects().get(0).value());
        assertEquals(List.of("true"), f.ok("map", "QUERY SPARQL", "ASK { :kitchen a :Location }").queriedObjects());
        assertEquals(iris("kitchen"), f.ok("map", "QUERY SPARQL", "PREFIX r: <http://www.example.org/robotics#>",
                "SELECT ?r", "?r a r:OccupiedRoom").queriedObjects());
        Response malformed = f.run("map", "QUERY SPARQL", "SELECT ?r WHERE { ?r a }");
        assertFails(malformed, 208);
        assertTrue(malformed.errorDescription().contains("line"));
    }

    @Test
    void entityNamesCanBeShort() {
        ArmorCore core = new ArmorCore(new io.github.armor.core.api.CoreConfig(false, "HERMIT",
                List.of(CoreFixture.ONTOLOGIES), false, 1000, 0, 0, io.github.armor.core.api.CoreConfig.Durability.NONE));
        core.execute(Directive.of("c", "map", "LOAD", "FILE", "", CoreFixture.ONTOLOGIES.resolve("robotics.owl")
                .toString(), "", "false", "HERMIT", "true"));
        assertEquals(List.of("kitchen"), core.execute(Directive.of("c", "map", "QUERY", "IND", "CLASS",
                "OccupiedRoom")).queriedObjects());
    }
}
