// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command.builtin;

import io.github.armor.core.answers.Inferences;
import io.github.armor.core.answers.Rendering;
import io.github.armor.core.answers.Syntax;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandGroup;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.sparql.Sparql;
import java.util.List;
import java.util.Set;
import java.util.function.BiFunction;
import java.util.function.Function;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLObjectPropertyExpression;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLRestriction;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.search.EntitySearcher;

/** Contract 5.3: every question, answered from asserted plus inferred knowledge, sorted. */
public final class Queries implements CommandGroup {
    @Override
    public void register(CommandTable table) {
        registerIndividualQueries(table);
        registerClassQueries(table);
        registerPropertyQueries(table);
        table.command("QUERY SPARQL").args("query").variadic()
                .summary("SPARQL SELECT or ASK, one string per row").query(c -> Sparql.answer(c, false));
        table.command("QUERY SPARQL FORMATTED").args("query").variadic().subscribedAs("QUERY SPARQL")
                .summary("SPARQL SELECT or ASK, rows as variable/value pairs").query(c -> Sparql.answer(c, true));
        table.command("QUERY CONSISTENCY").summary("is it consistent, and if not, why").query(Explanations::answer);
    }

    private static void registerIndividualQueries(CommandTable table) {
        table.command("QUERY IND").args("ind").emptySurplusIgnored()
                .summary("the classes of the individual").whileBusy(c -> StateQueries.classesOf(c, false))
                .query(c -> c.ok(c.render().entities(types(c.reference(), c.individual(0), false).stream())));
        table.command("QUERY IND CLASS").args("class").emptySurplusIgnored()
                .summary("the instances of the class").whileBusy(StateQueries::instances)
                .query(c -> c.ok(c.render().entities(
                Inferences.instances(c.reference(), c.owlClass(0), false).stream())));
        table.command("QUERY IND DL").args("class expression")
                .summary("the instances of a Manchester class expression").query(c -> c.ok(c.render().entities(
                Inferences.instances(c.reference(), c.classExpression(0), false)
                        .stream())));
        table.command("QUERY CLASS IND").args("ind").optional("most specific only").emptySurplusIgnored()
                .summary("the classes of the individual, optionally the most specific only")
                .whileBusy(c -> StateQueries.classesOf(c, c.args().size() > 1
                        && c.arg(1).trim().equalsIgnoreCase("true")))
                .query(c -> {
            boolean direct = c.hasArg(1) && c.flag(1);
            return c.ok(c.render().entities(types(c.reference(), c.individual(0), direct).stream()));
        });
        table.command("QUERY IND SAME").args("ind").summary("individuals equal to it").query(c -> {
            OWLNamedIndividual individual = c.individual(0);
            Set<OWLNamedIndividual> same = Inferences.union(
                    EntitySearcher.getSameIndividuals(individual, Inferences.closure(c.reference()))
                            .filter(i -> i.isNamed()).map(i -> i.asOWLNamedIndividual()),
                    Inferences.inferred(c.reference(), r -> r.getSameIndividuals(individual).entities()));
            same.remove(individual);
            return c.ok(c.render().entities(same.stream()));
        });
        table.command("QUERY IND DATAPROP").args("ind").emptySurplusIgnored()
                .summary("the data properties that have values for it")
                .query(c -> withValues(c, o -> o.dataPropertiesInSignature(Imports.INCLUDED), Queries::dataValues));
        table.command("QUERY IND OBJECTPROP").args("ind").emptySurplusIgnored()
                .summary("the object properties that have values for it")
                .query(c -> withValues(c, o -> o.objectPropertiesInSignature(Imports.INCLUDED),
                        Queries::objectValues));
    }

    /** What a property's values for an individual are, asserted plus inferred. */
    @FunctionalInterface
    private interface Values<P> {
        Set<?> of(Reference reference, P property, OWLNamedIndividual individual);
    }

    /** The properties of the ontology that have a value for the individual argument. */
    private static <P extends OWLEntity> Response withValues(CommandContext c,
                                                             Function<OWLOntology, Stream<P>> properties,
                                                             Values<P> values) {
        Reference reference = c.reference();
        OWLNamedIndividual individual = c.individual(0);
        return c.ok(c.render().entities(properties.apply(reference.ontology())
                .filter(p -> !values.of(reference, p, individual).isEmpty())));
    }

    private static void registerClassQueries(CommandTable table) {
        table.command("QUERY CLASS CLASS").args("class").emptySurplusIgnored()
                .summary("subclasses, all levels").query(c -> c.ok(c.render().entities(
                Inferences.subClasses(c.reference(), c.owlClass(0), false).stream())));
        table.command("QUERY CLASS DL").args("class expression")
                .summary("the subclasses of a Manchester class expression").query(c -> c.ok(c.render().entities(
                Inferences.subClasses(c.reference(), c.classExpression(0), false)
                        .stream())));
        classRelation(table, "QUERY CLASS SUPER", "superclasses", EntitySearcher::getSuperClasses,
                (r, owlClass) -> r.getSuperClasses(owlClass, false).entities());
        classRelation(table, "QUERY CLASS EQUIVALENT", "equivalent classes", EntitySearcher::getEquivalentClasses,
                (r, owlClass) -> r.getEquivalentClasses(owlClass).entities());
        classRelation(table, "QUERY CLASS DISJOINT", "disjoint classes", EntitySearcher::getDisjointClasses,
                (r, owlClass) -> r.getDisjointClasses(owlClass).entities());
        table.command("QUERY CLASS RESTRICTIONS").args("class").emptySurplusIgnored()
                .summary("its restrictions, Manchester syntax")
                .query(c -> c.ok(restrictions(c.reference(), c.owlClass(0), c.config().fullEntityIri())));
    }

    /** The restrictions among the conjuncts of a class's superclasses and definitions, in Manchester syntax. */
    public static List<String> restrictions(Reference reference, OWLClass owlClass, boolean fullIri) {
        Stream<OWLClassExpression> definitions = Stream.concat(
                EntitySearcher.getSuperClasses(owlClass, Inferences.closure(reference)),
                EntitySearcher.getEquivalentClasses(owlClass, Inferences.closure(reference)));
        return definitions.flatMap(OWLClassExpression::conjunctSet)
                .filter(e -> e instanceof OWLRestriction)
                .map(e -> Syntax.render(reference, fullIri, e))
                .distinct().sorted().toList();
    }

    /** A query answering the named classes related to a class: asserted ones plus inferred ones. */
    private static void classRelation(CommandTable table, String words, String summary,
                                      BiFunction<OWLClass, Stream<OWLOntology>, Stream<OWLClassExpression>> asserted,
                                      BiFunction<OWLReasoner, OWLClass, Stream<OWLClass>> inferred) {
        table.command(words).args("class").summary(summary).query(c -> {
            OWLClass owlClass = c.owlClass(0);
            Set<OWLClass> related = Inferences.union(
                    asserted.apply(owlClass, Inferences.closure(c.reference()))
                            .filter(e -> !e.isAnonymous()).map(OWLClassExpression::asOWLClass),
                    Inferences.inferred(c.reference(), r -> inferred.apply(r, owlClass)));
            related.remove(owlClass);
            return c.ok(c.render().entities(related.stream()));
        });
    }

    private static void registerPropertyQueries(CommandTable table) {
        table.command("QUERY OBJECTPROP IND").args("prop", "ind").emptySurplusIgnored()
                .summary("the individuals it is related to by the property").query(c -> c.ok(c.render().entities(
                objectValues(c.reference(), c.objectProperty(0), c.individual(1)).stream())));
        table.command("QUERY DATAPROP IND").args("prop", "ind").emptySurplusIgnored()
                .summary("its values of the property").query(c -> c.ok(Rendering.literals(
                dataValues(c.reference(), c.dataProperty(0), c.individual(1)))));
        table.command("QUERY OBJECTPROP OBJECTPROP").args("prop")
                .summary("sub-properties of an object property").query(c -> {
            OWLObjectProperty property = c.objectProperty(0);
            Set<OWLObjectProperty> subs = Inferences.union(
                    EntitySearcher.getSubProperties(property, Inferences.closure(c.reference()))
                            .filter(p -> p.isNamed()).map(OWLObjectPropertyExpression::asOWLObjectProperty),
                    Inferences.inferred(c.reference(), r -> r.getSubObjectProperties(property, false).entities()
                            .filter(p -> p.isNamed()).map(OWLObjectPropertyExpression::asOWLObjectProperty)));
            subs.remove(property);
            return c.ok(c.render().entities(subs.stream()));
        });
        table.command("QUERY DATAPROP DATAPROP").args("prop").summary("sub-properties of a data property").query(c -> {
            OWLDataProperty property = c.dataProperty(0);
            Set<OWLDataProperty> subs = Inferences.union(
                    EntitySearcher.getSubProperties(property, Inferences.closure(c.reference()))
                            .map(p -> p.asOWLDataProperty()),
                    Inferences.inferred(c.reference(), r -> r.getSubDataProperties(property, false).entities()));
            subs.remove(property);
            return c.ok(c.render().entities(subs.stream()));
        });
    }

    private static Set<OWLClass> types(Reference reference, OWLNamedIndividual individual, boolean direct) {
        if (!Inferences.known(reference, individual)) {
            return Set.of();
        }
        Set<OWLClass> inferred = Inferences.union(Inferences.inferred(reference,
                r -> r.getTypes(individual, direct).entities()));
        inferred.removeIf(OWLClass::isOWLThing);
        if (direct && !inferred.isEmpty()) {
            return inferred;
        }
        return Inferences.union(EntitySearcher.getTypes(individual, Inferences.closure(reference))
                .filter(t -> !t.isAnonymous()).map(OWLClassExpression::asOWLClass), inferred.stream());
    }

    static Set<OWLNamedIndividual> objectValues(Reference reference, OWLObjectProperty property,
                                                OWLNamedIndividual individual) {
        if (!Inferences.known(reference, property) || !Inferences.known(reference, individual)) {
            return Set.of();
        }
        return Inferences.union(
                EntitySearcher.getObjectPropertyValues(individual, property, Inferences.closure(reference))
                        .filter(i -> i.isNamed()).map(i -> i.asOWLNamedIndividual()),
                Inferences.inferred(reference, r -> r.getObjectPropertyValues(individual, property).entities()));
    }

    static Set<OWLLiteral> dataValues(Reference reference, OWLDataProperty property, OWLNamedIndividual individual) {
        if (!Inferences.known(reference, property) || !Inferences.known(reference, individual)) {
            return Set.of();
        }
        return Inferences.union(
                EntitySearcher.getDataPropertyValues(individual, property, Inferences.closure(reference)),
                Inferences.inferred(reference, r -> r.getDataPropertyValues(individual, property).stream()));
    }

}
