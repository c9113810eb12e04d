// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.EnumMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import java.util.WeakHashMap;
import java.util.stream.Stream;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLObjectHasValue;
import org.semanticweb.owlapi.model.OWLObjectOneOf;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasoner;

/**
 * What the rest of a reference's schema says of a scene and its elements: the schema without the
 * learned classes and scene properties, reasoned on once by a private reasoner of the reference's
 * kind and kept until that part changes. It gives the named classes a scene is an instance of
 * besides the learned ones (those SCENE is a subclass of) and the named types of each primitive.
 *
 * <p>Learned definitions only define new names from new properties, so leaving them out changes
 * nothing about the other names; a fresh scene is tied to the rest by its types alone, unless the
 * schema has nominals, rules, keys or the universal property ({@link #usable} is then false and the
 * scene is reasoned on inside the reference instead).
 */
final class SceneSchema {
    private static final Map<Object, SceneSchema> KEPT = new WeakHashMap<>();

    private final Set<OWLAxiom> axioms;
    private final boolean usable;
    private final Set<OWLClass> sceneTypes;
    private final Map<Shape, Set<OWLClass>> shapeTypes;
    private final boolean shapesApart;
    private long version = -1;

    private SceneSchema(Set<OWLAxiom> axioms, boolean usable, Set<OWLClass> sceneTypes,
                        Map<Shape, Set<OWLClass>> shapeTypes, boolean shapesApart) {
        this.axioms = axioms;
        this.usable = usable;
        this.sceneTypes = sceneTypes;
        this.shapeTypes = shapeTypes;
        this.shapesApart = shapesApart;
    }

    private static SceneSchema unusable(Set<OWLAxiom> axioms) {
        return new SceneSchema(axioms, false, Set.of(), Map.of(), false);
    }

    /** The reference's, made again only when the rest of its schema changed. */
    static SceneSchema of(SceneReference reference, SceneVocabulary vocabulary, LearnedScenes learned) {
        OWLOntology ontology = reference.ontology();
        long version = OntologyVersions.of(ontology);
        synchronized (KEPT) {
            SceneSchema kept = KEPT.get(reference.identity());
            if (kept != null && kept.version == version) {
                return kept;
            }
        }
        // With the vocabulary a learned class would bring, so that the rest's reasoner knows SCENE and the primitives.
        Set<OWLAxiom> rest = new LinkedHashSet<>(vocabulary.missing());
        Stream.of(ontology.tboxAxioms(Imports.INCLUDED), ontology.rboxAxioms(Imports.INCLUDED),
                        ontology.axioms(AxiomType.SWRL_RULE, Imports.INCLUDED)).flatMap(s -> s)
                .filter(axiom -> !learned.mentionsScenes(axiom)).forEach(rest::add);
        SceneSchema made;
        synchronized (KEPT) {
            SceneSchema kept = KEPT.get(reference.identity());
            made = kept != null && kept.axioms.equals(rest) ? kept.at(version) : null;
        }
        if (made == null) {
            made = reason(reference, vocabulary, rest).at(version);
        }
        synchronized (KEPT) {
            KEPT.put(reference.identity(), made);
        }
        return made;
    }

    /** The same facts, known to hold at this version of the ontology. */
    private SceneSchema at(long atVersion) {
        SceneSchema same = new SceneSchema(axioms, usable, sceneTypes, shapeTypes, shapesApart);
        same.version = atVersion;
        return same;
    }

    private static SceneSchema reason(SceneReference reference, SceneVocabulary vocabulary, Set<OWLAxiom> rest) {
        if (rest.stream().anyMatch(SceneSchema::obstacle)) {
            return unusable(rest);
        }
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        OWLReasoner reasoner = null;
        try {
            OWLOntology ontology = manager.createOntology(rest.stream());
            reasoner = reference.reasonerFactory().createReasoner(ontology);
            OWLReasoner asked = reasoner;
            if (!asked.isConsistent() || !asked.isSatisfiable(vocabulary.scene())) {
                return unusable(rest);
            }
            Map<Shape, Set<OWLClass>> shapes = new EnumMap<>(Shape.class);
            for (Shape shape : Shape.values()) {
                OWLClass owlClass = vocabulary.shape(shape);
                if (!asked.isSatisfiable(owlClass)) {
                    return unusable(rest);
                }
                shapes.put(shape, typesOf(asked, owlClass));
            }
            boolean apart = true;
            for (Shape one : Shape.values()) {
                for (Shape other : Shape.values()) {
                    apart &= one == other || !shapes.get(one).contains(vocabulary.shape(other))
                            && asked.isEntailed(reference.factory().getOWLDisjointClassesAxiom(
                                    vocabulary.shape(one), vocabulary.shape(other)));
                }
            }
            return new SceneSchema(rest, true, typesOf(asked, vocabulary.scene()), shapes, apart);
        } catch (OWLOntologyCreationException | RuntimeException e) {
            // A reasoner that cannot take the rest alone: the scene is reasoned on in the reference.
            return unusable(rest);
        } finally {
            if (reasoner != null) {
                reasoner.dispose();
            }
        }
    }

    /** The class, its equivalents and its named superclasses (owl:Thing left out). */
    private static Set<OWLClass> typesOf(OWLReasoner reasoner, OWLClass owlClass) {
        Set<OWLClass> types = new LinkedHashSet<>();
        types.add(owlClass);
        reasoner.getEquivalentClasses(owlClass).entities().forEach(types::add);
        reasoner.getSuperClasses(owlClass, false).entities().forEach(types::add);
        types.removeIf(OWLClass::isOWLThing);
        return Set.copyOf(types);
    }

    /** What ties a fresh individual to others, or leaves the schema to rules: then the reference reasons. */
    private static boolean obstacle(OWLAxiom axiom) {
        if (axiom.isOfType(AxiomType.SWRL_RULE) || axiom.isOfType(AxiomType.HAS_KEY)) {
            return true;
        }
        if (axiom.objectPropertiesInSignature().anyMatch(p -> p.isOWLTopObjectProperty())
                || axiom.dataPropertiesInSignature().anyMatch(p -> p.isOWLTopDataProperty())) {
            return true;
        }
        return axiom.nestedClassExpressions().anyMatch(SceneSchema::nominal);
    }

    private static boolean nominal(OWLClassExpression expression) {
        return expression instanceof OWLObjectOneOf || expression instanceof OWLObjectHasValue;
    }

    boolean usable() {
        return usable;
    }

    /** The named classes other than the learned ones a scene belongs to: SCENE and what it is a subclass of. */
    Set<OWLClass> sceneTypes() {
        return sceneTypes;
    }

    /** Whether the primitives' classes are pairwise disjoint and none is under another. */
    boolean shapesApart() {
        return usable && shapesApart;
    }

    /** The named types of a primitive of this shape: its class and what it is a subclass of. */
    Set<OWLClass> typesOf(Shape shape) {
        return shapeTypes.get(shape);
    }
}
