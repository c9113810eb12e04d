// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.answers.Literals;
import io.github.armor.core.answers.Rendering;
import io.github.armor.core.answers.Syntax;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.log.DirectiveLog;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.reference.ReferenceRegistry;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntologyChange;

/** What a command handler sees: the directive, its reference (if any), the registry and the settings. */
public final class CommandContext {
    private final Directive directive;
    private final CommandKind kind;
    private final Reference reference;
    private final ReferenceRegistry references;
    private final CoreConfig config;
    private final Rendering rendering;
    private final DirectiveLog log;
    private final boolean replaying;
    private final CommandTable commands;
    private final Supplier<List<String>> stateDamage;
    private Supplier<Response> afterRelease;
    private final List<String> unknownNames = new ArrayList<>();

    public CommandContext(Directive directive, CommandKind kind, Reference reference, ReferenceRegistry references,
                          CoreConfig config, Rendering rendering, DirectiveLog log, boolean replaying,
                          CommandTable commands, Supplier<List<String>> stateDamage) {
        this.directive = directive;
        this.kind = kind;
        this.reference = reference;
        this.references = references;
        this.config = config;
        this.rendering = rendering;
        this.log = log;
        this.replaying = replaying;
        this.commands = commands;
        this.stateDamage = stateDamage;
    }

    /** What the state directory could not bring back or cannot keep (GET STATE DAMAGE). */
    public List<String> stateDamage() {
        return stateDamage.get();
    }

    /** Every command the core answers (GET CATALOGUE lists them). */
    public CommandTable commands() {
        return commands;
    }

    /** Whether the directive is a journal record replayed at start, not a client's request. */
    public boolean replaying() {
        return replaying;
    }

    /**
     * For a read whose expensive part works on a private copy (SPARQL): {@code evaluation} runs
     * once the reference is released, so writers and other readers are not held out meanwhile.
     * Inside an atomic list, which holds its references to the end, it runs at once.
     */
    public Response afterRelease(Supplier<Response> evaluation) {
        afterRelease = evaluation;
        return Response.ok(true, List.of());
    }

    /**
     * The directive's answer: the deferred evaluation's, if the handler left one. A success says
     * in its description what the client should know of it: that it named entities the
     * reference did not know (a typo creates an entity, as in ARMOR; the client can warn), and,
     * for a query, that the reasoner does not use some axioms, so the answer may be incomplete.
     */
    public Response finishAfterRelease(Response underLock) {
        Supplier<Response> evaluation = afterRelease;
        afterRelease = null;
        Response response = evaluation == null ? underLock : evaluation.get();
        if (!response.success()) {
            return response;
        }
        if (!unknownNames.isEmpty()) {
            response = withNote(response, "new to the reference: " + String.join(", ", unknownNames));
        }
        String unused = reference == null ? "" : reference.coverage().summary();
        if (!unused.isEmpty() && kind == CommandKind.QUERY) {
            response = withNote(response, "may be incomplete: " + unused);
        }
        return response;
    }

    private static Response withNote(Response response, String note) {
        return response.withDescription(response.errorDescription().isEmpty() ? note
                : response.errorDescription() + "; " + note);
    }

    public DirectiveLog log() {
        return log;
    }

    public Directive directive() {
        return directive;
    }

    public Reference reference() {
        return reference;
    }

    public ReferenceRegistry references() {
        return references;
    }

    public CoreConfig config() {
        return config;
    }

    public Rendering render() {
        return rendering;
    }

    public OWLDataFactory factory() {
        return reference.factory();
    }

    public List<String> args() {
        return directive.args();
    }

    public String arg(int index) {
        return directive.args().get(index);
    }

    public boolean hasArg(int index) {
        return directive.args().size() > index && !directive.args().get(index).isEmpty();
    }

    public OWLNamedIndividual individual(int index) {
        return named(EntityType.NAMED_INDIVIDUAL, index);
    }

    public OWLClass owlClass(int index) {
        return named(EntityType.CLASS, index);
    }

    public OWLObjectProperty objectProperty(int index) {
        return named(EntityType.OBJECT_PROPERTY, index);
    }

    public OWLDataProperty dataProperty(int index) {
        return named(EntityType.DATA_PROPERTY, index);
    }

    /**
     * A Manchester class expression argument. A word that is no entity of the reference is read
     * as a new class (a typo answers nothing): each such class is noted as an unknown name is.
     */
    public OWLClassExpression classExpression(int index) {
        OWLClassExpression expression = Syntax.classExpression(reference, arg(index));
        expression.classesInSignature().forEach(owlClass -> noteIfUnknown(owlClass, owlClass.getIRI().getShortForm()));
        return expression;
    }

    /** The entity an argument names; an unknown one is noted, or refused in a query under strict_names. */
    private <E extends OWLEntity> E named(EntityType<E> type, int index) {
        E entity = reference.names().entity(type, arg(index));
        noteIfUnknown(entity, arg(index));
        return entity;
    }

    private void noteIfUnknown(OWLEntity entity, String written) {
        if (!reference.names().knows(entity)) {
            String unknown = reference.names().describeUnknown(entity.getEntityType(), written);
            if (config.safeguards().strictNames() && kind == CommandKind.QUERY) {
                throw new ArmorException(ExitCode.UNKNOWN_NAME, "reference '" + reference.name()
                        + "' does not know the " + unknown + " (strict_names is on)");
            }
            if (!unknownNames.contains(unknown)) {
                unknownNames.add(unknown);
            }
        }
    }

    /** A literal from a (type, value) argument pair. */
    public OWLLiteral literal(int typeIndex, int valueIndex) {
        return Literals.literal(factory(), reference.names(), arg(typeIndex), arg(valueIndex));
    }

    /**
     * A boolean flag argument: true or false, any case; empty is false, as ROS 1 ARMOR read it
     * (Boolean.valueOf), so old clients that leave a buffering flag empty keep working.
     */
    public boolean flag(int index) {
        String value = arg(index).trim();
        if (value.isEmpty()) {
            return false;
        }
        if (value.equalsIgnoreCase("true")) {
            return true;
        }
        if (value.equalsIgnoreCase("false")) {
            return false;
        }
        throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "argument " + index + " of "
                + directive.describe() + " must be true or false, got '" + value + "'");
    }

    /** Applies (or queues) changes and answers success. */
    public Response change(List<? extends OWLOntologyChange> changes) {
        reference.change(changes);
        return ok(List.of());
    }

    public Response ok(List<String> objects) {
        return Response.ok(reference == null || reference.isConsistent(), objects);
    }

    public Response ok() {
        return ok(List.of());
    }
}
