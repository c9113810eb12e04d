// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

import java.util.Set;
import java.util.function.Function;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;

/**
 * A reference's knowledge as a plugin reads it, while its directive holds the reference: the
 * ontology (to read: changes go through {@link Context#change}), its factory, its reasoner and
 * its names. Valid only during the directive.
 */
public interface Knowledge {
    /** The reference's name. */
    String name();

    /** The ontology; read it only (a change made on it directly is neither journaled nor undone). */
    OWLOntology ontology();

    /** The ontology and its imports. */
    Stream<OWLOntology> closure();

    OWLDataFactory factory();

    /**
     * What the reasoner answers, guarded by the reasoner's time limit; nothing when this reasoner
     * cannot answer that kind of question (ELK has no property-value queries).
     */
    <T> Stream<T> inferred(Function<OWLReasoner, Stream<T>> question);

    /** The named instances of a class expression, asserted and inferred, as QUERY IND CLASS answers. */
    Set<OWLNamedIndividual> instances(OWLClassExpression owlClass, boolean direct);

    /** Brings a buffered reasoner up to date with the ontology (after {@link Context#enact}). */
    void synchroniseReasoner();

    boolean consistent();

    /** A new reasoner of the reference's kind, for a plugin's own scratch ontologies. */
    OWLReasonerFactory reasonerFactory();

    /** The IRI a client's name means (prefixes and the default namespace applied). */
    IRI iri(EntityType<?> type, String name);

    /** The entity a client's name means. */
    <E extends OWLEntity> E entity(EntityType<E> type, String name);

    /** Whether the ontology mentions the entity. */
    boolean knows(OWLEntity entity);

    /** An unknown name described for an error message, with the closest known ones. */
    String describeUnknown(EntityType<?> type, String name);

    /** The same object for every directive on this reference while it stays loaded (a cache key). */
    Object identity();
}
