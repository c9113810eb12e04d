// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.view;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import io.github.armor.core.answers.Rendering;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reasoning.PublishedStates.Published;
import io.github.armor.core.reference.Reference;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.search.EntitySearcher;

/**
 * Individuals a page at a time, found by name, with their types; and one individual with its
 * types and property values. Everything says whether the ontology asserts it or the reasoner
 * infers it.
 */
final class IndividualsView {
    private final ViewReads reads;

    IndividualsView(ViewReads reads) {
        this.reads = reads;
    }

    /**
     * The individuals whose name contains {@code search}, ignoring case, sorted by name:
     * {@code limit} of them from {@code offset}, each with its asserted types and its most specific
     * inferred ones; {@code total} counts every match.
     */
    JsonObject page(String referenceName, String search, int offset, int limit) {
        Reference reference = reads.reference(referenceName);
        Optional<Published> published = reads.offLock(reference);
        String needle = search.trim().toLowerCase(Locale.ROOT);
        Function<Reference, List<OWLNamedIndividual>> find = r -> r.ontology()
                .individualsInSignature(Imports.INCLUDED)
                .filter(i -> needle.isEmpty() || i.getIRI().getShortForm().toLowerCase(Locale.ROOT).contains(needle))
                .sorted(ViewJson.BY_NAME).toList();
        List<OWLNamedIndividual> matches = published.isPresent() ? find.apply(reference) : reads.whole(reference, find);
        List<OWLNamedIndividual> shown = matches.subList(Math.min(offset, matches.size()),
                Math.min(offset + limit, matches.size()));
        JsonArray items = new JsonArray();
        Consumer<OWLNamedIndividual> describe = individual -> {
            JsonObject item = ViewJson.entity(individual);
            Set<OWLClass> asserted = assertedTypes(reference, individual);
            Set<OWLClass> types = new LinkedHashSet<>(asserted);
            types.addAll(published.map(state -> ViewReads.directTypes(state.state(), individual))
                    .orElseGet(() -> ViewReads.directTypes(reference, individual)));
            item.add("types", withAsserted(types, asserted));
            items.add(item);
        };
        if (published.isPresent()) {
            shown.forEach(describe);
        } else {
            reads.inSlices(reference, shown, describe);
        }
        JsonObject view = new JsonObject();
        view.addProperty("consistent", published.map(state -> state.state().consistent())
                .orElse(reference.isConsistent()));
        view.addProperty("total", matches.size());
        view.addProperty("offset", offset);
        view.add("individuals", items);
        return view;
    }

    /** One individual: every type, and the values of every property that has one for it. */
    JsonObject detail(String referenceName, String individualName) {
        Reference reference = reads.reference(referenceName);
        return reads.whole(reference, r -> {
            OWLNamedIndividual individual = r.names().entity(EntityType.NAMED_INDIVIDUAL, individualName);
            if (!r.names().knows(individual)) {
                throw new ArmorException(ExitCode.UNKNOWN_NAME, "reference '" + r.name() + "' has no "
                        + r.names().describeUnknown(EntityType.NAMED_INDIVIDUAL, individualName));
            }
            JsonObject view = ViewJson.entity(individual);
            Set<OWLClass> asserted = assertedTypes(r, individual);
            Set<OWLClass> types = new LinkedHashSet<>(asserted);
            types.addAll(ViewReads.inferred(r, reasoner -> reasoner.getTypes(individual, false).entities()
                    .filter(c -> !c.isOWLThing()).toList()).orElse(List.of()));
            view.add("types", withAsserted(types, asserted));
            view.add("object_values", objectValues(r, individual));
            view.add("data_values", dataValues(r, individual));
            Set<OWLNamedIndividual> same = ViewReads.inferred(r, reasoner -> reasoner.getSameIndividuals(individual)
                    .entities().filter(i -> !i.equals(individual)).collect(Collectors.toSet())).orElse(Set.of());
            view.add("same_as", ViewJson.entities(same));
            view.addProperty("inferred", r.isConsistent());
            return view;
        });
    }

    static Set<OWLClass> assertedTypes(Reference reference, OWLNamedIndividual individual) {
        return EntitySearcher.getTypes(individual, reference.ontology().importsClosure())
                .filter(t -> !t.isAnonymous()).map(OWLClassExpression::asOWLClass)
                .collect(Collectors.toCollection(LinkedHashSet::new));
    }

    /** The entities by name, each {iri, name, asserted}: types of an individual, values of a property. */
    private static JsonArray withAsserted(Set<? extends OWLEntity> entities, Set<? extends OWLEntity> asserted) {
        JsonArray array = new JsonArray();
        entities.stream().sorted(ViewJson.BY_NAME).forEach(e -> array.add(ViewJson.entity(e, asserted.contains(e))));
        return array;
    }

    /** {"property": {...}, "values": [{iri, name, asserted}]} for each object property with values. */
    private static JsonArray objectValues(Reference reference, OWLNamedIndividual individual) {
        return perProperty(reference.ontology().objectPropertiesInSignature(Imports.INCLUDED), property -> {
            Set<OWLNamedIndividual> asserted = EntitySearcher.getObjectPropertyValues(individual, property,
                    reference.ontology().importsClosure()).filter(i -> i.isNamed())
                    .map(i -> i.asOWLNamedIndividual()).collect(Collectors.toSet());
            Set<OWLNamedIndividual> values = new LinkedHashSet<>(asserted);
            values.addAll(ViewReads.inferred(reference, reasoner -> reasoner.getObjectPropertyValues(individual,
                    property).entities().toList()).orElse(List.of()));
            return withAsserted(values, asserted);
        });
    }

    /** {"property": {...}, "values": [{"value": "\"80\"^^xsd:integer", "asserted"}]} per data property with values. */
    private static JsonArray dataValues(Reference reference, OWLNamedIndividual individual) {
        return perProperty(reference.ontology().dataPropertiesInSignature(Imports.INCLUDED), property -> {
            Set<OWLLiteral> asserted = EntitySearcher.getDataPropertyValues(individual, property,
                    reference.ontology().importsClosure()).collect(Collectors.toSet());
            TreeMap<String, Boolean> values = new TreeMap<>();
            asserted.forEach(l -> values.put(Rendering.literal(l), true));
            ViewReads.inferred(reference, reasoner -> new ArrayList<>(reasoner.getDataPropertyValues(individual,
                    property))).orElse(new ArrayList<>()).forEach(l -> values.putIfAbsent(Rendering.literal(l), false));
            JsonArray shown = new JsonArray();
            values.forEach((value, isAsserted) -> {
                JsonObject item = new JsonObject();
                item.addProperty("value", value);
                item.addProperty("asserted", isAsserted);
                shown.add(item);
            });
            return shown;
        });
    }

    /** {"property": {...}, "values": [...]} for each property (not built in, by name) whose values are not empty. */
    private static <P extends OWLEntity> JsonArray perProperty(Stream<P> properties, Function<P, JsonArray> values) {
        JsonArray entries = new JsonArray();
        properties.filter(p -> !p.isBuiltIn()).sorted(ViewJson.BY_NAME).forEach(property -> {
            JsonArray shown = values.apply(property);
            if (!shown.isEmpty()) {
                JsonObject entry = new JsonObject();
                entry.add("property", ViewJson.entity(property));
                entry.add("values", shown);
                entries.add(entry);
            }
        });
        return entries;
    }
}
