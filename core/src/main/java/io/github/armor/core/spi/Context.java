// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.util.List;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntologyChange;

/**
 * What a plugin's handler sees of one directive: its arguments, read as the built-in commands
 * read them; the knowledge of its reference; the ways to change it; and answers.
 */
public interface Context {
    Directive directive();

    List<String> args();

    String arg(int index);

    /** Whether the argument is given and not empty. */
    boolean hasArg(int index);

    /** A true/false argument, any case; empty is false; anything else is refused (207). */
    boolean flag(int index);

    /** The individual an argument names (a name the reference does not know is noted in the answer). */
    OWLNamedIndividual individual(int index);

    OWLClass owlClass(int index);

    OWLObjectProperty objectProperty(int index);

    OWLDataProperty dataProperty(int index);

    /** A Manchester class expression argument. */
    OWLClassExpression classExpression(int index);

    /** A literal from a (type, value) argument pair. */
    OWLLiteral literal(int typeIndex, int valueIndex);

    /** The directive's reference, read-only; a command that needs no reference has none (IllegalStateException). */
    Knowledge knowledge();

    /**
     * Submits changes to the reference as the built-in manipulations do (queued under buffered
     * manipulation) and answers success; a failure or a list's rollback undoes them.
     */
    Response change(List<? extends OWLOntologyChange> changes);

    /**
     * Applies changes now, whatever the buffering, after the changes still waiting: for a
     * command that reasons about what it has just changed. Undone as {@link #change} is.
     */
    void enact(List<? extends OWLOntologyChange> changes);

    /** The checks of the paths a client names, to read or to write. */
    Paths paths();

    /** Whether this is a journal record replayed at start rather than a client's request. */
    boolean replaying();

    /** An entity as the core writes it in answers (short or full IRI, per {@code full_entity_iri}). */
    String render(OWLEntity entity);

    /** Entities as the core writes them, sorted. */
    List<String> render(Stream<? extends OWLEntity> entities);

    /** A success answering {@code objects}, with the reference's consistency. */
    Response ok(List<String> objects);

    Response ok();
}
