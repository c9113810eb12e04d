// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.view;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reasoning.InferredState;
import io.github.armor.core.reasoning.PublishedStates.Published;
import io.github.armor.core.reference.Reference;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.BooleanSupplier;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.search.EntitySearcher;

/**
 * Individuals as nodes, linked by the object properties the user chose (asserted and inferred
 * links told apart): a topological map of rooms joined by {@code connectedTo}. Above
 * {@code limit} individuals the graph is a sample: whole neighbourhoods, grown breadth-first from
 * a focus individual or from the first individuals by name, so what is shown stays connected.
 */
final class PropertyGraph {
    private final ViewReads reads;

    PropertyGraph(ViewReads reads) {
        this.reads = reads;
    }

    /** A link found from its subject; merged with its reverse when both exist (a symmetric property). */
    private record Link(OWLNamedIndividual source, OWLNamedIndividual target, OWLObjectProperty property,
                        boolean asserted) {}

    /** What the request names, resolved under the reference's lock. */
    private record Scope(List<OWLObjectProperty> properties, List<OWLNamedIndividual> candidates,
                         OWLNamedIndividual focus) {}

    /**
     * @param propertyNames the object properties to follow (null: every one; empty: none)
     * @param className     only instances of this class, asserted or inferred (empty: every individual)
     * @param focusName     grow the sample from this individual (empty: from the first by name)
     * @param limit         the most individuals shown
     */
    JsonObject graph(String referenceName, List<String> propertyNames, String className, String focusName,
                     int limit) {
        Reference reference = reads.reference(referenceName);
        Optional<InferredState> published = reads.offLock(reference).map(Published::state);
        // Inferred links (dashed) need the reasoner, so a free reference is read itself, in
        // slices; while a writer holds it, its last published state answers (asserted links),
        // so a page never waits for a writer.
        if (published.isPresent() && (reference.isBusy() || reference.othersWaiting())) {
            return draw(reference, propertyNames, className, focusName, limit, published.get());
        }
        try {
            return draw(reference, propertyNames, className, focusName, limit, null);
        } catch (ArmorException e) {
            if (e.exitCode() != ExitCode.TIMEOUT || published.isEmpty()) {
                throw e;
            }
            return draw(reference, propertyNames, className, focusName, limit, published.get());
        }
    }

    /** The graph read from {@code state}, off the lock, or (null) from the reference and its reasoner. */
    private JsonObject draw(Reference reference, List<String> propertyNames, String className, String focusName,
                            int limit, InferredState state) {
        Scope scope = state != null ? scope(reference, propertyNames, className, focusName, state)
                : reads.whole(reference, r -> scope(r, propertyNames, className, focusName, null));
        Set<OWLNamedIndividual> candidates = new HashSet<>(scope.candidates());
        Iterator<OWLNamedIndividual> seeds = scope.focus() != null ? List.of(scope.focus()).iterator()
                : scope.candidates().iterator();
        Set<OWLNamedIndividual> kept = new LinkedHashSet<>();
        ArrayDeque<OWLNamedIndividual> frontier = new ArrayDeque<>();
        Map<OWLNamedIndividual, List<OWLClass>> types = new LinkedHashMap<>();
        List<Link> links = new ArrayList<>();
        BooleanSupplier step = () -> {
            OWLNamedIndividual next = frontier.poll();
            while (next == null && seeds.hasNext() && kept.size() < limit) {
                OWLNamedIndividual seed = seeds.next();
                if (kept.add(seed)) {
                    next = seed;
                }
            }
            if (next == null) {
                return false;
            }
            types.put(next, mostSpecificTypes(reference, next, state));
            for (OWLNamedIndividual neighbour : expand(reference, next, scope.properties(), candidates, links,
                    state == null)) {
                if (kept.size() < limit && kept.add(neighbour)) {
                    frontier.add(neighbour);
                }
            }
            return true;
        };
        if (state != null) {
            boolean more = true;
            while (more) {
                more = step.getAsBoolean();
            }
        } else {
            reads.inSlices(reference, step);
        }
        JsonObject view = new JsonObject();
        view.add("nodes", nodes(types));
        view.add("edges", edges(links, kept));
        view.addProperty("candidates", candidates.size());
        view.addProperty("truncated", kept.size() >= limit && kept.size() < candidates.size());
        view.addProperty("consistent", state != null ? state.consistent() : reference.isConsistent());
        // Links the reasoner infers need it on the whole ontology; a view from the published state shows asserted ones.
        view.addProperty("inferred_links", state == null);
        return view;
    }

    /** What the request names; {@code state}: the published one to read instances from (null: ask the reasoner). */
    private static Scope scope(Reference reference, List<String> propertyNames, String className, String focusName,
                               InferredState state) {
        List<OWLObjectProperty> properties = new ArrayList<>();
        if (propertyNames == null) {
            reference.ontology().objectPropertiesInSignature(Imports.INCLUDED).filter(p -> !p.isBuiltIn())
                    .sorted(ViewJson.BY_NAME).forEach(properties::add);
        }
        for (String name : propertyNames == null ? List.<String>of() : propertyNames) {
            // The page sends the IRIs it listed: one the naming rules refuse (it holds a '|', say)
            // is still the reference's own property, and must not take the graph with it.
            properties.add(byIri(reference, name).orElseGet(() -> known(reference, EntityType.OBJECT_PROPERTY, name)));
        }
        List<OWLNamedIndividual> candidates;
        if (className.isBlank()) {
            candidates = reference.ontology().individualsInSignature(Imports.INCLUDED).sorted(ViewJson.BY_NAME)
                    .toList();
        } else {
            OWLClass owlClass = known(reference, EntityType.CLASS, className);
            Set<OWLNamedIndividual> instances = ClassHierarchy.assertedInstances(reference, owlClass);
            if (state == null) {
                ViewReads.inferred(reference, reasoner -> reasoner.getInstances(owlClass, false).entities().toList())
                        .ifPresent(instances::addAll);
            } else if (state.consistent() && state.knows(owlClass)) {
                instances.addAll(state.instances(owlClass));
            }
            candidates = instances.stream().sorted(ViewJson.BY_NAME).toList();
        }
        OWLNamedIndividual focus = null;
        if (!focusName.isBlank()) {
            focus = known(reference, EntityType.NAMED_INDIVIDUAL, focusName);
            if (!candidates.contains(focus)) {
                throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "the focus '" + focusName
                        + "' is not an instance of " + className);
            }
        }
        return new Scope(properties, candidates, focus);
    }

    /**
     * An object property of the reference named by its exact IRI in angle brackets, as the page
     * sends those it listed: found without the naming rules, which refuse some IRIs a loaded
     * document may hold.
     */
    private static Optional<OWLObjectProperty> byIri(Reference reference, String name) {
        String trimmed = name.trim();
        if (!(trimmed.startsWith("<") && trimmed.endsWith(">"))) {
            return Optional.empty();
        }
        IRI iri = IRI.create(trimmed.substring(1, trimmed.length() - 1));
        return reference.ontology().objectPropertiesInSignature(Imports.INCLUDED)
                .filter(p -> p.getIRI().equals(iri)).findFirst();
    }

    private static <E extends org.semanticweb.owlapi.model.OWLEntity> E known(Reference reference, EntityType<E> type,
                                                                              String name) {
        E entity = reference.names().entity(type, name);
        if (!reference.names().knows(entity)) {
            throw new ArmorException(ExitCode.UNKNOWN_NAME, "reference '" + reference.name() + "' has no "
                    + reference.names().describeUnknown(type, name));
        }
        return entity;
    }

    /**
     * Records the links from {@code individual} by each property (asserted and inferred) and
     * answers its neighbours among the candidates: those it links to, and those that assert a
     * link to it (so a sample grown from a room also reaches the agents in it).
     */
    private static Set<OWLNamedIndividual> expand(Reference reference, OWLNamedIndividual individual,
                                                  List<OWLObjectProperty> properties,
                                                  Set<OWLNamedIndividual> candidates, List<Link> links,
                                                  boolean inferred) {
        Set<OWLNamedIndividual> neighbours = new LinkedHashSet<>();
        for (OWLObjectProperty property : properties) {
            Set<OWLNamedIndividual> asserted = EntitySearcher.getObjectPropertyValues(individual, property,
                    reference.ontology().importsClosure()).filter(i -> i.isNamed())
                    .map(i -> i.asOWLNamedIndividual()).collect(Collectors.toSet());
            Set<OWLNamedIndividual> values = new LinkedHashSet<>(asserted);
            if (inferred) {
                ViewReads.inferred(reference, reasoner -> reasoner.getObjectPropertyValues(individual, property)
                        .entities().toList()).ifPresent(values::addAll);
            }
            for (OWLNamedIndividual value : values) {
                if (candidates.contains(value)) {
                    links.add(new Link(individual, value, property, asserted.contains(value)));
                    neighbours.add(value);
                }
            }
        }
        Set<OWLObjectProperty> followed = new HashSet<>(properties);
        reference.ontology().importsClosure().flatMap(o -> o.referencingAxioms(individual))
                .filter(a -> a.isOfType(AxiomType.OBJECT_PROPERTY_ASSERTION))
                .map(OWLObjectPropertyAssertionAxiom.class::cast)
                .filter(a -> individual.equals(a.getObject()) && a.getSubject().isNamed()
                        && !a.getProperty().isAnonymous() && followed.contains(a.getProperty().asOWLObjectProperty()))
                .map(a -> a.getSubject().asOWLNamedIndividual())
                .filter(candidates::contains)
                .forEach(neighbours::add);
        return neighbours;
    }

    private static List<OWLClass> mostSpecificTypes(Reference reference, OWLNamedIndividual individual,
                                                    InferredState state) {
        Set<OWLClass> types = new HashSet<>(state != null ? ViewReads.directTypes(state, individual)
                : ViewReads.directTypes(reference, individual));
        if (types.isEmpty()) {
            types.addAll(IndividualsView.assertedTypes(reference, individual));
        }
        return types.stream().sorted(ViewJson.BY_NAME).toList();
    }

    private static JsonArray nodes(Map<OWLNamedIndividual, List<OWLClass>> types) {
        JsonArray nodes = new JsonArray();
        types.entrySet().stream().sorted(Map.Entry.comparingByKey(ViewJson.BY_NAME)).forEach(entry -> {
            JsonObject node = ViewJson.entity(entry.getKey());
            node.add("types", ViewJson.entities(entry.getValue()));
            nodes.add(node);
        });
        return nodes;
    }

    /** One edge per linked pair and property; a pair linked both ways (symmetric) is one edge marked both. */
    private static JsonArray edges(List<Link> links, Set<OWLNamedIndividual> kept) {
        Map<List<Object>, Link> byEnds = new LinkedHashMap<>();
        for (Link link : links) {
            if (kept.contains(link.source()) && kept.contains(link.target())) {
                byEnds.merge(List.of(link.source(), link.target(), link.property()), link,
                        (a, b) -> new Link(a.source(), a.target(), a.property(), a.asserted() || b.asserted()));
            }
        }
        JsonArray edges = new JsonArray();
        Set<List<Object>> done = new HashSet<>();
        Comparator<Link> order = Comparator.comparing((Link l) -> l.source().getIRI().toString())
                .thenComparing(l -> l.target().getIRI().toString())
                .thenComparing(l -> l.property().getIRI().toString());
        for (Link link : byEnds.values().stream().sorted(order).toList()) {
            List<Object> key = List.of(link.source(), link.target(), link.property());
            List<Object> reverseKey = List.of(link.target(), link.source(), link.property());
            if (done.contains(key)) {
                continue;
            }
            Link reverse = link.source().equals(link.target()) ? null : byEnds.get(reverseKey);
            done.add(key);
            done.add(reverseKey);
            JsonObject edge = new JsonObject();
            edge.addProperty("source", link.source().getIRI().toString());
            edge.addProperty("target", link.target().getIRI().toString());
            edge.addProperty("property", link.property().getIRI().toString());
            edge.addProperty("property_name", link.property().getIRI().getShortForm());
            edge.addProperty("asserted", link.asserted() || reverse != null && reverse.asserted());
            edge.addProperty("both_ways", reverse != null);
            edges.add(edge);
        }
        return edges;
    }
}
