// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.answers.Inferences;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.reference.AllowedPaths;
import io.github.armor.core.reference.ReasonerRegistry;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.reference.WritablePaths;
import io.github.armor.core.spi.Context;
import io.github.armor.core.spi.Knowledge;
import io.github.armor.core.spi.Paths;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;

/** A plugin's view of a directive ({@link Context}) over the core's own {@link CommandContext}. */
final class PluginContext implements Context {
    private final CommandContext context;

    PluginContext(CommandContext context) {
        this.context = context;
    }

    @Override
    public Directive directive() {
        return context.directive();
    }

    @Override
    public List<String> args() {
        return context.args();
    }

    @Override
    public String arg(int index) {
        return context.arg(index);
    }

    @Override
    public boolean hasArg(int index) {
        return context.hasArg(index);
    }

    @Override
    public boolean flag(int index) {
        return context.flag(index);
    }

    @Override
    public OWLNamedIndividual individual(int index) {
        return context.individual(index);
    }

    @Override
    public OWLClass owlClass(int index) {
        return context.owlClass(index);
    }

    @Override
    public OWLObjectProperty objectProperty(int index) {
        return context.objectProperty(index);
    }

    @Override
    public OWLDataProperty dataProperty(int index) {
        return context.dataProperty(index);
    }

    @Override
    public OWLClassExpression classExpression(int index) {
        return context.classExpression(index);
    }

    @Override
    public OWLLiteral literal(int typeIndex, int valueIndex) {
        return context.literal(typeIndex, valueIndex);
    }

    @Override
    public Knowledge knowledge() {
        if (context.reference() == null) {
            throw new IllegalStateException(context.directive().describe() + " has no reference");
        }
        return new ReferenceKnowledge(context.reference());
    }

    @Override
    public Response change(List<? extends OWLOntologyChange> changes) {
        return context.change(changes);
    }

    @Override
    public void enact(List<? extends OWLOntologyChange> changes) {
        Reference reference = context.reference();
        // The waiting changes first, so that the transaction keeps them as they were: a rollback
        // restores them and undoes these, which were applied on their own.
        reference.applyPending();
        reference.change(changes);
        reference.applyPending();
    }

    @Override
    public Paths paths() {
        return new Paths() {
            @Override
            public Path readable(String clientPath) {
                return AllowedPaths.forReading(context.config()).check(clientPath);
            }

            @Override
            public Path writable(String clientPath) {
                return WritablePaths.of(context.config()).check(clientPath);
            }

            @Override
            public void write(Path checked, Content content) {
                WritablePaths.of(context.config()).write(checked, content::writeTo);
            }
        };
    }

    @Override
    public boolean replaying() {
        return context.replaying();
    }

    @Override
    public String render(OWLEntity entity) {
        return context.render().entity(entity);
    }

    @Override
    public List<String> render(Stream<? extends OWLEntity> entities) {
        return context.render().entities(entities);
    }

    @Override
    public Response ok(List<String> objects) {
        return context.ok(objects);
    }

    @Override
    public Response ok() {
        return context.ok();
    }

    /** A reference, read-only. */
    private record ReferenceKnowledge(Reference reference) implements Knowledge {
        @Override
        public String name() {
            return reference.name();
        }

        @Override
        public OWLOntology ontology() {
            return reference.ontology();
        }

        @Override
        public Stream<OWLOntology> closure() {
            return Inferences.closure(reference);
        }

        @Override
        public OWLDataFactory factory() {
            return reference.factory();
        }

        @Override
        public <T> Stream<T> inferred(Function<OWLReasoner, Stream<T>> question) {
            return Inferences.inferred(reference, question);
        }

        @Override
        public Set<OWLNamedIndividual> instances(OWLClassExpression owlClass, boolean direct) {
            return Inferences.instances(reference, owlClass, direct);
        }

        @Override
        public void synchroniseReasoner() {
            if (reference.settings().bufferedReasoner()) {
                reference.synchroniseReasoner();
            }
        }

        @Override
        public boolean consistent() {
            return reference.isConsistent();
        }

        @Override
        public OWLReasonerFactory reasonerFactory() {
            return ReasonerRegistry.factory(reference.reasonerName());
        }

        @Override
        public IRI iri(EntityType<?> type, String name) {
            return reference.names().iri(type, name);
        }

        @Override
        public <E extends OWLEntity> E entity(EntityType<E> type, String name) {
            return reference.names().entity(type, name);
        }

        @Override
        public boolean knows(OWLEntity entity) {
            return reference.names().knows(entity);
        }

        @Override
        public String describeUnknown(EntityType<?> type, String name) {
            return reference.names().describeUnknown(type, name);
        }

        @Override
        public Object identity() {
            return reference;
        }
    }
}
