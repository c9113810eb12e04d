// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.reasoning.InferredState;
import io.github.armor.core.reasoning.PublishedStates.Published;
import io.github.armor.core.reference.Reference;
import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;

/**
 * Answers from the state a reference's reasoner last published, for the {@link AnswerSource}s
 * of built-in and plugins' queries alike: the rule that a client reads its own writes, and the
 * description naming the state's revision, so a client knows how old the answer is.
 */
public final class PublishedAnswers {
    private PublishedAnswers() {}

    /** What a published state answers: the list it gives, or empty when it cannot answer exactly. */
    @FunctionalInterface
    public interface FromState {
        Optional<List<String>> objects(Reference reference, InferredState state, Predicate<OWLEntity> known);
    }

    /** The answer from the published state, or empty when the directive must wait for the reference. */
    public static Optional<Response> fromPublished(CommandContext context, FromState answer) {
        Reference reference = context.reference();
        Optional<Published> published = reference.publishedState();
        // A client reads its own writes: a state older than its last change is no answer for it.
        if (published.isEmpty() || published.get().revision()
                < reference.changeHistory().lastRevisionOf(context.directive().clientName())) {
            return Optional.empty();
        }
        InferredState state = published.get().state();
        Predicate<OWLEntity> known = entity -> entity instanceof OWLClass owlClass ? state.knows(owlClass)
                : entity instanceof OWLNamedIndividual individual && state.knows(individual);
        try {
            return answer.objects(reference, state, known).map(list -> Response.ok(state.consistent(), list)
                    .withDescription(note(published.get(), reference)));
        } catch (ArmorException e) {
            if (e.exitCode() != ExitCode.INCONSISTENT) {
                return Optional.empty();
            }
            return Optional.of(Response.failure(e, false).withDescription(e.getMessage() + "; "
                    + note(published.get(), reference)));
        }
    }

    /** The entity, when the state knows it; a name it does not know is the ordinary path's to describe. */
    public static <E extends OWLEntity> Optional<E> named(Reference reference, EntityType<E> type, String argument,
                                                          Predicate<OWLEntity> known) {
        E entity = reference.names().entity(type, argument, known);
        return entity.isBuiltIn() || known.test(entity) ? Optional.of(entity) : Optional.empty();
    }

    /** The failure an inconsistent state answers every question with. */
    public static <T> T inconsistent(Reference reference) {
        throw new ArmorException(ExitCode.INCONSISTENT, "reference '" + reference.name()
                + "' is inconsistent; QUERY CONSISTENCY explains why");
    }

    private static String note(Published published, Reference reference) {
        return "answered from reasoned state revision " + published.revision() + " while reference '"
                + reference.name() + "' was busy";
    }
}
