// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.assertFails;
import static io.github.armor.core.CoreFixture.iris;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandSpec;
import io.github.armor.core.command.CommandTable;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 18: unmodified ROS 1 client code. ROS 1 ARMOR read only the arguments a command named,
 * so old clients send dummies ({@code REASON ['']}), flags as Python prints them ({@code True})
 * and type words in any case ({@code Long}); every command ARMOR had answers them as ARMOR did.
 */
class Ros1IdiomsTest {
    /** Every fixed-argument combination of ARMOR's dispatch table (ARMORCommandExecutive), by our key. */
    private static final Set<String> ARMOR_FIXED_ARITY = Set.of(
            "LOAD FILE -", "LOAD FILE MOUNTED", "LOAD WEB -", "LOAD WEB MOUNTED", "SAVE - -", "SAVE INFERENCE -",
            "DROP - -", "MOUNT - -", "UNMOUNT - -", "GET ALL REFS", "GET REF CLIENT", "LOG SCREEN ON",
            "LOG SCREEN OFF", "LOG FILE ON", "LOG FILE OFF", "APPLY - -", "REASON - -",
            "QUERY IND -", "QUERY IND CLASS", "QUERY DATAPROP IND", "QUERY OBJECTPROP IND", "QUERY CLASS IND",
            "QUERY CLASS CLASS", "QUERY CLASS RESTRICTIONS", "QUERY IND DATAPROP", "QUERY IND OBJECTPROP",
            "ADD IND -", "ADD CLASS -", "ADD IND CLASS", "ADD CLASS CLASS", "ADD DATAPROP IND", "ADD OBJECTPROP IND",
            "ADD CARDINALITY MIN", "DISJOINT IND CLASS", "DISJOINT CLASS CLASS", "MAKE EQUIVALENT CLASS",
            "REMOVE IND -", "REMOVE CLASS -", "REMOVE IND CLASS", "REMOVE CLASS CLASS", "REMOVE DATAPROP IND",
            "REMOVE OBJECTPROP IND", "REPLACE DATAPROP IND", "REPLACE OBJECTPROP IND", "RENAME IND -",
            "RENAME CLASS -", "RENAME DATAPROP -", "RENAME OBJECTPROP -");

    @TempDir
    Path scratch;

    @Test
    void exactlyTheCommandsArmorHadIgnoreEmptySurplusArguments() {
        Set<String> ignoring = CommandTable.standard().catalogue().stream().filter(CommandSpec::emptySurplusIgnored)
                .map(CommandSpec::key).collect(Collectors.toCollection(TreeSet::new));
        assertEquals(new TreeSet<>(ARMOR_FIXED_ARITY), ignoring);
    }

    /** One valid call of each command ARMOR had, on robotics.owl loaded as "map": words, then arguments. */
    static Stream<Arguments> armorCalls() {
        String robotics = CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString();
        return Stream.of(
                call("LOAD FILE", robotics, "http://www.example.org/robotics", "false", "PELLET", "false"),
                call("LOAD FILE MOUNTED", robotics, "", "False", "HERMIT", "True"),
                call("LOAD WEB", "https://example.org/onto.owl", "", "false", "", "false"),
                call("LOAD WEB MOUNTED", "https://example.org/onto.owl", "", "false", "", "false"),
                call("SAVE", "@scratch/saved.owl"), call("SAVE INFERENCE", "@scratch/inferred.owl"),
                call("DROP"), call("MOUNT"), call("UNMOUNT"), call("GET ALL REFS"), call("GET REF CLIENT", "map"),
                call("LOG SCREEN ON"), call("LOG SCREEN OFF"), call("LOG FILE ON", "@scratch/armor.log"),
                call("LOG FILE OFF"), call("APPLY"), call("REASON"),
                call("QUERY IND", "robot1"), call("QUERY IND CLASS", "OccupiedRoom"),
                call("QUERY DATAPROP IND", "batteryLevel", "robot1"), call("QUERY OBJECTPROP IND", "isIn", "robot1"),
                call("QUERY CLASS IND", "robot1", "true"), call("QUERY CLASS CLASS", "Location"),
                call("QUERY CLASS RESTRICTIONS", "OccupiedRoom"), call("QUERY IND DATAPROP", "robot1"),
                call("QUERY IND OBJECTPROP", "robot1"), call("ADD IND", "box1"), call("ADD CLASS", "Charger"),
                call("ADD IND CLASS", "bob", "Person"), call("ADD CLASS CLASS", "Charger", "Location"),
                call("ADD DATAPROP IND", "batteryLevel", "robot1", "INT", "75"),
                call("ADD OBJECTPROP IND", "isIn", "alice", "bedroom"),
                call("ADD CARDINALITY MIN", "Robot", "isIn", "1", "Location"), call("DISJOINT IND CLASS", "Room"),
                call("DISJOINT CLASS CLASS", "Agent"), call("MAKE EQUIVALENT CLASS", "Corridor"),
                call("REMOVE IND", "alice"), call("REMOVE CLASS", "Person"),
                call("REMOVE IND CLASS", "alice", "Person"),
                call("REMOVE CLASS CLASS", "Robot", "Agent"),
                call("REMOVE DATAPROP IND", "batteryLevel", "robot1", "INTEGER", "80"),
                call("REMOVE OBJECTPROP IND", "isIn", "robot1", "kitchen"),
                call("REPLACE DATAPROP IND", "batteryLevel", "robot1", "INT", "60", "80"),
                call("REPLACE OBJECTPROP IND", "isIn", "robot1", "bedroom", "kitchen"),
                call("RENAME IND", "robot1", "turtlebot"), call("RENAME CLASS", "Person", "Human"),
                call("RENAME DATAPROP", "batteryLevel", "charge"), call("RENAME OBJECTPROP", "isIn", "locatedIn"));
    }

    private static Arguments call(String words, String... args) {
        return Arguments.of(words, List.of(args));
    }

    @Test
    void everyCommandArmorHadIsCalledBelow() {
        Set<String> called = armorCalls().map(a -> key((String) a.get()[0])).collect(Collectors.toSet());
        assertEquals(ARMOR_FIXED_ARITY, called);
    }

    /** ARMOR's idiom (a dummy '' or two after the arguments) answers and changes exactly what the call without does. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("armorCalls")
    void emptySurplusArgumentsAnswerAsTheCallWithout(String words, List<String> args) throws IOException {
        Outcome plain = outcome(words, args, "plain");
        for (List<String> dummies : List.of(List.of(""), List.of("", ""))) {
            List<String> withDummies = new ArrayList<>(args);
            withDummies.addAll(dummies);
            Outcome idiom = outcome(words, withDummies, "idiom" + dummies.size());
            assertEquals(plain.answer(), idiom.answer(), words + " " + withDummies);
            assertEquals(plain.state(), idiom.state(), words + " " + withDummies + " changed something else");
        }
    }

    /** A surplus argument that says something is still refused, and changes nothing. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("armorCalls")
    void surplusArgumentsThatAreNotEmptyAreRefused(String words, List<String> args) throws IOException {
        Outcome untouched = outcome("GET ALL REFS", List.of(), "untouched");
        List<String> withSurplus = new ArrayList<>(args);
        withSurplus.addAll(List.of("", "kitchen"));
        CoreFixture f = loaded("surplus");
        Response refused = f.run("map", words, resolve(withSurplus, "surplus"));
        assertFails(refused, 207);
        assertTrue(refused.errorDescription().contains("got " + withSurplus.size()), refused.errorDescription());
        assertEquals(untouched.state(), state(f, "surplus"));
    }

    /** The field case: buffered manipulation and a buffered reasoner, REASON sent with args ['']. */
    @Test
    void reasonWithADummyArgumentAppliesTheBufferAndReasons() {
        CoreFixture f = new CoreFixture(scratch);
        f.ok("map", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(),
                "http://www.example.org/robotics", "True", "PELLET", "True");
        f.ok("map", "ADD IND CLASS", "bob", "Person");
        f.ok("map", "ADD OBJECTPROP IND", "isIn", "bob", "bedroom");
        assertEquals(iris("kitchen"), f.ok("map", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        f.ok("map", "REASON", "");
        assertEquals(iris("bedroom", "kitchen"), f.ok("map", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        f.ok("map", "ADD IND CLASS", "carl", "Person");
        f.ok("map", "APPLY", "");
        assertEquals(iris("alice", "bob", "carl"), f.ok("map", "QUERY IND CLASS", "Person").queriedObjects());
    }

    /** Flags as Python's str() writes them, or left empty (ARMOR's Boolean.valueOf read '' as false). */
    @ParameterizedTest
    @ValueSource(strings = {"True", "true", "TRUE", "False", "false", ""})
    void flagsInAnyCaseOrEmptyAreRead(String flag) {
        CoreFixture f = new CoreFixture(scratch);
        f.ok("map", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "", flag, "", flag);
        f.ok("map", "ADD IND CLASS", "bob", "Person");
        boolean buffered = flag.equalsIgnoreCase("true");
        List<String> people = f.ok("map", "QUERY IND CLASS", "Person").queriedObjects();
        assertEquals(buffered ? iris("alice") : iris("alice", "bob"), people);
        List<String> mostSpecific = f.ok("map", "QUERY CLASS IND", "robot1", "true").queriedObjects();
        List<String> all = f.ok("map", "QUERY CLASS IND", "robot1", "false").queriedObjects();
        assertTrue(all.containsAll(mostSpecific) && all.size() > mostSpecific.size(), all + " " + mostSpecific);
        assertEquals(buffered ? mostSpecific : all, f.ok("map", "QUERY CLASS IND", "robot1", flag).queriedObjects());
        assertFails(f.run("other", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(), "",
                "yes", "", "false"), 207);
    }

    @Test
    void typeWordsInAnyCaseAndPythonBooleans() {
        CoreFixture f = new CoreFixture(scratch);
        f.loadRobotics("map", "PELLET", false);
        for (String type : List.of("Long", "long", "LONG")) {
            f.ok("map", "REPLACE DATAPROP IND", "visitedAt", "bedroom", type, "17", "1700000000");
            assertEquals(List.of("\"17\"^^xsd:long"), f.ok("map", "QUERY DATAPROP IND", "visitedAt", "bedroom")
                    .queriedObjects());
            f.ok("map", "REPLACE DATAPROP IND", "visitedAt", "bedroom", type, "1700000000", "17");
        }
        for (String type : List.of("Int", "int", "Integer", "integer")) {
            f.ok("map", "REPLACE DATAPROP IND", "batteryLevel", "robot1", type, "60", "80");
            assertEquals(List.of("\"60\"^^xsd:integer"), f.ok("map", "QUERY DATAPROP IND", "batteryLevel", "robot1")
                    .queriedObjects());
            f.ok("map", "REPLACE DATAPROP IND", "batteryLevel", "robot1", type, "80", "60");
        }
        f.ok("map", "ADD DATAPROP IND", "charging", "robot1", "Boolean", "True");
        f.ok("map", "ADD DATAPROP IND", "docked", "robot1", "bool", "FALSE");
        assertEquals(List.of("\"true\"^^xsd:boolean"), f.ok("map", "QUERY DATAPROP IND", "charging", "robot1")
                .queriedObjects());
        assertEquals(List.of("\"false\"^^xsd:boolean"), f.ok("map", "QUERY DATAPROP IND", "docked", "robot1")
                .queriedObjects());
        f.ok("map", "REMOVE DATAPROP IND", "charging", "robot1", "BOOL", "true");
        assertEquals(List.of(), f.ok("map", "QUERY DATAPROP IND", "charging", "robot1").queriedObjects());
        assertFails(f.run("map", "ADD DATAPROP IND", "docked", "robot1", "bool", "yes"), 101);
    }

    /** armor_api documented ARMOR's reasoner names PELLET, HERMIT, FACT and SNOROCKET, in any case. */
    @Test
    void armorsReasonerNamesLoad() {
        CoreFixture f = new CoreFixture(scratch);
        String robotics = CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString();
        for (String name : List.of("FACT", "fact", "Pellet", "hermit")) {
            f.ok(name, "LOAD FILE", robotics, "", "false", name, "false");
            // Needs the inverse of isIn: complete reasoners find it.
            assertEquals(iris("kitchen"), f.ok(name, "QUERY IND CLASS", "OccupiedRoom").queriedObjects(), name);
        }
        f.ok("snorocket", "LOAD FILE", robotics, "", "false", "SNOROCKET", "false");
        // ELK, an OWL 2 EL classifier as Snorocket was, does not use the inverse.
        assertEquals(List.of(), f.ok("snorocket", "QUERY IND CLASS", "OccupiedRoom").queriedObjects());
        assertEquals(iris("robot1"), f.ok("snorocket", "QUERY IND CLASS", "RobotInRoom").queriedObjects());
    }

    /** A field idiom ARMOR executed wrongly: a data value sent to REPLACE OBJECTPROP IND with a type word. */
    @Test
    void aTypeWordSentToAnObjectPropertyCommandIsRefused() throws IOException {
        CoreFixture f = loaded("typo");
        String before = state(f, "typo");
        assertFails(f.run("map", "REPLACE OBJECTPROP IND", "visitedAt", "bedroom", "Long", "5", "1700000000"), 207);
        assertEquals(before, state(f, "typo"));
    }

    private record Outcome(String answer, String state) {}

    /** A fresh core with robotics.owl as "map" (Pellet) and the client "test" mounted, as a setup for words. */
    private CoreFixture loaded(String tag) {
        CoreFixture f = new CoreFixture(scratch);
        f.ok("map", "LOAD FILE", CoreFixture.ONTOLOGIES.resolve("robotics.owl").toString(),
                "http://www.example.org/robotics", "false", "PELLET", "false");
        f.ok("map", "MOUNT");
        return f;
    }

    private Outcome outcome(String words, List<String> args, String tag) throws IOException {
        CoreFixture f = loaded(tag);
        Response response = f.run(key(words).startsWith("LOAD") ? "other" : "map", words, resolve(args, tag));
        String answer = response.success() + " " + response.exitCode() + " " + response.queriedObjects() + " "
                + response.sparqlQueriedObjects() + " " + response.isConsistent();
        return new Outcome(answer, state(f, tag));
    }

    /** What a core holds: its references, their mount holders, and the map's axioms. */
    private String state(CoreFixture f, String tag) throws IOException {
        StringBuilder text = new StringBuilder(f.ok("", "GET ALL REFS").queriedObjects().toString());
        for (String reference : f.ok("", "GET ALL REFS").queriedObjects()) {
            text.append(reference).append(f.ok("", "GET REF CLIENT", reference).queriedObjects());
        }
        if (f.ok("", "GET ALL REFS").queriedObjects().contains("map")) {
            Path saved = scratch.resolve("state-" + tag + ".ofn");
            f.ok("map", "SAVE", saved.toString(), "functional");
            text.append(Files.readString(saved));
        }
        return text.toString();
    }

    private String[] resolve(List<String> args, String tag) {
        return args.stream().map(a -> a.startsWith("@scratch/") ? scratch.resolve(tag + "-" + a.substring(9)).toString()
                : a).toArray(String[]::new);
    }

    private static String key(String words) {
        List<String> parts = new ArrayList<>(List.of(words.split(" ")));
        while (parts.size() < 3) {
            parts.add("-");
        }
        return String.join(" ", parts);
    }
}
