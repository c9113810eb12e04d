// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.AboxModules.Module;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.reasoner.InferenceType;
import org.semanticweb.owlapi.reasoner.NodeSet;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.reasoner.ReasonerInterruptedException;
import org.semanticweb.owlapi.reasoner.impl.OWLClassNodeSet;

/**
 * Reasons on modules: the schema plus the modules' assertions in a fresh reasoner of the
 * reference's kind, which answers each member's types. Modules go together in batches (a
 * reasoner per module would start too often); a batch that is inconsistent is halved until the
 * inconsistent modules are found, since the others' types are still needed. A module shaped like
 * one reasoned on before takes its result ({@link ModuleShapes}): a new robot asserted a Robot
 * has the types every such robot has, a room with three robots those of every such room; and a
 * module is reasoned on with its twins collapsed ({@link ModuleTwins}): a room with three robots
 * of one kind as a room with one.
 */
final class ModuleRealiser {
    /** Individuals per batch: large enough to start few reasoners, small enough to bound memory. */
    static final int BATCH_INDIVIDUALS = 5000;

    /** A module reasoned on: consistent with these types, or inconsistent (no types). */
    record Realised(Module module, boolean consistent, Map<OWLNamedIndividual, TypeProfile> types) {}

    private final OWLReasonerFactory factory;
    private final OWLReasonerConfiguration configuration;
    private final List<OWLAxiom> schema;
    private final OWLOntologyManager scratch = OWLManager.createOWLOntologyManager();
    private final TypeProfile.Interner profiles = new TypeProfile.Interner();
    private final ModuleShapes shapes;
    // Over an upper ontology: the classes realised (null: every class), and the schema cut to what modules use.
    private final Set<OWLClass> tracked;
    private final SchemaSlices slices;
    private volatile OWLReasoner running;
    private volatile boolean interrupted;

    ModuleRealiser(OWLReasonerFactory factory, OWLReasonerConfiguration configuration, List<OWLAxiom> schema) {
        this(factory, configuration, schema, null, false);
    }

    /**
     * @param tracked the classes to realise (null: every class, with the most specific ones)
     * @param sliced  reason on the part of the schema the modules' assertions use ({@link SchemaSlices})
     */
    ModuleRealiser(OWLReasonerFactory factory, OWLReasonerConfiguration configuration, List<OWLAxiom> schema,
                   Set<OWLClass> tracked, boolean sliced) {
        this.factory = factory;
        this.configuration = configuration;
        this.schema = List.copyOf(schema);
        this.shapes = new ModuleShapes(scratch, this.schema);
        this.tracked = tracked == null ? null : Set.copyOf(tracked);
        this.slices = sliced ? new SchemaSlices(scratch, this.schema) : null;
    }

    /** Whether the schema alone is consistent (then so is an ontology without individuals). */
    boolean schemaConsistent() {
        return withReasoner(Set.of(), OWLReasoner::isConsistent);
    }

    /** Reasons on the modules; every module comes back once, consistent with types or inconsistent. */
    List<Realised> realise(List<Module> modules, Function<Module, Set<OWLAxiom>> axiomsOf) {
        List<Realised> done = new ArrayList<>();
        List<Pending> batch = new ArrayList<>();
        int individuals = 0;
        // A module shaped like one waiting to be reasoned on takes that one's result afterwards.
        Map<Set<OWLAxiom>, Module> firstOfShape = new HashMap<>();
        Map<Module, List<Module>> followers = new IdentityHashMap<>();
        Map<Module, ModuleShapes.Shape> shapeOf = new IdentityHashMap<>();
        for (Module module : modules) {
            Set<OWLAxiom> axioms = axiomsOf.apply(module);
            ModuleShapes.Shape shape = shapes.shapeOf(module, axioms);
            if (shape != null && shape.key() != null) {
                Realised known = shapes.lookup(module, shape);
                if (known != null) {
                    done.add(known);
                    continue;
                }
                shapeOf.put(module, shape);
                Module first = firstOfShape.putIfAbsent(shape.key(), module);
                if (first != null) {
                    followers.computeIfAbsent(first, k -> new ArrayList<>()).add(module);
                    continue;
                }
            }
            Pending pending = shape == null
                    ? new Pending(module, axioms, module.namedMembers().toList(), null)
                    : new Pending(module, shape.collapsed().axioms(), shape.collapsed().kept(), shape);
            batch.add(pending);
            individuals += pending.asked.size();
            if (individuals >= BATCH_INDIVIDUALS) {
                reason(batch, done);
                batch = new ArrayList<>();
                individuals = 0;
            }
        }
        if (!batch.isEmpty()) {
            reason(batch, done);
        }
        if (!followers.isEmpty()) {
            Map<Module, Realised> byModule = new IdentityHashMap<>();
            done.forEach(realised -> byModule.put(realised.module(), realised));
            followers.forEach((first, others) -> others.forEach(other -> done.add(shapes.transfer(
                    byModule.get(first), shapeOf.get(first), other, shapeOf.get(other)))));
        }
        return done;
    }

    /**
     * A module to reason on: the assertions the reasoner is given (its twins collapsed), the
     * members whose types it is asked, and the module's shape (null: not collapsed).
     */
    private record Pending(Module module, Set<OWLAxiom> axioms, List<OWLNamedIndividual> asked,
                           ModuleShapes.Shape shape) {
        Realised spread(Realised ofAsked) {
            return shape == null || !ofAsked.consistent() ? ofAsked
                    : new Realised(module, true, shape.collapsed().spread(ofAsked.types()));
        }
    }

    /** How many modules took the result of an earlier module of the same shape. */
    long reusedShapes() {
        return shapes.reused();
    }

    /** Forgets an interruption of an earlier update: call before each new one. */
    void prepare() {
        interrupted = false;
    }

    /** Stops the reasoning under way; the caller gets a {@link ReasonerInterruptedException}. */
    void interrupt() {
        interrupted = true;
        OWLReasoner current = running;
        if (current != null) {
            current.interrupt();
        }
    }

    private void reason(List<Pending> batch, List<Realised> done) {
        checkInterrupted();
        Set<OWLAxiom> union = new LinkedHashSet<>();
        batch.forEach(pending -> union.addAll(pending.axioms));
        List<Realised> found = withReasoner(union, reasoner -> {
            if (!reasoner.isConsistent()) {
                return null;
            }
            if (tracked != null) {
                return realiseTracked(reasoner, batch);
            }
            if (reasoner.getPrecomputableInferenceTypes().contains(InferenceType.CLASS_ASSERTIONS)) {
                reasoner.precomputeInferences(InferenceType.CLASS_ASSERTIONS);
            }
            // All types are the most specific ones and everything above them: asked once per kind of individual.
            Map<NodeSet<OWLClass>, TypeProfile> byDirectTypes = new HashMap<>();
            List<Realised> realised = new ArrayList<>();
            for (Pending pending : batch) {
                Map<OWLNamedIndividual, TypeProfile> types = new LinkedHashMap<>();
                pending.asked.forEach(member -> types.put(member, byDirectTypes.computeIfAbsent(
                        reasoner.getTypes(member, true), direct -> profiles.intern(
                                TypeProfile.of(withSuperClasses(reasoner, direct), direct)))));
                realised.add(new Realised(pending.module, true, types));
            }
            return realised;
        });
        if (found != null) {
            for (int i = 0; i < batch.size(); i++) {
                Realised all = batch.get(i).spread(found.get(i));
                remember(batch.get(i).shape, all);
                done.add(all);
            }
        } else if (batch.size() == 1) {
            Realised inconsistent = new Realised(batch.get(0).module, false, Map.of());
            remember(batch.get(0).shape, inconsistent);
            done.add(inconsistent);
        } else {
            int half = batch.size() / 2;
            reason(batch.subList(0, half), done);
            reason(batch.subList(half, batch.size()), done);
        }
    }

    /**
     * The realised classes each member belongs to: one instance question per class, which needs
     * no classification of the schema (SOMA's takes minutes), instead of every type of every member.
     */
    private List<Realised> realiseTracked(OWLReasoner reasoner, List<Pending> batch) {
        Map<OWLClass, Set<OWLNamedIndividual>> instances = new HashMap<>();
        for (OWLClass owlClass : tracked) {
            instances.put(owlClass, reasoner.getInstances(owlClass, false).entities()
                    .collect(java.util.stream.Collectors.toSet()));
        }
        OWLClass thing = scratch.getOWLDataFactory().getOWLThing();
        List<Realised> realised = new ArrayList<>();
        for (Pending pending : batch) {
            Map<OWLNamedIndividual, TypeProfile> types = new LinkedHashMap<>();
            pending.asked.forEach(member -> {
                Set<OWLClass> memberOf = new java.util.HashSet<>();
                instances.forEach((owlClass, members) -> {
                    if (members.contains(member)) {
                        memberOf.add(owlClass);
                    }
                });
                types.put(member, profiles.intern(TypeProfile.partial(memberOf, thing)));
            });
            realised.add(new Realised(pending.module, true, types));
        }
        return realised;
    }

    private static NodeSet<OWLClass> withSuperClasses(OWLReasoner reasoner, NodeSet<OWLClass> direct) {
        OWLClassNodeSet all = new OWLClassNodeSet();
        // Every individual is a Thing; JFact leaves it out for some (individuals named in the schema).
        all.addNode(reasoner.getTopClassNode());
        direct.forEach(node -> {
            all.addNode(node);
            // JFact answers an empty node for an individual whose only type is owl:Thing.
            node.entities().findFirst().ifPresent(representative ->
                    all.addAllNodes(reasoner.getSuperClasses(representative, false).nodes()));
        });
        return all;
    }

    private <T> T withReasoner(Set<OWLAxiom> abox, Function<OWLReasoner, T> question) {
        OWLOntology ontology;
        try {
            ontology = scratch.createOntology();
        } catch (OWLOntologyCreationException e) {
            throw new IllegalStateException("could not create a scratch ontology", e);
        }
        OWLReasoner reasoner = null;
        try {
            scratch.addAxioms(ontology, schemaFor(abox).stream());
            scratch.addAxioms(ontology, abox.stream());
            reasoner = factory.createReasoner(ontology, configuration);
            running = reasoner;
            checkInterrupted();
            return question.apply(reasoner);
        } finally {
            running = null;
            if (reasoner != null) {
                reasoner.dispose();
            }
            scratch.removeOntology(ontology);
        }
    }

    /** The schema a reasoner on these assertions needs: all of it, or the slice their signature uses. */
    private List<OWLAxiom> schemaFor(Set<OWLAxiom> abox) {
        if (slices == null) {
            return schema;
        }
        Set<org.semanticweb.owlapi.model.OWLEntity> signature = new java.util.HashSet<>();
        abox.forEach(axiom -> axiom.signature().forEach(signature::add));
        if (tracked != null) {
            signature.addAll(tracked);
        }
        return slices.sliceFor(signature);
    }

    private void checkInterrupted() {
        if (interrupted || Thread.currentThread().isInterrupted()) {
            throw new ReasonerInterruptedException("interrupted between modules");
        }
    }

    private void remember(ModuleShapes.Shape shape, Realised realised) {
        if (shape != null) {
            shapes.remember(shape, realised);
        }
    }
}
