// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLNamedIndividual;

/** A published state never changes: the next one is built beside it, sharing what did not change. */
class InferredStateTest {
    private final OWLDataFactory factory = OWLManager.getOWLDataFactory();
    private final OWLClass robot = factory.getOWLClass(IRI.create("urn:test#Robot"));
    private final OWLClass room = factory.getOWLClass(IRI.create("urn:test#Room"));
    private final TypeProfile robotTypes = new TypeProfile(Set.of(Set.of(robot), Set.of(factory.getOWLThing())),
            Set.of(Set.of(robot)));
    private final TypeProfile roomTypes = new TypeProfile(Set.of(Set.of(room), Set.of(factory.getOWLThing())),
            Set.of(Set.of(room)));

    private OWLNamedIndividual individual(int number) {
        return factory.getOWLNamedIndividual(IRI.create("urn:test#i" + number));
    }

    @Test
    void editsMakeANewStateAndLeaveTheOldOneAsItWas() {
        InferredState.Editor first = InferredState.empty().edit().classes(Set.of(robot, room));
        // More than one chunk of slots, so that an edit copies some chunks and shares others.
        for (int i = 0; i < 3000; i++) {
            first.put(individual(i), i % 3 == 0 ? roomTypes : robotTypes);
        }
        InferredState before = first.done();
        InferredState after = before.edit().put(individual(0), robotTypes).remove(individual(1))
                .put(individual(5000), roomTypes).consistent(false).done();

        assertEquals(1000, before.instances(room).size());
        assertTrue(before.instances(room).contains(individual(0)));
        assertTrue(before.knows(individual(1)) && !before.knows(individual(5000)));
        assertTrue(before.consistent());
        assertEquals(3000, before.individuals());

        assertFalse(after.instances(room).contains(individual(0)));
        assertTrue(after.instances(room).contains(individual(5000)));
        assertFalse(after.knows(individual(1)));
        assertFalse(after.consistent());
        assertEquals(3000, after.individuals());
        assertEquals(List.of(individual(2999)), after.instances(robot).stream()
                .filter(i -> i.equals(individual(2999))).toList());
        assertEquals(Set.of(robot), after.classesOf(individual(2), true).orElseThrow());
    }
}
