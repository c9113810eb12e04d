// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
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
 * Scene identification and tagging on one reference (docs/scenes.md): the scene is an individual
 * related to its elements, classified under the scene classes learned so far (recognition, each
 * class with its similarity), and when none is similar enough a new class is learned from it. Only
 * a learned class (and the vocabulary it needs) stays. The caller runs this as one directive, so
 * a failure anywhere undoes all of it.
 *
 * <p>Two ways to the same recognitions. In a plain reference ({@link LearnedScenes}) the scene's
 * learned classes follow from its assertions by counting, and its other classes from the rest of
 * the schema, reasoned on apart and kept ({@link SceneSchema}): the scene never enters the
 * reference, whose reasoner (which would classify every learned class again for each scene) is
 * not asked. Otherwise the scene's individuals are added to the reference, its reasoner is asked
 * for their types, and they are removed again.
 */
public final class SceneTeacher {
    private static final String SCENE_INDIVIDUAL = "sit-scene";
    private static final String ELEMENT_INDIVIDUAL = "sit-element-";

    private SceneTeacher() {}

    /** A class the scene was recognised as: its similarity card(class) / card(scene), and its definition if learned. */
    public record Recognition(OWLClass owlClass, double similarity, Optional<SceneDefinition> definition) {}

    /**
     * What one scene gave: its facts and cardinality, the classes it was recognised as (most
     * similar first), the class learned from it, if any, and whether the reference's reasoner was asked.
     */
    public record Outcome(Scene scene, List<SpatialRelations.Fact> facts, int cardinality,
                          List<Recognition> recognitions, Optional<OWLClass> learned,
                          Optional<SceneDefinition> learnedDefinition, boolean inReference) {}

    /**
     * Recognises the scene and learns it unless a recognised class has a similarity above
     * {@code threshold}. A scene with no relation changes nothing and is recognised as nothing.
     */
    public static Outcome evaluate(SceneReference reference, Scene scene, double threshold) {
        List<SpatialRelations.Fact> facts = SpatialRelations.of(scene);
        List<SceneAssertion> assertions = SceneAssertion.of(scene, facts);
        if (assertions.isEmpty()) {
            return new Outcome(scene, facts, 0, List.of(), Optional.empty(), Optional.empty(), false);
        }
        OWLOntology ontology = reference.ontology();
        SceneVocabulary vocabulary = new SceneVocabulary(reference);
        LearnedScenes learned = LearnedScenes.of(reference, vocabulary.scene());
        List<OWLAxiom> schema = new ArrayList<>(vocabulary.missing());
        assertions.stream().map(a -> vocabulary.property(a.property())).distinct()
                .filter(p -> !vocabulary.known(p))
                .forEach(p -> schema.add(reference.factory().getOWLDeclarationAxiom(p)));
        List<OWLAxiom> addedSchema = absent(ontology, schema);

        SceneSchema rest = learned.plain() ? SceneSchema.of(reference, vocabulary, learned) : null;
        Set<OWLClass> types;
        List<OWLOntologyChange> changes = new ArrayList<>();
        boolean inReference = rest == null || !rest.usable();
        if (inReference) {
            OWLNamedIndividual sceneIndividual = vocabulary.freshIndividual(SCENE_INDIVIDUAL);
            List<OWLAxiom> individuals = individuals(reference, vocabulary, sceneIndividual, scene, assertions);
            reference.enact(additions(ontology, addedSchema, individuals));
            types = reference.types(sceneIndividual);
            individuals.forEach(axiom -> changes.add(new RemoveAxiom(ontology, axiom)));
        } else {
            if (!reference.consistent()) {
                throw new InvalidScene(InvalidScene.Kind.INCONSISTENT, "the reference is inconsistent, so a scene"
                        + " belongs to every class; QUERY CONSISTENCY explains why");
            }
            types = counted(learned, rest, vocabulary, scene, assertions);
        }
        List<Recognition> recognitions = recognitions(types, vocabulary, learned, assertions.size());
        boolean learn = recognitions.stream().noneMatch(r -> r.similarity() > threshold);

        Optional<OWLClass> learnedClass = Optional.empty();
        Optional<SceneDefinition> definition = Optional.empty();
        if (learn) {
            SceneDefinition learnedDefinition = SceneDefinition.of(scene, facts);
            if (!inReference) {
                addedSchema.forEach(axiom -> changes.add(new AddAxiom(ontology, axiom)));
            }
            learnedClass = Optional.of(learn(vocabulary, ontology, learnedDefinition, changes));
            definition = Optional.of(learnedDefinition);
        } else if (inReference) {
            addedSchema.forEach(axiom -> changes.add(new RemoveAxiom(ontology, axiom)));
        }
        if (!changes.isEmpty()) {
            reference.enact(changes);
        }
        return new Outcome(scene, facts, assertions.size(), recognitions, learnedClass, definition, inReference);
    }

    /** The scene as individuals: axioms to be added to the reference and removed again. */
    private static List<OWLAxiom> individuals(SceneReference reference, SceneVocabulary vocabulary,
                                              OWLNamedIndividual sceneIndividual, Scene scene,
                                              List<SceneAssertion> assertions) {
        OWLDataFactory factory = reference.factory();
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
        return individuals;
    }

    /**
     * The classes a scene belongs to in a plain reference: the learned ones whose requirements its
     * assertions meet, and SCENE with what the rest of the schema puts above it.
     */
    private static Set<OWLClass> counted(LearnedScenes learned, SceneSchema rest, SceneVocabulary vocabulary,
                                         Scene scene, List<SceneAssertion> assertions) {
        Map<OWLObjectProperty, List<Integer>> objects = new LinkedHashMap<>();
        for (SceneAssertion assertion : assertions) {
            objects.computeIfAbsent(vocabulary.property(assertion.property()), p -> new ArrayList<>())
                    .add(assertion.object());
        }
        List<Set<OWLClass>> elementTypes = scene.elements().stream().map(e -> rest.typesOf(e.shape())).toList();
        Set<OWLClass> types = new LinkedHashSet<>(rest.sceneTypes());
        types.addAll(learned.recognised(objects, elementTypes));
        return types;
    }

    private static List<Recognition> recognitions(Set<OWLClass> types, SceneVocabulary vocabulary,
                                                  LearnedScenes learned, int cardinality) {
        List<Recognition> recognitions = new ArrayList<>();
        for (OWLClass owlClass : types) {
            if (owlClass.isOWLThing() || owlClass.equals(vocabulary.scene())) {
                continue;
            }
            Optional<SceneDefinition> definition = learned.get(owlClass).map(LearnedScenes.Learned::definition);
            int classCardinality = definition.map(SceneDefinition::cardinality).orElse(0);
            recognitions.add(new Recognition(owlClass, Math.min(1.0, (double) classCardinality / cardinality),
                    definition));
        }
        recognitions.sort(Comparator.comparingDouble(Recognition::similarity).reversed()
                .thenComparing(r -> r.owlClass().getIRI().toString()));
        return recognitions;
    }

    private static List<OWLOntologyChange> additions(OWLOntology ontology, List<OWLAxiom> schema,
                                                     List<OWLAxiom> individuals) {
        List<OWLOntologyChange> changes = new ArrayList<>();
        schema.forEach(axiom -> changes.add(new AddAxiom(ontology, axiom)));
        individuals.forEach(axiom -> changes.add(new AddAxiom(ontology, axiom)));
        return changes;
    }

    /** The axioms the ontology does not hold yet: only those are added, and removed again. */
    private static List<OWLAxiom> absent(OWLOntology ontology, List<OWLAxiom> axioms) {
        return axioms.stream().distinct().filter(axiom -> !ontology.containsAxiom(axiom)).toList();
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
