// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.WeakHashMap;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDifferentIndividualsAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLObjectPropertyExpression;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.parameters.Imports;

/**
 * The ABox cut into modules: the connected parts of the graph whose edges are the assertions that
 * tie individuals together ({@link AboxLinks}). Kept up to date change by change: only the modules
 * of the individuals a change touched are taken apart and grown again from the ontology.
 */
final class AboxModules {
    /** Individuals that are reasoned on together; {@code consistent} is set once they have been. */
    static final class Module {
        final Set<OWLIndividual> members;
        boolean consistent = true;
        // Holds the individuals the schema names: reasoned on with them, never compared by shape.
        boolean hub;

        Module(Set<OWLIndividual> members) {
            this.members = members;
        }

        boolean isSingleton() {
            return members.size() == 1;
        }

        Stream<OWLNamedIndividual> namedMembers() {
            return members.stream().filter(OWLIndividual::isNamed).map(OWLIndividual::asOWLNamedIndividual);
        }
    }

    /** What a re-partition did: the modules made, the ones taken apart, the individuals no longer in the ontology. */
    record Repartition(List<Module> made, List<Module> dropped, List<OWLIndividual> gone) {}

    private final OWLOntology ontology;
    private final AboxLinks links;
    private final OWLDataFactory factory;
    private final Map<OWLIndividual, Module> moduleOf = new HashMap<>();
    // The members of each DifferentIndividuals axiom, as a set (students list thousands in one).
    private final Map<OWLDifferentIndividualsAxiom, Set<OWLIndividual>> differentMembers = new WeakHashMap<>();
    private final Set<Module> inconsistent = new LinkedHashSet<>();
    private int count;
    // Without imports the ontology's own index answers (the closure's costs a stream per lookup);
    // an import change is a schema change, after which the modules are made anew.
    private final Imports imports;

    AboxModules(OWLOntology ontology, AboxLinks links) {
        this.ontology = ontology;
        this.imports = ontology.importsDeclarations().findAny().isPresent() ? Imports.INCLUDED : Imports.EXCLUDED;
        this.links = links;
        this.factory = ontology.getOWLOntologyManager().getOWLDataFactory();
    }

    /** Every individual of the ontology (imports included), in modules. */
    List<Module> partitionAll() {
        moduleOf.clear();
        count = 0;
        inconsistent.clear();
        List<Module> made = new ArrayList<>();
        Stream.concat(ontology.individualsInSignature(Imports.INCLUDED),
                        ontology.referencedAnonymousIndividuals(Imports.INCLUDED))
                .forEach(individual -> {
                    if (!moduleOf.containsKey(individual)) {
                        made.add(grow(individual));
                    }
                });
        return made;
    }

    /** Takes apart the modules of the touched individuals and grows new ones from the ontology as it is now. */
    Repartition repartition(Collection<OWLIndividual> touched) {
        Set<OWLIndividual> seeds = new LinkedHashSet<>(touched);
        List<Module> dropped = new ArrayList<>();
        for (OWLIndividual individual : touched) {
            Module old = moduleOf.get(individual);
            if (old != null && !dropped.contains(old)) {
                dropped.add(old);
                seeds.addAll(old.members);
            }
        }
        dropped.forEach(this::forget);
        List<Module> made = new ArrayList<>();
        List<OWLIndividual> gone = new ArrayList<>();
        for (OWLIndividual seed : seeds) {
            if (moduleOf.containsKey(seed)) {
                continue;
            }
            if (!inOntology(seed)) {
                gone.add(seed);
                continue;
            }
            // Growing may reach a module the change did not touch (a new edge merges it): it is taken apart too.
            made.add(grow(seed, dropped));
        }
        return new Repartition(made, dropped, gone);
    }

    /** The module an individual is in, or null when it is in none (not in the ontology). */
    Module of(OWLIndividual individual) {
        return moduleOf.get(individual);
    }

    void markInconsistent(Module module) {
        module.consistent = false;
        inconsistent.add(module);
    }

    /** Whether some module is inconsistent (the ontology then is). */
    boolean anyInconsistent() {
        return !inconsistent.isEmpty();
    }

    /**
     * The ABox part of a module: every logical assertion about its individuals, with each edge to
     * an individual outside it replaced by what the edge says about this end (a : ∃P.⊤, b : ∃P⁻.⊤),
     * and each DifferentIndividuals axiom cut down to the module's members (individuals of
     * different modules are different elements of the whole ontology's model anyway).
     */
    Set<OWLAxiom> axiomsOf(Module module) {
        Set<OWLAxiom> axioms = new LinkedHashSet<>();
        Set<OWLDifferentIndividualsAxiom> differences = new HashSet<>();
        for (OWLIndividual member : module.members) {
            if (member.isNamed()) {
                axioms.add(factory.getOWLDeclarationAxiom(member.asOWLNamedIndividual()));
            }
            referencing(member).filter(OWLAxiom::isLogicalAxiom).forEach(axiom -> {
                if (axiom instanceof OWLObjectPropertyAssertionAxiom edge && !links.links(edge.getProperty())) {
                    axioms.add(splitEnd(edge, member, module));
                } else if (axiom instanceof OWLDifferentIndividualsAxiom different) {
                    if (differences.add(different)) {
                        Set<OWLIndividual> all = differentMembers.computeIfAbsent(different,
                                d -> new HashSet<>(d.getIndividualsAsList()));
                        List<OWLIndividual> inside = module.members.stream().filter(all::contains).toList();
                        if (inside.size() > 1) {
                            axioms.add(inside.size() == all.size() ? different
                                    : factory.getOWLDifferentIndividualsAxiom(inside));
                        }
                    }
                } else {
                    axioms.add(axiom);
                }
            });
        }
        return axioms;
    }

    /** The classes, properties and datatypes of the assertions of every module but the hub. */
    Set<OWLEntity> signatureOutsideHub() {
        Set<OWLEntity> signature = new HashSet<>();
        Set<Module> done = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
        for (Module module : moduleOf.values()) {
            if (!module.hub && done.add(module)) {
                axiomsOf(module).forEach(axiom -> axiom.signature()
                        .filter(entity -> !entity.isOWLNamedIndividual()).forEach(signature::add));
            }
        }
        return signature;
    }

    private OWLAxiom splitEnd(OWLObjectPropertyAssertionAxiom edge, OWLIndividual member, Module module) {
        OWLIndividual other = edge.getSubject().equals(member) ? edge.getObject() : edge.getSubject();
        if (module.members.contains(other)) {
            return edge;
        }
        OWLObjectPropertyExpression property = edge.getSubject().equals(member) ? edge.getProperty()
                : edge.getProperty().getInverseProperty();
        return factory.getOWLClassAssertionAxiom(factory.getOWLObjectSomeValuesFrom(property, factory.getOWLThing()),
                member);
    }

    private boolean inOntology(OWLIndividual individual) {
        return individual.isNamed()
                ? ontology.containsEntityInSignature(individual.asOWLNamedIndividual(), Imports.INCLUDED)
                : referencing(individual).findAny().isPresent();
    }

    private Stream<OWLAxiom> referencing(OWLIndividual individual) {
        return individual.isNamed() ? ontology.referencingAxioms(individual.asOWLNamedIndividual(), imports)
                : ontology.referencingAxioms(individual.asOWLAnonymousIndividual(), imports);
    }

    private Module grow(OWLIndividual seed) {
        return grow(seed, new ArrayList<>());
    }

    /** The module the individual is in, or null when it is not in the ontology. */
    Module moduleOf(OWLIndividual individual) {
        return moduleOf.get(individual);
    }

    /** How many modules there are. */
    int count() {
        return count;
    }

    /** The module of {@code seed}: everything reachable over tying assertions (breadth first). */
    private Module grow(OWLIndividual seed, List<Module> dropped) {
        Module module = new Module(new LinkedHashSet<>());
        count++;
        Deque<OWLIndividual> frontier = new ArrayDeque<>();
        frontier.add(seed);
        module.members.add(seed);
        while (!frontier.isEmpty()) {
            OWLIndividual individual = frontier.poll();
            Module earlier = moduleOf.put(individual, module);
            if (earlier != null && earlier != module && !dropped.contains(earlier)) {
                dropped.add(earlier);
                forget(earlier);
                moduleOf.put(individual, module);
            }
            Stream<OWLIndividual> neighbours = referencing(individual).filter(links::ties)
                    .flatMap(AboxLinks::individualsOf);
            if (individual.isNamed() && links.nominals().contains(individual.asOWLNamedIndividual())) {
                module.hub = true;
                neighbours = Stream.concat(neighbours, links.nominals().stream());
            }
            neighbours.forEach(neighbour -> {
                if (module.members.add(neighbour)) {
                    frontier.add(neighbour);
                }
            });
        }
        return module;
    }

    /** Forgets a module's assignments (its members are about to be assigned again). */
    private void forget(Module module) {
        count--;
        inconsistent.remove(module);
        for (OWLIndividual member : module.members) {
            moduleOf.remove(member, module);
        }
    }
}
