// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.WeakHashMap;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLEquivalentClassesAxiom;
import org.semanticweb.owlapi.model.OWLObjectIntersectionOf;
import org.semanticweb.owlapi.model.OWLObjectMinCardinality;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLSubClassOfAxiom;
import org.semanticweb.owlapi.model.parameters.Imports;

/**
 * The scene classes a reference has learned: the subclasses of SCENE stated equivalent to a scene
 * definition, each with the restrictions it requires, and the scene properties of the reference
 * (every object property named like one: {@code rightSPHERE}, ...).
 *
 * <p>Whether the reference is <em>plain</em>: no axiom but a learned class's own declaration,
 * definition and place under SCENE mentions a learned class, and none but declarations and those
 * definitions mentions a scene property. In a plain reference a scene's membership of a learned
 * class follows from its assertions alone ({@link #recognised}): the definitions are the only
 * axioms about those names, so a scene is an instance exactly when it has, for each restriction,
 * that many distinct related elements of a type the filler subsumes (docs/scenes.md).
 */
final class LearnedScenes {
    /** {@code property min min filler}, as the class's definition states it. */
    record Requirement(OWLObjectProperty property, OWLClass filler, int min) {}

    /** A learned class: its definition read two ways (for words, and entity by entity for counting), and its axiom. */
    record Learned(OWLClass owlClass, SceneDefinition definition, List<Requirement> requirements,
                   OWLEquivalentClassesAxiom axiom) {}

    private final Map<OWLClass, Learned> learned;
    private final Set<OWLObjectProperty> sceneProperties;
    private final Set<OWLAxiom> definitions = new HashSet<>();
    private final boolean plain;

    private LearnedScenes(Map<OWLClass, Learned> learned, Set<OWLObjectProperty> sceneProperties, OWLOntology ontology,
                          OWLClass scene) {
        this.learned = learned;
        this.sceneProperties = sceneProperties;
        learned.values().forEach(each -> definitions.add(each.axiom()));
        this.plain = plainIn(ontology, scene);
    }

    // By the reference's identity: ontologies are equal when their IRIs are, whatever they hold.
    private static final Map<Object, Kept> KEPT = new WeakHashMap<>();

    /** What was found at a version of an ontology, for a SCENE class. */
    private record Kept(long version, OWLClass scene, LearnedScenes found) {}

    /** The learned classes of the reference, read again only when its ontology changed. */
    static LearnedScenes of(SceneReference reference, OWLClass scene) {
        OWLOntology ontology = reference.ontology();
        long version = OntologyVersions.of(ontology);
        synchronized (KEPT) {
            Kept kept = KEPT.get(reference.identity());
            if (kept != null && kept.version() == version && kept.scene().equals(scene)) {
                return kept.found();
            }
        }
        LearnedScenes found = read(ontology, scene);
        synchronized (KEPT) {
            KEPT.put(reference.identity(), new Kept(version, scene, found));
        }
        return found;
    }

    private static LearnedScenes read(OWLOntology ontology, OWLClass scene) {
        Map<OWLClass, Learned> learned = new LinkedHashMap<>();
        ontology.importsClosure().flatMap(o -> o.subClassAxiomsForSuperClass(scene))
                .filter(axiom -> !axiom.getSubClass().isAnonymous())
                .map(axiom -> axiom.getSubClass().asOWLClass()).distinct()
                .sorted(Comparator.comparingInt((OWLClass c) -> SceneVocabulary.learnedNumber(c).orElse(Integer.MAX_VALUE))
                        .thenComparing(c -> c.getIRI().toString()))
                .forEach(owlClass -> definitionOf(ontology, owlClass).ifPresent(found -> learned.put(owlClass, found)));
        Set<OWLObjectProperty> properties = new LinkedHashSet<>();
        ontology.objectPropertiesInSignature(Imports.INCLUDED)
                .filter(p -> Relation.ofProperty(p.getIRI().getShortForm()).isPresent()).forEach(properties::add);
        return new LearnedScenes(learned, properties, ontology, scene);
    }

    /** The learned class's definition, if it states one (one EquivalentClasses with a scene definition). */
    private static Optional<Learned> definitionOf(OWLOntology ontology, OWLClass owlClass) {
        return ontology.importsClosure().flatMap(o -> o.equivalentClassesAxioms(owlClass))
                .filter(axiom -> axiom.classExpressions().count() == 2)
                .map(axiom -> {
                    OWLClassExpression expression = axiom.getClassExpressionsMinus(owlClass).iterator().next();
                    return SceneDefinition.read(expression)
                            .map(definition -> new Learned(owlClass, definition, requirements(expression), axiom));
                })
                .flatMap(Optional::stream).findFirst();
    }

    private static List<Requirement> requirements(OWLClassExpression expression) {
        List<OWLClassExpression> parts = expression instanceof OWLObjectIntersectionOf intersection
                ? intersection.getOperandsAsList() : List.of(expression);
        List<Requirement> requirements = new ArrayList<>();
        for (OWLClassExpression part : parts) {
            OWLObjectMinCardinality min = (OWLObjectMinCardinality) part;
            requirements.add(new Requirement(min.getProperty().asOWLObjectProperty(), min.getFiller().asOWLClass(),
                    min.getCardinality()));
        }
        return requirements;
    }

    List<Learned> classes() {
        return List.copyOf(learned.values());
    }

    Optional<Learned> get(OWLClass owlClass) {
        return Optional.ofNullable(learned.get(owlClass));
    }

    /** Learned classes and scene properties: what the rest of the schema is reasoned on without. */
    boolean mentionsScenes(OWLAxiom axiom) {
        return axiom.classesInSignature().anyMatch(learned::containsKey)
                || axiom.objectPropertiesInSignature().anyMatch(sceneProperties::contains);
    }

    boolean plain() {
        return plain;
    }

    private boolean plainIn(OWLOntology ontology, OWLClass scene) {
        for (Learned each : learned.values()) {
            boolean onlyItsOwn = ontology.referencingAxioms(each.owlClass(), Imports.INCLUDED).allMatch(axiom ->
                    axiom.isOfType(AxiomType.DECLARATION) || axiom.isOfType(AxiomType.ANNOTATION_ASSERTION)
                            || isDefinition(axiom)
                            || axiom instanceof OWLSubClassOfAxiom sub && sub.getSubClass().equals(each.owlClass())
                            && sub.getSuperClass().equals(scene));
            if (!onlyItsOwn) {
                return false;
            }
        }
        for (OWLObjectProperty property : sceneProperties) {
            if (!ontology.referencingAxioms(property, Imports.INCLUDED).allMatch(axiom ->
                    axiom.isOfType(AxiomType.DECLARATION) || axiom.isOfType(AxiomType.ANNOTATION_ASSERTION)
                            || isDefinition(axiom))) {
                return false;
            }
        }
        return true;
    }

    /** A learned class's definition. */
    private boolean isDefinition(OWLAxiom axiom) {
        return definitions.contains(axiom);
    }

    /**
     * Whether {@code general} subsumes {@code specific} when the primitives are pairwise disjoint
     * and apart: every requirement of the general one is met by the specific one's on the same
     * property and filler with at least as large a minimum.
     */
    boolean subsumes(Learned general, Learned specific) {
        for (Requirement wanted : general.requirements()) {
            boolean met = specific.requirements().stream().anyMatch(r -> r.property().equals(wanted.property())
                    && r.filler().equals(wanted.filler()) && r.min() >= wanted.min());
            if (!met) {
                return false;
            }
        }
        return true;
    }

    /**
     * In a plain reference, the learned classes a scene is an instance of: those whose every
     * requirement it meets, counting distinct elements related by the property whose type the
     * filler subsumes ({@code typesOf} gives each element's named types in the rest of the schema).
     */
    List<OWLClass> recognised(Map<OWLObjectProperty, List<Integer>> objectsByProperty,
                              List<Set<OWLClass>> typesOfElements) {
        List<OWLClass> recognised = new ArrayList<>();
        for (Learned each : learned.values()) {
            boolean met = true;
            for (Requirement requirement : each.requirements()) {
                long counted = objectsByProperty.getOrDefault(requirement.property(), List.of()).stream()
                        .filter(element -> typesOfElements.get(element).contains(requirement.filler())).count();
                if (counted < requirement.min()) {
                    met = false;
                    break;
                }
            }
            if (met) {
                recognised.add(each.owlClass());
            }
        }
        return recognised;
    }
}
