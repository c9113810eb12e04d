// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.HashSet;
import java.util.Set;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.parameters.Imports;

/**
 * Which classes the modules' individuals are realised against, with every change.
 *
 * <p>A reference whose ontology stands alone is realised against every class, as before: its
 * classes are its own, and realising them all once per module costs less than asking class by
 * class. A reference that imports an upper ontology (SOMA and DUL: hundreds of classes, each
 * individual's reasoning costing seconds) is realised against its own classes (those its own
 * schema axioms and declarations name) and the classes clients asked about since it was loaded
 * (a QUERY IND CLASS, a subscription): a question about another class adds it, and the modules
 * are realised again, once. The types of one individual against every class (QUERY CLASS IND,
 * the web view's individual) are found when asked, for its module alone, and kept until a change
 * touches the module.
 */
public final class RealisationScope {
    private final boolean everyClass;
    private final Set<OWLClass> tracked;

    private RealisationScope(boolean everyClass, Set<OWLClass> tracked) {
        this.everyClass = everyClass;
        this.tracked = tracked;
    }

    /**
     * The scope of an ontology: every class, or, when it imports classes it does not name itself,
     * its own ones and those {@code asked} about.
     */
    static RealisationScope of(OWLOntology ontology, Set<OWLClass> asked) {
        Set<OWLClass> own = ownClasses(ontology);
        boolean imported = importsClasses(ontology, own);
        if (!imported) {
            return new RealisationScope(true, Set.of());
        }
        own.addAll(asked);
        return new RealisationScope(false, Set.copyOf(own));
    }

    /** Whether an ontology imports classes it does not name itself (an upper ontology's). */
    public static boolean overUpperOntology(OWLOntology ontology) {
        // Asked after every change (durability keeps the hierarchy of one): without imports, no axiom is read.
        return ontology.importsDeclarations().findAny().isPresent() && importsClasses(ontology, ownClasses(ontology));
    }

    private static boolean importsClasses(OWLOntology ontology, Set<OWLClass> own) {
        return ontology.importsDeclarations().findAny().isPresent() && ontology.classesInSignature(Imports.INCLUDED)
                .anyMatch(owlClass -> !owlClass.isBuiltIn() && !own.contains(owlClass));
    }

    /** The classes the ontology's own schema axioms and declarations name (its imports' aside). */
    static Set<OWLClass> ownClasses(OWLOntology ontology) {
        Set<OWLClass> own = ontology.axioms(Imports.EXCLUDED)
                .filter(axiom -> axiom.isOfType(AxiomType.DECLARATION)
                        || axiom.isLogicalAxiom() && !axiom.isOfType(AxiomType.ABoxAxiomTypes))
                .flatMap(OWLAxiom::classesInSignature).filter(owlClass -> !owlClass.isBuiltIn())
                .collect(Collectors.toCollection(HashSet::new));
        return own;
    }

    /** Whether every class is realised (the ontology stands alone). */
    boolean everyClass() {
        return everyClass;
    }

    /** The classes realised with every change when not every class is; empty otherwise. */
    Set<OWLClass> tracked() {
        return tracked;
    }

    /** Whether the kept types answer "instances of {@code owlClass}" without realising it first. */
    boolean answers(OWLClass owlClass) {
        return everyClass || owlClass.isOWLThing() || tracked.contains(owlClass);
    }
}
