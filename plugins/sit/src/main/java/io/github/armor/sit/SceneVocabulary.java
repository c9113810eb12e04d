// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.OWLAnnotationAssertionAxiom;
import org.semanticweb.owlapi.model.OWLAnnotationProperty;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.parameters.Imports;

/**
 * The names scenes are written with in one reference, resolved as its commands resolve plain
 * names (so a loaded simpleSIT.owl's own SCENE, SPHERE, ... are used), and the axioms that
 * declare what is missing: SCENE; GEOMETRIC-PRIMITIVE, disjoint with it; SPHERE and ORIENTABLE
 * under it; PLANE, CONE and CYLINDER under ORIENTABLE; the four primitives pairwise disjoint.
 */
final class SceneVocabulary {
    static final String SCENE = "SCENE";
    static final String PRIMITIVE = "GEOMETRIC-PRIMITIVE";
    static final String ORIENTABLE = "ORIENTABLE";
    /** The annotation on SCENE that keeps the number of the last learned class: numbers are never reused. */
    static final String COUNTER = "lastLearnedScene";
    private static final Pattern LEARNED_NAME = Pattern.compile(Pattern.quote(SCENE) + "-(\\d+)");

    private final SceneReference reference;
    private final OWLDataFactory factory;
    private final OWLOntology ontology;
    private final OWLClass scene;
    private final OWLClass primitive;
    private final OWLClass orientable;
    private final Map<Shape, OWLClass> shapes = new EnumMap<>(Shape.class);
    private final OWLAnnotationProperty counter;

    SceneVocabulary(SceneReference reference) {
        this.reference = reference;
        this.factory = reference.factory();
        this.ontology = reference.ontology();
        this.scene = owlClass(SCENE);
        this.primitive = owlClass(PRIMITIVE);
        this.orientable = owlClass(ORIENTABLE);
        for (Shape shape : Shape.values()) {
            shapes.put(shape, owlClass(shape.name()));
        }
        this.counter = factory.getOWLAnnotationProperty(reference.iri(EntityType.ANNOTATION_PROPERTY, COUNTER));
    }

    private OWLClass owlClass(String name) {
        return factory.getOWLClass(reference.iri(EntityType.CLASS, name));
    }

    OWLClass scene() {
        return scene;
    }

    OWLClass shape(Shape shape) {
        return shapes.get(shape);
    }

    OWLObjectProperty property(Relation.Property property) {
        return factory.getOWLObjectProperty(reference.iri(EntityType.OBJECT_PROPERTY, property.name()));
    }

    boolean known(OWLEntity entity) {
        return ontology.containsEntityInSignature(entity, Imports.INCLUDED);
    }

    /** An individual of this name, or of it with a suffix, that the reference does not know. */
    OWLNamedIndividual freshIndividual(String name) {
        OWLNamedIndividual individual = factory.getOWLNamedIndividual(reference.iri(EntityType.NAMED_INDIVIDUAL, name));
        for (int suffix = 2; known(individual); suffix++) {
            individual = factory.getOWLNamedIndividual(reference.iri(EntityType.NAMED_INDIVIDUAL, name + "-" + suffix));
        }
        return individual;
    }

    /** The declarations and axioms of the classes above, for those the reference does not know yet. */
    List<OWLAxiom> missing() {
        List<OWLAxiom> axioms = new ArrayList<>();
        boolean anyShapeMissing = shapes.values().stream().anyMatch(c -> !known(c));
        if (!known(scene)) {
            axioms.add(factory.getOWLDeclarationAxiom(scene));
        }
        if (!known(primitive)) {
            axioms.add(factory.getOWLDeclarationAxiom(primitive));
            axioms.add(factory.getOWLDisjointClassesAxiom(primitive, scene));
        }
        if (!known(orientable)) {
            axioms.add(factory.getOWLDeclarationAxiom(orientable));
            axioms.add(factory.getOWLSubClassOfAxiom(orientable, primitive));
        }
        for (Shape shape : Shape.values()) {
            OWLClass owlClass = shapes.get(shape);
            if (!known(owlClass)) {
                axioms.add(factory.getOWLDeclarationAxiom(owlClass));
                axioms.add(factory.getOWLSubClassOfAxiom(owlClass, shape.orientable() ? orientable : primitive));
            }
        }
        if (anyShapeMissing) {
            axioms.add(factory.getOWLDisjointClassesAxiom(shapes.values()));
        }
        return axioms;
    }

    /** The number the last learned class took here (0 before the first). */
    int lastNumber() {
        int last = 0;
        for (OWLAnnotationAssertionAxiom axiom : counterAxioms()) {
            Optional<Integer> value = axiom.getValue().asLiteral().flatMap(literal -> {
                try {
                    return Optional.of(Integer.parseInt(literal.getLiteral().trim()));
                } catch (NumberFormatException e) {
                    return Optional.empty();
                }
            });
            last = Math.max(last, value.orElse(0));
        }
        // Classes named SCENE-<n> by hand or from another reference's file count too.
        for (OWLClass owlClass : ontology.getClassesInSignature(Imports.INCLUDED)) {
            OptionalInt number = learnedNumber(owlClass);
            if (number.isPresent()) {
                last = Math.max(last, number.getAsInt());
            }
        }
        return last;
    }

    /** The n of a class named SCENE-n. */
    static OptionalInt learnedNumber(OWLClass owlClass) {
        Matcher matcher = LEARNED_NAME.matcher(owlClass.getIRI().getShortForm());
        if (!matcher.matches()) {
            return OptionalInt.empty();
        }
        try {
            return OptionalInt.of(Integer.parseInt(matcher.group(1)));
        } catch (NumberFormatException e) {
            return OptionalInt.empty();
        }
    }

    OWLClass learnedClass(int number) {
        return owlClass(SCENE + "-" + number);
    }

    /** The counter's annotations as they are now (to be replaced). */
    List<OWLAnnotationAssertionAxiom> counterAxioms() {
        return ontology.annotationAssertionAxioms(scene.getIRI(), Imports.INCLUDED)
                .filter(axiom -> axiom.getProperty().equals(counter)).toList();
    }

    OWLAnnotationAssertionAxiom counterAxiom(int number) {
        return factory.getOWLAnnotationAssertionAxiom(counter, scene.getIRI(), factory.getOWLLiteral(number));
    }
}
