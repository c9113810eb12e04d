// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.semanticweb.owlapi.model.AddAxiom;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.RemoveAxiom;

/**
 * Scene identification and tagging on one reference (docs/scenes.md): the scene becomes an
 * individual related to its elements, the reasoner classifies it under the scene classes learned
 * so far (recognition, each class with its similarity), and when none is similar enough a new
 * class is learned from it. The scene's individuals are removed again; only a learned class (and
 * the vocabulary it needs) stays. The caller runs this as one directive, so a failure anywhere
 * undoes all of it.
 */
public final class SceneTeacher {
    private static final String SCENE_INDIVIDUAL = "sit-scene";
    private static final String ELEMENT_INDIVIDUAL = "sit-element-";

    private SceneTeacher() {}

    /** A class the scene was recognised as: its similarity card(class) / card(scene), and its definition if it has one. */
    public record Recognition(OWLClass owlClass, double similarity, Optional<SceneDefinition> definition) {}

    /**
     * What one scene gave: its facts and cardinality, the classes it was recognised as (most
     * similar first) and the class learned from it, if any.
     */
    public record Outcome(Scene scene, List<SpatialRelations.Fact> facts, int cardinality,
                          List<Recognition> recognitions, Optional<OWLClass> learned,
                          Optional<SceneDefinition> learnedDefinition) {}

    /**
     * Recognises the scene and learns it unless a recognised class has a similarity above
     * {@code threshold}. A scene with no relation changes nothing and is recognised as nothing.
     */
    public static Outcome evaluate(SceneReference reference, Scene scene, double threshold) {
        List<SpatialRelations.Fact> facts = SpatialRelations.of(scene);
        List<SceneAssertion> assertions = SceneAssertion.of(scene, facts);
        if (assertions.isEmpty()) {
            return new Outcome(scene, facts, 0, List.of(), Optional.empty(), Optional.empty());
        }
        OWLDataFactory factory = reference.factory();
        OWLOntology ontology = reference.ontology();
        SceneVocabulary vocabulary = new SceneVocabulary(reference);

        // The scene as individuals: what is added here is removed again below.
        List<OWLAxiom> schema = new ArrayList<>(vocabulary.missing());
        Set<OWLObjectProperty> properties = new LinkedHashSet<>();
        assertions.forEach(a -> properties.add(vocabulary.property(a.property())));
        properties.stream().filter(p -> !vocabulary.known(p)).forEach(p -> schema.add(factory.getOWLDeclarationAxiom(p)));
        OWLNamedIndividual sceneIndividual = vocabulary.freshIndividual(SCENE_INDIVIDUAL);
        List<OWLNamedIndividual> elements = new ArrayList<>();
        List<OWLAxiom> individuals = new ArrayList<>();
        individuals.add(factory.getOWLDeclarationAxiom(sceneIndividual));
        individuals.add(factory.getOWLClassAssertionAxiom(vocabulary.scene(), sceneIndividual));
        for (int i = 0; i < scene.elements().size(); i++) {
            OWLNamedIndividual element = vocabulary.freshIndividual(ELEMENT_INDIVIDUAL + (i + 1));
            elements.add(element);
            individuals.add(factory.getOWLDeclarationAxiom(element));
            individuals.add(factory.getOWLClassAssertionAxiom(vocabulary.shape(scene.elements().get(i).shape()), element));
        }
        if (elements.size() > 1) {
            // Cardinalities count distinct elements only if they are known to be distinct (no unique name assumption).
            individuals.add(factory.getOWLDifferentIndividualsAxiom(elements));
        }
        for (SceneAssertion assertion : assertions) {
            individuals.add(factory.getOWLObjectPropertyAssertionAxiom(vocabulary.property(assertion.property()),
                    sceneIndividual, elements.get(assertion.object())));
        }
        List<OWLAxiom> addedSchema = absent(ontology, schema);
        List<OWLAxiom> addedIndividuals = absent(ontology, individuals);
        reference.enact(additions(ontology, addedSchema, addedIndividuals));

        List<Recognition> recognitions = recognise(reference, vocabulary, sceneIndividual, assertions.size());
        boolean learn = recognitions.stream().noneMatch(r -> r.similarity() > threshold);

        List<OWLOntologyChange> undo = new ArrayList<>();
        addedIndividuals.forEach(axiom -> undo.add(new RemoveAxiom(ontology, axiom)));
        Optional<OWLClass> learned = Optional.empty();
        Optional<SceneDefinition> definition = Optional.empty();
        if (learn) {
            SceneDefinition learnedDefinition = SceneDefinition.of(scene, facts);
            OWLClass learnedClass = learn(vocabulary, ontology, learnedDefinition, undo);
            learned = Optional.of(learnedClass);
            definition = Optional.of(learnedDefinition);
        } else {
            addedSchema.forEach(axiom -> undo.add(new RemoveAxiom(ontology, axiom)));
        }
        reference.enact(undo);
        return new Outcome(scene, facts, assertions.size(), recognitions, learned, definition);
    }

    private static List<OWLOntologyChange> additions(OWLOntology ontology, List<OWLAxiom> schema,
                                                     List<OWLAxiom> individuals) {
        List<OWLOntologyChange> changes = new ArrayList<>();
        schema.forEach(axiom -> changes.add(new AddAxiom(ontology, axiom)));
        individuals.forEach(axiom -> changes.add(new AddAxiom(ontology, axiom)));
        return changes;
    }

    /** The axioms the ontology does not hold yet: only those are removed again. */
    private static List<OWLAxiom> absent(OWLOntology ontology, List<OWLAxiom> axioms) {
        return axioms.stream().distinct().filter(axiom -> !ontology.containsAxiom(axiom)).toList();
    }

    /** The scene individual's classes but SCENE itself (and owl:Thing), each with its similarity. */
    private static List<Recognition> recognise(SceneReference reference, SceneVocabulary vocabulary,
                                               OWLNamedIndividual sceneIndividual, int cardinality) {
        List<Recognition> recognitions = new ArrayList<>();
        for (OWLClass owlClass : reference.types(sceneIndividual)) {
            if (owlClass.isOWLThing() || owlClass.equals(vocabulary.scene())) {
                continue;
            }
            Optional<SceneDefinition> definition = definitionOf(reference.ontology(), owlClass);
            int classCardinality = definition.map(SceneDefinition::cardinality).orElse(0);
            double similarity = Math.min(1.0, (double) classCardinality / cardinality);
            recognitions.add(new Recognition(owlClass, similarity, definition));
        }
        recognitions.sort(Comparator.comparingDouble(Recognition::similarity).reversed()
                .thenComparing(r -> r.owlClass().getIRI().toString()));
        return recognitions;
    }

    /** The scene definition a class is stated equivalent to, if it has one. */
    public static Optional<SceneDefinition> definitionOf(OWLOntology ontology, OWLClass owlClass) {
        return ontology.equivalentClassesAxioms(owlClass)
                .flatMap(axiom -> axiom.getClassExpressionsMinus(owlClass).stream())
                .map(SceneDefinition::read).flatMap(Optional::stream).findFirst();
    }

    /** A new class SCENE-n under SCENE, equivalent to the definition; the counter moves to n. */
    private static OWLClass learn(SceneVocabulary vocabulary, OWLOntology ontology, SceneDefinition definition,
                                  List<OWLOntologyChange> changes) {
        OWLDataFactory factory = ontology.getOWLOntologyManager().getOWLDataFactory();
        int number = vocabulary.lastNumber() + 1;
        OWLClass learned = vocabulary.learnedClass(number);
        while (vocabulary.known(learned)) {
            learned = vocabulary.learnedClass(++number);
        }
        List<OWLClassExpression> restrictions = new ArrayList<>();
        for (SceneDefinition.Restriction restriction : definition.restrictions()) {
            restrictions.add(factory.getOWLObjectMinCardinality(restriction.min(),
                    vocabulary.property(restriction.property()), vocabulary.shape(restriction.type())));
        }
        OWLClassExpression expression = restrictions.size() == 1 ? restrictions.get(0)
                : factory.getOWLObjectIntersectionOf(restrictions);
        changes.add(new AddAxiom(ontology, factory.getOWLDeclarationAxiom(learned)));
        changes.add(new AddAxiom(ontology, factory.getOWLSubClassOfAxiom(learned, vocabulary.scene())));
        changes.add(new AddAxiom(ontology, factory.getOWLEquivalentClassesAxiom(learned, expression)));
        vocabulary.counterAxioms().forEach(axiom -> changes.add(new RemoveAxiom(ontology, axiom)));
        changes.add(new AddAxiom(ontology, vocabulary.counterAxiom(number)));
        return learned;
    }
}
