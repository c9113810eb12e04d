// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.pddl;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.spi.Knowledge;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SortedMap;
import java.util.SortedSet;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.search.EntitySearcher;
import org.semanticweb.owlapi.vocab.OWL2Datatype;

/**
 * Makes a PDDL problem from what a reference knows, asserted and inferred alike (the same
 * knowledge QUERY IND CLASS and QUERY OBJECTPROP IND answer from): its objects are the
 * instances of the mapping's type classes, its {@code :init} the instances of the unary
 * predicates' classes, the values of the binary predicates' properties and the numeric values
 * of the fluents' data properties, and its goal the mapping's facts and the requirements on
 * every instance of a class. A name the reference does not know answers 224, naming it.
 * The caller holds the reference.
 */
final class ProblemGenerator {
    private final Knowledge reference;

    ProblemGenerator(Knowledge reference) {
        this.reference = reference;
    }

    /** An entity of the mapping with its PDDL name. */
    private record Named<E extends OWLEntity>(E entity, String pddl) {}

    /** A fact before its objects are named. */
    private record RawFact(String predicate, List<OWLNamedIndividual> arguments) {}

    PddlProblem generate(Mapping mapping) {
        String domain = PddlNames.valid(mapping.domain(), "mapping domain");
        String problem = mapping.problem() == null ? PddlNames.sanitise(reference.name())
                : PddlNames.valid(mapping.problem(), "mapping problem");
        List<Named<OWLClass>> types = resolve(mapping.types(), EntityType.CLASS, "types");
        List<Named<OWLClass>> unary = resolve(mapping.unaryPredicates(), EntityType.CLASS, "unary_predicates");
        List<Named<OWLObjectProperty>> binary = resolve(mapping.binaryPredicates(), EntityType.OBJECT_PROPERTY,
                "binary_predicates");
        List<Named<OWLDataProperty>> fluents = resolve(mapping.numericFluents(), EntityType.DATA_PROPERTY,
                "numeric_fluents");

        boolean typed = !types.isEmpty();
        Map<OWLNamedIndividual, String> typeOf = typed ? objectTypes(types) : Map.of();
        Collection<OWLNamedIndividual> subjects = typed ? sorted(typeOf.keySet())
                : sorted(reference.ontology().individualsInSignature(Imports.INCLUDED).toList());
        Set<OWLNamedIndividual> inProblem = typed ? typeOf.keySet() : new LinkedHashSet<>();

        List<RawFact> init = new ArrayList<>();
        for (Named<OWLClass> predicate : unary) {
            for (OWLNamedIndividual instance : sorted(reference.instances(predicate.entity(), false))) {
                if (!typed || typeOf.containsKey(instance)) {
                    init.add(new RawFact(predicate.pddl(), List.of(instance)));
                }
            }
        }
        for (Named<OWLObjectProperty> predicate : binary) {
            for (OWLNamedIndividual subject : subjects) {
                for (OWLNamedIndividual value : sorted(objectValues(predicate.entity(), subject))) {
                    if (!typed || typeOf.containsKey(value)) {
                        init.add(new RawFact(predicate.pddl(), List.of(subject, value)));
                    }
                }
            }
        }
        Map<RawFact, BigDecimal> values = new LinkedHashMap<>();
        for (Named<OWLDataProperty> fluent : fluents) {
            for (OWLNamedIndividual subject : subjects) {
                BigDecimal value = numericValue(fluent, subject);
                if (value != null) {
                    values.put(new RawFact(fluent.pddl(), List.of(subject)), value);
                }
            }
        }
        for (List<String> fact : mapping.init()) {
            init.add(fact(fact, "init", typed, typeOf));
        }
        List<RawFact> goal = new ArrayList<>();
        for (Mapping.Goal item : mapping.goal()) {
            if (item instanceof Mapping.Fact fact) {
                goal.add(fact(fact.words(), "goal", typed, typeOf));
            } else if (item instanceof Mapping.ForAll forAll) {
                goal.addAll(required(forAll, typed, typeOf));
            }
        }

        if (!typed) {
            init.forEach(fact -> inProblem.addAll(fact.arguments()));
            values.keySet().forEach(fact -> inProblem.addAll(fact.arguments()));
            goal.forEach(fact -> inProblem.addAll(fact.arguments()));
        }
        Map<IRI, String> names = PddlNames.unique(inProblem.stream().map(OWLNamedIndividual::getIRI).toList());
        SortedMap<String, SortedSet<String>> objects = new TreeMap<>();
        for (OWLNamedIndividual individual : inProblem) {
            objects.computeIfAbsent(typed ? typeOf.get(individual) : "", t -> new TreeSet<>())
                    .add(names.get(individual.getIRI()));
        }
        SortedMap<String, BigDecimal> fluentValues = new TreeMap<>();
        values.forEach((term, value) -> fluentValues.put(render(term, names), value));
        return new PddlProblem(problem, domain, reference.name(), objects, renderAll(init, names), fluentValues,
                renderAll(goal, names));
    }

    private <E extends OWLEntity> List<Named<E>> resolve(Map<String, String> section, EntityType<E> type,
                                                         String where) {
        List<Named<E>> resolved = new ArrayList<>();
        section.forEach((name, pddl) -> {
            E entity = known(type, name, "the mapping's " + where);
            resolved.add(new Named<>(entity, PddlNames.given(pddl, entity.getIRI(), where + "." + name)));
        });
        return resolved;
    }

    /** The entity a name of the mapping means; 224 when the reference does not know it. */
    private <E extends OWLEntity> E known(EntityType<E> type, String name, String where) {
        E entity = reference.entity(type, name);
        if (!reference.knows(entity)) {
            throw new ArmorException(ExitCode.UNKNOWN_NAME, where + " names the "
                    + reference.describeUnknown(type, name) + ", which reference '" + reference.name()
                    + "' does not know");
        }
        return entity;
    }

    /**
     * Each instance of a type class with its type: of the classes it belongs to, one no other
     * of them is a subclass of; of several such, the first the mapping lists.
     */
    private Map<OWLNamedIndividual, String> objectTypes(List<Named<OWLClass>> types) {
        Map<OWLClass, Set<OWLClass>> superClasses = new HashMap<>();
        for (Named<OWLClass> type : types) {
            superClasses.put(type.entity(), reference.inferred(r -> r.getSuperClasses(type.entity(), false)
                    .entities()).collect(Collectors.toSet()));
        }
        Map<OWLNamedIndividual, List<Named<OWLClass>>> candidates = new HashMap<>();
        for (Named<OWLClass> type : types) {
            for (OWLNamedIndividual instance : reference.instances(type.entity(), false)) {
                candidates.computeIfAbsent(instance, i -> new ArrayList<>()).add(type);
            }
        }
        Map<OWLNamedIndividual, String> typeOf = new HashMap<>();
        candidates.forEach((individual, classes) -> {
            Named<OWLClass> chosen = classes.stream()
                    .filter(type -> classes.stream().noneMatch(other -> other != type
                            && superClasses.get(other.entity()).contains(type.entity())))
                    .findFirst().orElse(classes.get(0));
            typeOf.put(individual, chosen.pddl());
        });
        return typeOf;
    }

    private Set<OWLNamedIndividual> objectValues(OWLObjectProperty property, OWLNamedIndividual subject) {
        return union(
                EntitySearcher.getObjectPropertyValues(subject, property, reference.closure())
                        .filter(i -> i.isNamed()).map(i -> i.asOWLNamedIndividual()),
                reference.inferred(r -> r.getObjectPropertyValues(subject, property).entities()));
    }

    /** The one numeric value of a fluent's data property, or null when it has none. */
    private BigDecimal numericValue(Named<OWLDataProperty> fluent, OWLNamedIndividual subject) {
        Set<OWLLiteral> literals = union(
                EntitySearcher.getDataPropertyValues(subject, fluent.entity(), reference.closure()),
                reference.inferred(r -> r.getDataPropertyValues(subject, fluent.entity()).stream()));
        Set<BigDecimal> numbers = new TreeSet<>();
        for (OWLLiteral literal : literals) {
            IRI datatype = literal.getDatatype().getIRI();
            BigDecimal number = null;
            if (OWL2Datatype.isBuiltIn(datatype) && OWL2Datatype.getDatatype(datatype).isNumeric()) {
                try {
                    number = new BigDecimal(literal.getLiteral().trim());
                } catch (NumberFormatException e) {
                    // reported below
                }
            }
            if (number == null) {
                throw new ArmorException(ExitCode.BAD_DATA_TYPE, "numeric fluent " + fluent.pddl() + ": "
                        + subject.getIRI().getShortForm() + " has the value \"" + literal.getLiteral() + "\"^^"
                        + datatype.getShortForm() + " of " + fluent.entity().getIRI().getShortForm()
                        + ", which is no number");
            }
            numbers.add(number.stripTrailingZeros());
        }
        if (numbers.size() > 1) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "numeric fluent " + fluent.pddl() + ": "
                    + subject.getIRI().getShortForm() + " has " + numbers.size() + " values of "
                    + fluent.entity().getIRI().getShortForm() + " " + numbers.stream()
                    .map(BigDecimal::toPlainString).toList() + "; a fluent has one");
        }
        return numbers.isEmpty() ? null : numbers.iterator().next();
    }

    private RawFact fact(List<String> words, String where, boolean typed, Map<OWLNamedIndividual, String> typeOf) {
        String shown = "(" + String.join(" ", words) + ")";
        String predicate = PddlNames.valid(words.get(0), "mapping " + where + " fact " + shown);
        List<OWLNamedIndividual> arguments = new ArrayList<>();
        for (String word : words.subList(1, words.size())) {
            OWLNamedIndividual individual = known(EntityType.NAMED_INDIVIDUAL, word,
                    "the mapping's " + where + " fact " + shown);
            if (typed && !typeOf.containsKey(individual)) {
                throw notAnObject(individual, where + " fact " + shown);
            }
            arguments.add(individual);
        }
        return new RawFact(predicate, arguments);
    }

    private List<RawFact> required(Mapping.ForAll forAll, boolean typed, Map<OWLNamedIndividual, String> typeOf) {
        OWLClass owlClass = known(EntityType.CLASS, forAll.className(), "the mapping's goal forall");
        List<RawFact> facts = new ArrayList<>();
        for (OWLNamedIndividual instance : sorted(reference.instances(owlClass, false))) {
            if (typed && !typeOf.containsKey(instance)) {
                throw notAnObject(instance, "goal forall " + forAll.className());
            }
            for (List<String> pattern : forAll.require()) {
                List<String> words = pattern.stream().map(word -> word.startsWith("?")
                        ? "<" + instance.getIRI() + ">" : word).toList();
                facts.add(fact(words, "goal", typed, typeOf));
            }
        }
        return facts;
    }

    private static ArmorException notAnObject(OWLNamedIndividual individual, String where) {
        return new ArmorException(ExitCode.WRONG_ARGUMENTS, "mapping " + where + ": individual "
                + individual.getIRI().getShortForm() + " is no object of the problem (none of its classes is in"
                + " types)");
    }

    private static SortedSet<String> renderAll(List<RawFact> facts, Map<IRI, String> names) {
        return facts.stream().map(fact -> render(fact, names)).collect(Collectors.toCollection(TreeSet::new));
    }

    private static String render(RawFact fact, Map<IRI, String> names) {
        return PddlProblem.fact(fact.predicate(), fact.arguments().stream().map(i -> names.get(i.getIRI())).toList());
    }

    private static List<OWLNamedIndividual> sorted(Collection<OWLNamedIndividual> individuals) {
        return individuals.stream().distinct().sorted(Comparator.comparing(OWLNamedIndividual::getIRI)).toList();
    }

    /** Asserted and inferred answers together, each once, in the order found. */
    @SafeVarargs
    private static <T> Set<T> union(Stream<? extends T>... parts) {
        return Stream.of(parts).flatMap(part -> part).collect(Collectors.toCollection(LinkedHashSet::new));
    }
}
