// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.view;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reasoning.InferredState;
import io.github.armor.core.reasoning.ModularReasoner;
import io.github.armor.core.reasoning.PublishedStates.Published;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.reference.ReferenceRegistry;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.reasoner.OWLReasoner;

/**
 * How views read a reference: under its lock with the directives' lock wait (lock_wait_ms), and
 * through its reasoner's time limit, as any directive. A view that visits many entities does so in
 * slices, releasing the reference in between: a slice ends after {@link #SLICE_NANOS}, or as soon
 * as a directive waits for the reference. Its lock is fair, so the directives of ROS clients that
 * queued meanwhile run first: they wait for one entity's worth of a view, never for the whole.
 */
final class ViewReads {
    static final long SLICE_NANOS = 20_000_000L;

    private final ReferenceRegistry references;
    private final long lockWaitMs;

    ViewReads(ReferenceRegistry references, long lockWaitMs) {
        this.references = references;
        this.lockWaitMs = lockWaitMs;
    }

    Reference reference(String name) {
        return references.get(name);
    }

    ReferenceRegistry references() {
        return references;
    }

    /**
     * What a view shows of a reference that publishes its reasoned state (a reference reasoned on
     * in modules): that state, read without the reference's lock, beside the ontology's asserted
     * axioms, which its manager lets any thread read while a writer changes it (the writer
     * takes the ontology's own write lock only to apply a change). Open pages then never make a
     * robot's directive wait, nor wake a reasoner. Empty when there is no such state: the view
     * reads the reference as a directive does.
     */
    Optional<Published> offLock(Reference reference) {
        Optional<Published> published = reference.publishedState();
        published.ifPresent(state -> checkStillLoaded(reference));
        return published;
    }

    /**
     * An individual's most specific types as a published state knows them: all of them when its
     * module was realised against every class, else the realised classes it belongs to (over an
     * upper ontology).
     */
    static Set<OWLClass> directTypes(InferredState state, OWLNamedIndividual individual) {
        Set<OWLClass> types = new HashSet<>(state.classesOf(individual, true)
                .or(() -> state.realisedClassesOf(individual)).orElse(Set.of()));
        types.removeIf(OWLClass::isOWLThing);
        return types;
    }

    /** Runs {@code work} holding the reference, as one directive would. */
    <T> T whole(Reference reference, Function<Reference, T> work) {
        return reference.lockedForView(lockWaitMs, r -> {
            checkStillLoaded(r);
            return work.apply(r);
        });
    }

    /** Runs {@code work} on every item, holding the reference for slices of at most {@link #SLICE_NANOS}. */
    <T> void inSlices(Reference reference, List<T> items, Consumer<T> work) {
        Iterator<T> remaining = items.iterator();
        inSlices(reference, () -> {
            if (!remaining.hasNext()) {
                return false;
            }
            work.accept(remaining.next());
            return remaining.hasNext();
        });
    }

    /**
     * Calls {@code step} until it answers that no work is left, holding the reference for slices
     * of at most {@link #SLICE_NANOS}, each ended early by a directive waiting (each slice does at
     * least one step).
     */
    void inSlices(Reference reference, BooleanSupplier step) {
        boolean more = true;
        while (more) {
            more = reference.lockedForView(lockWaitMs, r -> {
                checkStillLoaded(r);
                long deadline = System.nanoTime() + SLICE_NANOS;
                boolean left;
                do {
                    left = step.getAsBoolean();
                } while (left && System.nanoTime() < deadline && !r.othersWaiting());
                return left;
            });
        }
    }

    /**
     * The reasoner's answer, or none where it has none to give: the reference is inconsistent, or
     * its reasoner cannot answer this kind of question (ELK and property values), or it failed on
     * this entity (a buffered reasoner that has not seen it yet). A time limit overrun is an error.
     * The caller holds the reference.
     */
    static <T> Optional<T> inferred(Reference reference, Function<OWLReasoner, T> question) {
        if (!reference.isConsistent()) {
            return Optional.empty();
        }
        try {
            OWLReasoner reasoner = reference.reasonerForQuery();
            return Optional.ofNullable(reference.guardReasoner(() -> question.apply(reasoner)));
        } catch (ArmorException e) {
            if (e.exitCode() == ExitCode.NOT_SUPPORTED || e.exitCode() == ExitCode.INCONSISTENT
                    || e.exitCode() == ExitCode.REASONER_FAILED) {
                return Optional.empty();
            }
            throw e;
        }
    }

    /**
     * An individual's most specific inferred types: its direct types, less any that is a
     * superclass of another of them (Openllet, realising incrementally, can answer a type
     * together with its own subclass). Empty when the reasoner has no answer. The caller holds
     * the reference.
     */
    static Set<OWLClass> directTypes(Reference reference, OWLNamedIndividual individual) {
        return inferred(reference, reasoner -> {
            Set<OWLClass> direct = reasoner.getTypes(individual, true).entities().filter(c -> !c.isOWLThing())
                    .collect(Collectors.toCollection(HashSet::new));
            if (reasoner instanceof ModularReasoner) {
                // Its direct types come from a fresh reasoning of the individual's module, never
                // from incremental realisation; and a superclass question would wake its reasoner
                // on the whole ontology, seconds on a large one after every change.
                return direct;
            }
            Set<OWLClass> implied = new HashSet<>();
            for (OWLClass type : direct) {
                reasoner.getSuperClasses(type, false).entities().forEach(implied::add);
            }
            direct.removeAll(implied);
            return direct;
        }).orElse(Set.of());
    }

    private void checkStillLoaded(Reference reference) {
        if (references.find(reference.name()).orElse(null) != reference) {
            throw new ArmorException(ExitCode.UNKNOWN_REFERENCE, "reference '" + reference.name()
                    + "' was dropped while the view was being read");
        }
    }
}
