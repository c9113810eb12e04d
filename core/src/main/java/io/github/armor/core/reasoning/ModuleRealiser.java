// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.AboxModules.Module;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
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
import org.semanticweb.owlapi.util.OWLObjectDuplicator;

/**
 * Reasons on modules: the schema plus the modules' assertions in a fresh reasoner of the
 * reference's kind, which answers each member's types. Modules go together in batches (a
 * reasoner per module would start too often); a batch that is inconsistent is halved until the
 * inconsistent modules are found, since the others' types are still needed. A module of one
 * individual is looked up first by its shape (its assertions with the individual renamed): a new
 * robot asserted a Robot has the types every such robot has.
 */
final class ModuleRealiser {
    /** Individuals per batch: large enough to start few reasoners, small enough to bound memory. */
    static final int BATCH_INDIVIDUALS = 5000;
    private static final int SHAPES_KEPT = 4096;
    private static final IRI PLACEHOLDER = IRI.create("urn:armor:reasoning#individual");

    /** A module reasoned on: consistent with these types, or inconsistent (no types). */
    record Realised(Module module, boolean consistent, Map<OWLNamedIndividual, TypeProfile> types) {}

    private record Shape(boolean consistent, TypeProfile types) {}

    private final OWLReasonerFactory factory;
    private final OWLReasonerConfiguration configuration;
    private final List<OWLAxiom> schema;
    private final OWLOntologyManager scratch = OWLManager.createOWLOntologyManager();
    private final TypeProfile.Interner profiles = new TypeProfile.Interner();
    private final Map<Set<OWLAxiom>, Shape> shapes = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Set<OWLAxiom>, Shape> eldest) {
            return size() > SHAPES_KEPT;
        }
    };
    private volatile OWLReasoner running;
    private volatile boolean interrupted;

    ModuleRealiser(OWLReasonerFactory factory, OWLReasonerConfiguration configuration, List<OWLAxiom> schema) {
        this.factory = factory;
        this.configuration = configuration;
        this.schema = List.copyOf(schema);
    }

    /** Whether the schema alone is consistent (then so is an ontology without individuals). */
    boolean schemaConsistent() {
        return withReasoner(Set.of(), OWLReasoner::isConsistent);
    }

    /** Reasons on the modules; every module comes back once, consistent with types or inconsistent. */
    List<Realised> realise(List<Module> modules, Function<Module, Set<OWLAxiom>> axiomsOf) {
        List<Realised> done = new ArrayList<>();
        List<Module> batch = new ArrayList<>();
        List<Set<OWLAxiom>> batchAxioms = new ArrayList<>();
        int batchIndividuals = 0;
        for (Module module : modules) {
            Set<OWLAxiom> axioms = axiomsOf.apply(module);
            Realised known = byShape(module, axioms);
            if (known != null) {
                done.add(known);
                continue;
            }
            batch.add(module);
            batchAxioms.add(axioms);
            batchIndividuals += module.members.size();
            if (batchIndividuals >= BATCH_INDIVIDUALS) {
                reason(batch, batchAxioms, done);
                batch = new ArrayList<>();
                batchAxioms = new ArrayList<>();
                batchIndividuals = 0;
            }
        }
        if (!batch.isEmpty()) {
            reason(batch, batchAxioms, done);
        }
        return done;
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

    private void reason(List<Module> batch, List<Set<OWLAxiom>> axioms, List<Realised> done) {
        checkInterrupted();
        Set<OWLAxiom> union = new LinkedHashSet<>();
        axioms.forEach(union::addAll);
        List<Realised> found = withReasoner(union, reasoner -> {
            if (!reasoner.isConsistent()) {
                return null;
            }
            if (reasoner.getPrecomputableInferenceTypes().contains(InferenceType.CLASS_ASSERTIONS)) {
                reasoner.precomputeInferences(InferenceType.CLASS_ASSERTIONS);
            }
            // All types are the most specific ones and everything above them: asked once per kind of individual.
            Map<NodeSet<OWLClass>, TypeProfile> byDirectTypes = new HashMap<>();
            List<Realised> realised = new ArrayList<>();
            for (Module module : batch) {
                Map<OWLNamedIndividual, TypeProfile> types = new LinkedHashMap<>();
                module.namedMembers().forEach(member -> types.put(member, byDirectTypes.computeIfAbsent(
                        reasoner.getTypes(member, true), direct -> profiles.intern(
                                TypeProfile.of(withSuperClasses(reasoner, direct), direct)))));
                realised.add(new Realised(module, true, types));
            }
            return realised;
        });
        if (found != null) {
            for (int i = 0; i < batch.size(); i++) {
                remember(batch.get(i), axioms.get(i), found.get(i));
            }
            done.addAll(found);
        } else if (batch.size() == 1) {
            Realised inconsistent = new Realised(batch.get(0), false, Map.of());
            remember(batch.get(0), axioms.get(0), inconsistent);
            done.add(inconsistent);
        } else {
            int half = batch.size() / 2;
            reason(batch.subList(0, half), axioms.subList(0, half), done);
            reason(batch.subList(half, batch.size()), axioms.subList(half, axioms.size()), done);
        }
    }

    private static NodeSet<OWLClass> withSuperClasses(OWLReasoner reasoner, NodeSet<OWLClass> direct) {
        OWLClassNodeSet all = new OWLClassNodeSet();
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
            scratch.addAxioms(ontology, schema.stream());
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

    private void checkInterrupted() {
        if (interrupted || Thread.currentThread().isInterrupted()) {
            throw new ReasonerInterruptedException("interrupted between modules");
        }
    }

    /** The result of a one-individual module whose shape was reasoned on before, or null. */
    private Realised byShape(Module module, Set<OWLAxiom> axioms) {
        OWLNamedIndividual individual = soleNamedMember(module);
        if (individual == null) {
            return null;
        }
        Shape shape = shapes.get(shapeKey(individual, axioms));
        if (shape == null) {
            return null;
        }
        return new Realised(module, shape.consistent(), shape.consistent() ? Map.of(individual, shape.types()) : Map.of());
    }

    private void remember(Module module, Set<OWLAxiom> axioms, Realised realised) {
        OWLNamedIndividual individual = soleNamedMember(module);
        if (individual != null) {
            shapes.put(shapeKey(individual, axioms), new Shape(realised.consistent(),
                    realised.consistent() ? realised.types().get(individual) : null));
        }
    }

    private static OWLNamedIndividual soleNamedMember(Module module) {
        if (!module.isSingleton()) {
            return null;
        }
        var only = module.members.iterator().next();
        return only.isNamed() ? only.asOWLNamedIndividual() : null;
    }

    /** The module's assertions with its individual renamed to one placeholder: equal keys, equal types. */
    private Set<OWLAxiom> shapeKey(OWLNamedIndividual individual, Set<OWLAxiom> axioms) {
        OWLObjectDuplicator renamer = new OWLObjectDuplicator(Map.<OWLEntity, IRI>of(individual, PLACEHOLDER), scratch);
        Set<OWLAxiom> key = new LinkedHashSet<>();
        for (OWLAxiom axiom : axioms) {
            key.add(renamer.duplicateObject(axiom));
        }
        return Set.copyOf(key);
    }
}
