// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.reasoning.InferredState;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.spi.PublishedState;
import io.github.armor.core.spi.StateAnswer;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Predicate;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;

/**
 * A plugin's {@link StateAnswer} as the core asks it: through the same published-state path as
 * the built-in queries' sources ({@link PublishedAnswers}); an inconsistent state is answered
 * by the core, as the built-in queries answer it. Its class loader is the plugin's.
 */
record PluginStateSource(StateAnswer answer) implements AnswerSource {
    @Override
    public Optional<Response> answer(CommandContext context) {
        return PublishedAnswers.fromPublished(context, (reference, state, known) -> state.consistent()
                ? answer.objects(new View(context, reference, state, known))
                : PublishedAnswers.inconsistent(reference));
    }

    ClassLoader loader() {
        return answer.getClass().getClassLoader();
    }

    private record View(CommandContext context, Reference reference, InferredState state,
                        Predicate<OWLEntity> knows) implements PublishedState {
        @Override
        public Directive directive() {
            return context.directive();
        }

        @Override
        public <E extends OWLEntity> Optional<E> known(EntityType<E> type, String name) {
            return PublishedAnswers.named(reference, type, name, knows);
        }

        @Override
        public List<OWLNamedIndividual> instances(OWLClass owlClass) {
            return state.instances(owlClass);
        }

        @Override
        public Optional<Set<OWLClass>> classesOf(OWLNamedIndividual individual, boolean direct) {
            return state.classesOf(individual, direct);
        }

        @Override
        public List<String> render(Stream<? extends OWLEntity> entities) {
            return context.render().entities(entities);
        }
    }
}
