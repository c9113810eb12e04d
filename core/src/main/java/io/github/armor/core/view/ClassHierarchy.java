// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.view;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import io.github.armor.core.answers.Syntax;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.command.builtin.Queries;
import io.github.armor.core.reasoning.ClassifiedSchema;
import io.github.armor.core.reasoning.PublishedStates.Published;
import io.github.armor.core.reference.Reference;
import java.util.ArrayDeque;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.search.EntitySearcher;

/**
 * The class hierarchy as the reasoner infers it, each subclass link marked asserted or inferred,
 * unsatisfiable classes flagged; and one class in detail: its definition in Manchester syntax and
 * its instances, asserted and inferred told apart. Without a reasoner's answer (an inconsistent
 * reference) the asserted hierarchy is shown, and said to be.
 */
final class ClassHierarchy {
    private final ViewReads reads;

    ClassHierarchy(ViewReads reads) {
        this.reads = reads;
    }

    JsonObject hierarchy(String referenceName) {
        Reference reference = reads.reference(referenceName);
        Optional<Published> published = reads.offLock(reference);
        Optional<ClassifiedSchema> kept = reference.classifiedSchema();
        if (published.isPresent() && kept.isPresent()) {
            return keptHierarchy(reference, published.get().state().consistent(), kept.get());
        }
        List<OWLClass> classes = reads.whole(reference, r -> r.ontology().classesInSignature(Imports.INCLUDED)
                .filter(c -> !c.isBuiltIn()).sorted(ViewJson.BY_NAME).toList());
        Set<OWLClass> unsatisfiable = reads.whole(reference, r -> ViewReads.inferred(r, reasoner ->
                reasoner.getUnsatisfiableClasses().entities().filter(c -> !c.isOWLNothing())
                        .collect(Collectors.toSet())).orElse(Set.of()));
        JsonArray nodes = new JsonArray();
        boolean[] allInferred = {reference.isConsistent()};
        reads.inSlices(reference, classes, owlClass -> {
            Set<OWLClass> asserted = assertedParents(reference, owlClass);
            Optional<Set<OWLClass>> inferred = unsatisfiable.contains(owlClass) ? Optional.empty()
                    : ViewReads.inferred(reference, reasoner -> reasoner.getSuperClasses(owlClass, true).entities()
                    .filter(c -> !c.isOWLThing()).collect(Collectors.toSet()));
            allInferred[0] &= inferred.isPresent() || unsatisfiable.contains(owlClass);
            JsonObject node = ViewJson.entity(owlClass);
            JsonArray parents = new JsonArray();
            inferred.orElse(asserted).stream().sorted(ViewJson.BY_NAME)
                    .forEach(parent -> parents.add(ViewJson.entity(parent, asserted.contains(parent))));
            node.add("parents", parents);
            Set<OWLClass> equivalents = ViewReads.inferred(reference, reasoner -> reasoner.getEquivalentClasses(
                    owlClass).entities().filter(c -> !c.equals(owlClass) && !c.isBuiltIn())
                    .collect(Collectors.toSet())).orElse(Set.of());
            node.add("equivalents", ViewJson.entities(equivalents));
            node.addProperty("unsatisfiable", unsatisfiable.contains(owlClass));
            nodes.add(node);
        });
        JsonObject view = new JsonObject();
        view.addProperty("consistent", reference.isConsistent());
        view.addProperty("inferred", allInferred[0]);
        view.add("classes", nodes);
        return view;
    }

    /**
     * The hierarchy the reference keeps for its schema (classified once: {@link ClassifiedSchema}),
     * read without the reference's lock; the asserted one when the ontology is inconsistent.
     */
    private static JsonObject keptHierarchy(Reference reference, boolean consistent, ClassifiedSchema kept) {
        Set<OWLClass> unsatisfiable = consistent ? kept.bottomNode().entities().filter(c -> !c.isOWLNothing())
                .collect(Collectors.toSet()) : Set.of();
        JsonArray nodes = new JsonArray();
        reference.ontology().classesInSignature(Imports.INCLUDED).filter(c -> !c.isBuiltIn())
                .sorted(ViewJson.BY_NAME).forEach(owlClass -> {
                    Set<OWLClass> asserted = assertedParents(reference, owlClass);
                    Set<OWLClass> parents = !consistent || unsatisfiable.contains(owlClass) ? asserted
                            : kept.superClasses(owlClass, true).entities().filter(c -> !c.isOWLThing())
                            .collect(Collectors.toSet());
                    JsonObject node = ViewJson.entity(owlClass);
                    JsonArray shown = new JsonArray();
                    parents.stream().sorted(ViewJson.BY_NAME)
                            .forEach(parent -> shown.add(ViewJson.entity(parent, asserted.contains(parent))));
                    node.add("parents", shown);
                    node.add("equivalents", ViewJson.entities(consistent ? kept.equivalentClasses(owlClass).entities()
                            .filter(c -> !c.equals(owlClass) && !c.isBuiltIn()).collect(Collectors.toSet())
                            : Set.of()));
                    node.addProperty("unsatisfiable", unsatisfiable.contains(owlClass));
                    nodes.add(node);
                });
        JsonObject view = new JsonObject();
        view.addProperty("consistent", consistent);
        view.addProperty("inferred", consistent);
        view.add("classes", nodes);
        return view;
    }

    /** Named superclasses the ontology states: the named conjuncts of its SubClassOf and EquivalentTo. */
    static Set<OWLClass> assertedParents(Reference reference, OWLClass owlClass) {
        Set<OWLClass> parents = Stream.concat(
                        EntitySearcher.getSuperClasses(owlClass, reference.ontology().importsClosure()),
                        EntitySearcher.getEquivalentClasses(owlClass, reference.ontology().importsClosure()))
                .flatMap(OWLClassExpression::conjunctSet).filter(e -> !e.isAnonymous())
                .map(OWLClassExpression::asOWLClass).collect(Collectors.toCollection(HashSet::new));
        parents.remove(owlClass);
        parents.removeIf(OWLClass::isOWLThing);
        return parents;
    }

    /**
     * Individuals the ontology states to be of the class or of a class stated below it: what can
     * be said of its instances without a reasoner.
     */
    static Set<OWLNamedIndividual> assertedInstances(Reference reference, OWLClass owlClass) {
        Set<OWLClass> seen = new HashSet<>(Set.of(owlClass));
        ArrayDeque<OWLClass> below = new ArrayDeque<>(seen);
        Set<OWLNamedIndividual> instances = new HashSet<>();
        while (!below.isEmpty()) {
            OWLClass next = below.poll();
            EntitySearcher.getIndividuals(next, reference.ontology().importsClosure()).filter(i -> i.isNamed())
                    .forEach(i -> instances.add(i.asOWLNamedIndividual()));
            reference.ontology().importsClosure().flatMap(o -> o.subClassAxiomsForSuperClass(next))
                    .map(a -> a.getSubClass()).filter(e -> !e.isAnonymous()).map(OWLClassExpression::asOWLClass)
                    .filter(seen::add).forEach(below::add);
        }
        return instances;
    }

    /**
     * One class: its frame in Manchester syntax (EquivalentTo, SubClassOf, DisjointWith, as
     * asserted), its restrictions (as QUERY CLASS RESTRICTIONS, by short names), its inferred
     * superclasses, whether it is satisfiable, and its instances (at most
     * {@code instanceLimit}, by name; {@code instance_count} tells how many there are).
     */
    JsonObject detail(String referenceName, String className, int instanceLimit) {
        Reference reference = reads.reference(referenceName);
        return reads.whole(reference, r -> {
            OWLClass owlClass = r.names().entity(EntityType.CLASS, className);
            if (!r.names().knows(owlClass)) {
                throw new ArmorException(ExitCode.UNKNOWN_NAME, "reference '" + r.name() + "' has no class "
                        + r.names().describeUnknown(EntityType.CLASS, className));
            }
            JsonObject view = ViewJson.entity(owlClass);
            view.add("equivalent_to", manchester(r, EntitySearcher.getEquivalentClasses(owlClass,
                    r.ontology().importsClosure()).filter(e -> !e.equals(owlClass))));
            view.add("subclass_of", manchester(r, EntitySearcher.getSuperClasses(owlClass,
                    r.ontology().importsClosure())));
            view.add("disjoint_with", manchester(r, EntitySearcher.getDisjointClasses(owlClass,
                    r.ontology().importsClosure()).filter(e -> !e.equals(owlClass))));
            view.add("restrictions", ViewJson.strings(Queries.restrictions(r, owlClass, false)));
            view.add("annotations", ViewJson.strings(r.ontology().importsClosure()
                    .flatMap(o -> EntitySearcher.getAnnotations(owlClass, o))
                    .map(a -> a.getProperty().getIRI().getShortForm() + ": "
                            + a.getValue().asLiteral().map(l -> l.getLiteral()).orElse(a.getValue().toString()))
                    .distinct().sorted().toList()));
            Optional<Boolean> satisfiable = ViewReads.inferred(r, reasoner -> reasoner.isSatisfiable(owlClass));
            view.addProperty("inferred", satisfiable.isPresent());
            view.addProperty("unsatisfiable", !satisfiable.orElse(true));
            Set<OWLClass> superclasses = ViewReads.inferred(r, reasoner -> reasoner.getSuperClasses(owlClass, false)
                    .entities().filter(c -> !c.isOWLThing()).collect(Collectors.toSet())).orElse(Set.of());
            view.add("inferred_superclasses", ViewJson.entities(superclasses));
            Set<OWLNamedIndividual> asserted = EntitySearcher.getIndividuals(owlClass, r.ontology().importsClosure())
                    .filter(i -> i.isNamed()).map(i -> i.asOWLNamedIndividual()).collect(Collectors.toSet());
            Set<OWLNamedIndividual> all = new HashSet<>(asserted);
            if (satisfiable.isEmpty()) {
                all.addAll(assertedInstances(r, owlClass));
            }
            if (satisfiable.orElse(false)) {
                ViewReads.inferred(r, reasoner -> reasoner.getInstances(owlClass, false).entities().toList())
                        .ifPresent(all::addAll);
            }
            JsonArray instances = new JsonArray();
            all.stream().sorted(ViewJson.BY_NAME).limit(instanceLimit)
                    .forEach(i -> instances.add(ViewJson.entity(i, asserted.contains(i))));
            view.add("instances", instances);
            view.addProperty("instance_count", all.size());
            return view;
        });
    }

    private static JsonArray manchester(Reference reference, Stream<OWLClassExpression> expressions) {
        return ViewJson.strings(expressions.map(e -> Syntax.render(reference, false, e)).sorted().toList());
    }
}
