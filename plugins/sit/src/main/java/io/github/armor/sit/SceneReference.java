// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.List;
import java.util.Set;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;

/**
 * What the scene logic needs of the reference a directive runs on, and nothing more: the one
 * seam between this plugin and the core (SitCommands implements it over the core's plugin
 * interface). Every call happens under the reference's lock, within the directive's transaction.
 */
public interface SceneReference {
    /** The ontology, to read (changes go through {@link #enact}). */
    OWLOntology ontology();

    OWLDataFactory factory();

    /** The IRI a plain name has in this reference, resolved as its commands resolve names. */
    IRI iri(EntityType<?> type, String name);

    /**
     * Applies the changes to the ontology at once, even on a reference whose changes wait for
     * APPLY (those waiting are applied first, as APPLY would). If the directive fails later, they
     * are undone with everything else it did.
     */
    void enact(List<OWLOntologyChange> changes);

    /**
     * The named classes the individual belongs to, asserted or inferred, direct or not, from the
     * reference's reasoner brought up to date first (a buffered one too).
     */
    Set<OWLClass> types(OWLNamedIndividual individual);

    /** Whether the reference is consistent, as its reasoner last found. */
    boolean consistent();

    /** Makes reasoners of the reference's kind (for reasoning on part of its schema alone). */
    OWLReasonerFactory reasonerFactory();

    /** The same object for as long as the reference stays loaded (a key for what is kept about it). */
    Object identity();

    /** The named superclasses of a class, asserted or inferred, direct or not (not itself). */
    Set<OWLClass> superClasses(OWLClass owlClass);

    /** The named classes equivalent to a class, asserted or inferred (not itself). */
    Set<OWLClass> equivalentClasses(OWLClass owlClass);

}
