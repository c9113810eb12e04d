// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.AboxModules.Module;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassAssertionAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.OWLPropertyAssertionAxiom;
import org.semanticweb.owlapi.util.OWLObjectDuplicator;

/**
 * Modules that are the same up to the names of their individuals: a room with three robots in it
 * has the types every room with three robots has, so it is reasoned on once.
 *
 * <p>A module's shape is its assertions with its individuals renamed to placeholders, in an
 * order found from what each individual's assertions say. Two modules with equal shapes are
 * images of each other under a renaming of individuals, and OWL semantics does not depend on
 * names, so the reasoner's answer for one, renamed, is its answer for the other. The order only
 * decides how often shapes match: a tie broken differently gives a different shape (one more
 * module reasoned on), never a wrong answer.
 */
final class ModuleShapes {
    /** Modules larger than this are not compared (rarely repeated, and costly to rename). */
    static final int LARGEST = 64;
    private static final int KEPT = 4096;
    private static final String PLACEHOLDER = "urn:armor:reasoning#individual";

    /** A module's shape, and its members in placeholder order. */
    record Shape(Set<OWLAxiom> key, List<OWLNamedIndividual> order) {}

    /** What reasoning on a shape gave: consistency, and the types by placeholder. */
    private record Outcome(boolean consistent, List<TypeProfile> types) {}

    private final OWLOntologyManager manager;
    private final Map<Set<OWLAxiom>, Outcome> known = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Set<OWLAxiom>, Outcome> eldest) {
            return size() > KEPT;
        }
    };

    private long reused;

    ModuleShapes(OWLOntologyManager manager) {
        this.manager = manager;
    }

    /** The shape of a module with these assertions, or null when it is not compared (hub, size, anonymous individuals). */
    Shape shapeOf(Module module, Set<OWLAxiom> axioms) {
        // The hub's individuals are named in the schema: renaming them would change what it says.
        if (module.hub || module.members.size() > LARGEST || module.members.stream().anyMatch(OWLIndividual::isAnonymous)) {
            return null;
        }
        Map<OWLIndividual, List<Long>> roles = new HashMap<>();
        for (OWLAxiom axiom : axioms) {
            List<OWLIndividual> about = AboxLinks.individualsOf(axiom).toList();
            long what = describe(axiom);
            for (int position = 0; position < about.size(); position++) {
                roles.computeIfAbsent(about.get(position), k -> new ArrayList<>()).add(what * 8 + position);
            }
        }
        Map<OWLNamedIndividual, String> signature = new HashMap<>();
        module.namedMembers().forEach(member -> {
            List<Long> own = roles.getOrDefault(member, new ArrayList<>());
            own.sort(null);
            signature.put(member, own.toString());
        });
        List<OWLNamedIndividual> order = new ArrayList<>(signature.keySet());
        order.sort(Comparator.comparing((OWLNamedIndividual member) -> signature.get(member))
                .thenComparing(member -> member.getIRI().toString()));
        Map<OWLEntity, IRI> renaming = new HashMap<>();
        for (int i = 0; i < order.size(); i++) {
            renaming.put(order.get(i), IRI.create(PLACEHOLDER + i));
        }
        OWLObjectDuplicator renamer = new OWLObjectDuplicator(renaming, manager);
        Set<OWLAxiom> key = new LinkedHashSet<>();
        for (OWLAxiom axiom : axioms) {
            key.add(renamer.duplicateObject(axiom));
        }
        return new Shape(Set.copyOf(key), List.copyOf(order));
    }

    /** The result for a module whose shape was reasoned on before, or null. */
    ModuleRealiser.Realised lookup(Module module, Shape shape) {
        Outcome outcome = known.get(shape.key());
        if (outcome == null) {
            return null;
        }
        reused++;
        if (!outcome.consistent()) {
            return new ModuleRealiser.Realised(module, false, Map.of());
        }
        Map<OWLNamedIndividual, TypeProfile> types = new LinkedHashMap<>();
        for (int i = 0; i < shape.order().size(); i++) {
            types.put(shape.order().get(i), outcome.types().get(i));
        }
        return new ModuleRealiser.Realised(module, true, types);
    }

    /** How many modules took the result of an earlier one (tests check that this path runs). */
    long reused() {
        return reused;
    }

    /** The result of module {@code from} (shape {@code fromShape}) for module {@code to} of the same shape. */
    ModuleRealiser.Realised transfer(ModuleRealiser.Realised from, Shape fromShape, Module to, Shape toShape) {
        reused++;
        if (!from.consistent()) {
            return new ModuleRealiser.Realised(to, false, Map.of());
        }
        Map<OWLNamedIndividual, TypeProfile> types = new LinkedHashMap<>();
        for (int i = 0; i < toShape.order().size(); i++) {
            types.put(toShape.order().get(i), from.types().get(fromShape.order().get(i)));
        }
        return new ModuleRealiser.Realised(to, true, types);
    }

    void remember(Shape shape, ModuleRealiser.Realised realised) {
        List<TypeProfile> types = realised.consistent()
                ? shape.order().stream().map(realised.types()::get).toList() : List.of();
        known.put(shape.key(), new Outcome(realised.consistent(), types));
    }

    /**
     * What an assertion says apart from its individuals, as a number for ordering them (content
     * hash codes: equal assertions up to individuals give equal numbers; a collision only costs
     * a missed match).
     */
    private static long describe(OWLAxiom axiom) {
        long kind = axiom.getAxiomType().getIndex();
        if (axiom instanceof OWLClassAssertionAxiom assertion) {
            return kind << 32 | assertion.getClassExpression().hashCode() & 0xffffffffL;
        }
        if (axiom instanceof OWLPropertyAssertionAxiom<?, ?> assertion) {
            int value = assertion.getObject() instanceof OWLIndividual ? 0 : assertion.getObject().hashCode();
            return kind << 32 | (assertion.getProperty().hashCode() * 31 + value) & 0xffffffffL;
        }
        return kind << 32;
    }
}
