// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

import io.github.armor.core.api.Directive;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;

/**
 * What a {@link StateAnswer} reads while another directive holds the reference: the directive,
 * and the types its reasoner last published (the state QUERY IND CLASS answers from then),
 * never the live ontology, which the writer is changing (the answer's description names the
 * state's revision). It is consistent: the core answers an inconsistent state's questions itself.
 */
public interface PublishedState {
    Directive directive();

    default List<String> args() {
        return directive().args();
    }

    default String arg(int index) {
        return args().get(index);
    }

    /** The entity a client's name means, when the state knows it; empty otherwise (wait for the reference). */
    <E extends OWLEntity> Optional<E> known(EntityType<E> type, String name);

    /** The named instances of a class the state knows, asserted and inferred. */
    List<OWLNamedIndividual> instances(OWLClass owlClass);

    /** The classes of an individual the state knows, all or the most specific only; empty when it cannot say. */
    Optional<Set<OWLClass>> classesOf(OWLNamedIndividual individual, boolean direct);

    /** Entities as the core writes them in answers, sorted. */
    List<String> render(Stream<? extends OWLEntity> entities);
}
