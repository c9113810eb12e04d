// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLNamedIndividual;

/**
 * What the reasoner knows about the individuals at one moment: an immutable value, so that any
 * thread may read it while the next one is being computed.
 *
 * <p>Individuals get stable numbers; the types live in chunks of {@value #CHUNK} slots, and a new
 * state copies only the chunk table and the chunks it changes (copy-on-write), so a change of a
 * few individuals costs a few kilobytes whatever the size of the ABox. The numbering is shared by
 * every state of one reasoner and only grows; a state ignores numbers given after it was made.
 */
public final class InferredState {
    private static final int CHUNK_BITS = 10;
    private static final int CHUNK = 1 << CHUNK_BITS;

    /** One individual and its types; a null profile: its module is inconsistent, its types unknown. */
    private record Slot(OWLNamedIndividual individual, TypeProfile profile) {}

    private final Numbering numbering;
    private final Slot[][] chunks;
    private final int size;
    private final int individuals;
    private final boolean consistent;
    private final Set<OWLClass> classes;
    private final RealisationScope scope;

    private InferredState(Numbering numbering, Slot[][] chunks, int size, int individuals, boolean consistent,
                          Set<OWLClass> classes, RealisationScope scope) {
        this.numbering = numbering;
        this.chunks = chunks;
        this.size = size;
        this.individuals = individuals;
        this.consistent = consistent;
        this.classes = classes;
        this.scope = scope;
    }

    /** A state with no individual, to be filled through {@link #edit()}; null scope: every class is realised. */
    static InferredState empty(RealisationScope scope) {
        return new InferredState(new Numbering(), new Slot[0][], 0, 0, true, Set.of(), scope);
    }

    static InferredState empty() {
        return empty(null);
    }

    /** Whether the ontology was consistent: when not, no type is known. */
    public boolean consistent() {
        return consistent;
    }

    /** How many named individuals the ontology had. */
    public int individuals() {
        return individuals;
    }

    /**
     * Whether the class was in the ontology's signature and its instances are known (built-in
     * classes always are; over an upper ontology, only the classes realised: {@link RealisationScope}).
     */
    public boolean knows(OWLClass owlClass) {
        return owlClass.isBuiltIn() || classes.contains(owlClass) && (scope == null || scope.answers(owlClass));
    }

    /** Whether the class is in the ontology's signature, its instances known or not. */
    boolean inSignature(OWLClass owlClass) {
        return owlClass.isBuiltIn() || classes.contains(owlClass);
    }

    /** The classes realised with every change (every class when null). */
    RealisationScope scope() {
        return scope;
    }

    /** Whether the individual was in the ontology's signature. */
    public boolean knows(OWLNamedIndividual individual) {
        return slot(individual) != null;
    }

    /** The individual's types, or empty when it was unknown or its types were (inconsistency). */
    Optional<TypeProfile> types(OWLNamedIndividual individual) {
        Slot slot = slot(individual);
        return slot == null ? Optional.empty() : Optional.ofNullable(slot.profile());
    }

    /** The named individuals that are instances of the class. */
    public List<OWLNamedIndividual> instances(OWLClass owlClass) {
        List<OWLNamedIndividual> found = new ArrayList<>();
        Map<TypeProfile, Boolean> answered = new IdentityHashMap<>();
        TypeProfile last = null;
        boolean lastAnswer = false;
        for (Slot[] chunk : chunks) {
            if (chunk == null) {
                continue;
            }
            for (Slot slot : chunk) {
                if (slot == null || slot.profile() == null) {
                    continue;
                }
                TypeProfile profile = slot.profile();
                if (profile != last) {
                    last = profile;
                    lastAnswer = answered.computeIfAbsent(profile, p -> p.has(owlClass, false));
                }
                if (lastAnswer) {
                    found.add(slot.individual());
                }
            }
        }
        return found;
    }

    /** The named individuals the state knows. */
    List<OWLNamedIndividual> individualsList() {
        List<OWLNamedIndividual> found = new ArrayList<>(individuals);
        for (Slot[] chunk : chunks) {
            if (chunk != null) {
                for (Slot slot : chunk) {
                    if (slot != null) {
                        found.add(slot.individual());
                    }
                }
            }
        }
        return found;
    }

    /**
     * The classes of an individual, for a reader that has no reasoner (empty: unknown individual,
     * or only some of its classes are known: {@link #realisedClassesOf}).
     */
    public Optional<Set<OWLClass>> classesOf(OWLNamedIndividual individual, boolean direct) {
        return types(individual).filter(TypeProfile::complete).map(profile -> {
            Set<OWLClass> flat = new java.util.HashSet<>();
            (direct ? profile.direct() : profile.all()).forEach(flat::addAll);
            return flat;
        });
    }

    /**
     * What is known of an individual's classes without reasoning again: all of them, or over an
     * upper ontology those of the realised classes it belongs to (empty: unknown individual).
     */
    public Optional<Set<OWLClass>> realisedClassesOf(OWLNamedIndividual individual) {
        return types(individual).map(profile -> {
            Set<OWLClass> flat = new java.util.HashSet<>();
            profile.all().forEach(flat::addAll);
            return flat;
        });
    }

    private Slot slot(OWLNamedIndividual individual) {
        Integer number = numbering.numbers.get(individual);
        if (number == null || number >= size) {
            return null;
        }
        Slot[] chunk = chunks[number >>> CHUNK_BITS];
        return chunk == null ? null : chunk[number & (CHUNK - 1)];
    }

    Editor edit() {
        return new Editor(this);
    }

    /** Numbers for individuals, shared by the states of one reasoner; written by the writer only. */
    private static final class Numbering {
        final Map<OWLNamedIndividual, Integer> numbers = new ConcurrentHashMap<>();
        int next;

        int numberOf(OWLNamedIndividual individual) {
            Integer number = numbers.get(individual);
            if (number == null) {
                number = next++;
                numbers.put(individual, number);
            }
            return number;
        }
    }

    /** Makes the next state from this one, copying only what changes. Single use, writer thread only. */
    static final class Editor {
        private final InferredState base;
        private Slot[][] chunks;
        private final BitSet copied = new BitSet();
        private int individuals;
        private boolean consistent;
        private Set<OWLClass> classes;

        private Editor(InferredState base) {
            this.base = base;
            this.chunks = base.chunks;
            this.individuals = base.individuals;
            this.consistent = base.consistent;
            this.classes = base.classes;
        }

        /** The individual is in the ontology with these types (null: unknown, its module is inconsistent). */
        Editor put(OWLNamedIndividual individual, TypeProfile profile) {
            Slot[] chunk = writableChunk(base.numbering.numberOf(individual));
            int index = base.numbering.numbers.get(individual) & (CHUNK - 1);
            if (chunk[index] == null) {
                individuals++;
            }
            chunk[index] = new Slot(individual, profile);
            return this;
        }

        /** The individual left the ontology. */
        Editor remove(OWLNamedIndividual individual) {
            Integer number = base.numbering.numbers.get(individual);
            if (number == null || number >>> CHUNK_BITS >= chunks.length || chunks[number >>> CHUNK_BITS] == null) {
                return this;
            }
            Slot[] chunk = writableChunk(number);
            if (chunk[number & (CHUNK - 1)] != null) {
                individuals--;
                chunk[number & (CHUNK - 1)] = null;
            }
            return this;
        }

        Editor consistent(boolean value) {
            consistent = value;
            return this;
        }

        Editor classes(Set<OWLClass> value) {
            classes = Set.copyOf(value);
            return this;
        }

        Set<OWLClass> classes() {
            return classes;
        }

        InferredState done() {
            return new InferredState(base.numbering, chunks, base.numbering.next, individuals, consistent, classes,
                    base.scope);
        }

        private Slot[] writableChunk(int number) {
            int chunkIndex = number >>> CHUNK_BITS;
            if (chunks == base.chunks || chunkIndex >= chunks.length) {
                chunks = Arrays.copyOf(chunks, Math.max(chunks.length, chunkIndex + 1));
            }
            if (!copied.get(chunkIndex)) {
                Slot[] old = chunks[chunkIndex];
                chunks[chunkIndex] = old == null ? new Slot[CHUNK] : old.clone();
                copied.set(chunkIndex);
            }
            return chunks[chunkIndex];
        }
    }
}
