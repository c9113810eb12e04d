// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import org.semanticweb.owlapi.model.OWLClass;

/** The answers of the scene queries, one JSON object per item (QUERY SIT SCENES, QUERY SIT RECENT). */
final class SceneJson {
    private SceneJson() {}

    /** A learned scene class: its name, cardinality, definition in words and its place in the hierarchy. */
    static JsonObject sceneClass(OWLClass owlClass, SceneDefinition definition, Set<OWLClass> parents,
                                 Set<OWLClass> equivalents, Function<OWLClass, String> render) {
        JsonObject item = new JsonObject();
        item.addProperty("class", render.apply(owlClass));
        item.addProperty("name", owlClass.getIRI().getShortForm());
        item.addProperty("cardinality", definition.cardinality());
        item.addProperty("definition", definition.words());
        item.add("restrictions", restrictions(definition));
        item.add("superscenes", names(parents, render));
        item.add("equivalent", names(equivalents, render));
        return item;
    }

    /** A scene as it was answered: its elements, relations, recognitions (each explained) and what was learned. */
    static JsonObject outcome(SceneTeacher.Outcome outcome, String client, long atEpochMs,
                              Function<OWLClass, String> render) {
        JsonObject item = new JsonObject();
        item.addProperty("at_ms", atEpochMs);
        item.addProperty("client", client);
        JsonArray elements = new JsonArray();
        for (SceneElement element : outcome.scene().elements()) {
            JsonObject shown = new JsonObject();
            shown.addProperty("label", element.label());
            shown.addProperty("type", element.shape().name());
            JsonArray features = new JsonArray();
            for (double value : element.centre()) {
                features.add(value);
            }
            if (element.hasAxis()) {
                for (double value : element.axis()) {
                    features.add(value);
                }
            }
            shown.add("features", features);
            elements.add(shown);
        }
        item.add("elements", elements);
        item.addProperty("cardinality", outcome.cardinality());
        item.addProperty("relations", outcome.facts().size());
        // How it was recognised: by counting in a plain reference, or by the reference's reasoner.
        item.addProperty("recognised_by", outcome.inReference() ? "reasoner" : "counting");
        item.addProperty("learned", outcome.learned().map(render).orElse(""));
        outcome.learnedDefinition().ifPresent(d -> item.addProperty("learned_definition", d.words()));
        JsonArray recognitions = new JsonArray();
        for (SceneTeacher.Recognition recognition : outcome.recognitions()) {
            JsonObject shown = new JsonObject();
            shown.addProperty("class", render.apply(recognition.owlClass()));
            shown.addProperty("name", recognition.owlClass().getIRI().getShortForm());
            shown.addProperty("similarity", recognition.similarity());
            recognition.definition().ifPresent(definition -> {
                shown.addProperty("cardinality", definition.cardinality());
                shown.add("explanation", explanation(Explanation.of(outcome.scene(), outcome.facts(), definition)));
            });
            recognitions.add(shown);
        }
        item.add("recognitions", recognitions);
        return item;
    }

    private static JsonArray explanation(List<Explanation.Match> matches) {
        JsonArray shown = new JsonArray();
        for (Explanation.Match match : matches) {
            JsonObject item = new JsonObject();
            item.addProperty("restriction", match.restriction().words());
            item.addProperty("min", match.restriction().min());
            item.addProperty("counted", match.counted());
            JsonArray relations = new JsonArray();
            match.relations().forEach(relations::add);
            item.add("relations", relations);
            shown.add(item);
        }
        return shown;
    }

    private static JsonArray restrictions(SceneDefinition definition) {
        JsonArray shown = new JsonArray();
        for (SceneDefinition.Restriction restriction : definition.restrictions()) {
            JsonObject item = new JsonObject();
            item.addProperty("property", restriction.property().name());
            item.addProperty("relation", restriction.property().relation().word());
            item.addProperty("subject", restriction.property().subject().name());
            item.addProperty("type", restriction.type().name());
            item.addProperty("min", restriction.min());
            item.addProperty("words", restriction.words());
            shown.add(item);
        }
        return shown;
    }

    private static JsonArray names(Set<OWLClass> classes, Function<OWLClass, String> render) {
        JsonArray shown = new JsonArray();
        classes.stream().map(render).sorted().forEach(shown::add);
        return shown;
    }
}
