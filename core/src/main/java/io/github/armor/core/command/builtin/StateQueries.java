// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command.builtin;

import static io.github.armor.core.command.PublishedAnswers.fromPublished;
import static io.github.armor.core.command.PublishedAnswers.inconsistent;
import static io.github.armor.core.command.PublishedAnswers.named;

import io.github.armor.core.answers.Rendering;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.AnswerSource;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.reasoning.InferredState;
import io.github.armor.core.reference.Reference;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Predicate;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;

/**
 * Questions about types answered while another directive holds the reference (a writer
 * reasoning for seconds): from the state its reasoner last published, never from the live
 * ontology, which the writer is changing. The answer is the one the locked path gave when that
 * state was published; its description names the state's revision, so a client knows how old it
 * is. Anything this cannot answer exactly (an unknown name, another command, no published state)
 * is left to the ordinary path, which waits for the reference. Each is an {@link AnswerSource}
 * registered beside its command's handler (see {@link Queries}).
 */
final class StateQueries {
    private StateQueries() {}

    /** The instances of the class argument (QUERY IND CLASS), from the published state. */
    static Optional<Response> instances(CommandContext context) {
        return fromPublished(context, (reference, state, known) -> named(reference, EntityType.CLASS,
                context.arg(0), known).map(owlClass -> context.render().entities(state.consistent()
                ? state.instances(owlClass).stream() : inconsistent(reference))));
    }

    /** The classes of the individual argument, all or the most specific only, from the published state. */
    static Optional<Response> classesOf(CommandContext context, boolean direct) {
        return fromPublished(context, (reference, state, known) -> types(reference, state, context.arg(0), direct,
                known, context.render()));
    }

    private static Optional<List<String>> types(Reference reference, InferredState state, String argument,
                                                boolean direct, Predicate<OWLEntity> known, Rendering rendering) {
        return named(reference, EntityType.NAMED_INDIVIDUAL, argument, known).flatMap(individual -> {
            if (!state.consistent()) {
                return Optional.of(rendering.entities(inconsistent(reference)));
            }
            // Over an upper ontology only some of its classes may be known: then the ordinary path answers.
            return state.classesOf(individual, direct)
                    .map(classes -> rendering.entities(classes.stream().filter(c -> !c.isOWLThing())));
        });
    }
}
