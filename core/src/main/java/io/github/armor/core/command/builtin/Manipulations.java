// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command.builtin;

import io.github.armor.core.answers.Inferences;
import io.github.armor.core.answers.Literals;
import io.github.armor.core.answers.Rendering;
import io.github.armor.core.answers.Syntax;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandGroup;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.reference.Reference;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import org.semanticweb.owlapi.model.AddAxiom;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLSubClassOfAxiom;
import org.semanticweb.owlapi.model.RemoveAxiom;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.util.OWLEntityRemover;
import org.semanticweb.owlapi.util.OWLEntityRenamer;

/** Contract 5.2: every change a client can make, each refused with 102 under a foreign mount. */
public final class Manipulations implements CommandGroup {
    @Override
    public void register(CommandTable table) {
        registerArmorCommands(table);
        registerPairs(table);
        registerRenames(table);
    }

    private static void registerArmorCommands(CommandTable table) {
        table.command("ADD IND").args("ind").emptySurplusIgnored()
                .summary("declare an individual").manipulation(c -> c.change(adds(c, List.of(
                c.factory().getOWLDeclarationAxiom(c.individual(0)),
                c.factory().getOWLClassAssertionAxiom(c.factory().getOWLThing(), c.individual(0))))));
        table.command("ADD CLASS").args("class").emptySurplusIgnored()
                .summary("declare a class").manipulation(c -> c.change(adds(c, List.of(
                c.factory().getOWLDeclarationAxiom(c.owlClass(0)),
                c.factory().getOWLSubClassOfAxiom(c.owlClass(0), c.factory().getOWLThing())))));
        table.command("ADD CARDINALITY MIN").alias("ADD MIN CARDINALITY").emptySurplusIgnored()
                .args("class", "object prop", "n", "value class")
                .summary("class SubClassOf prop min n value class")
                .manipulation(c -> c.change(adds(c, List.of(c.factory().getOWLSubClassOfAxiom(c.owlClass(0),
                        c.factory().getOWLObjectMinCardinality(cardinality(c.arg(2)), c.objectProperty(1),
                                c.owlClass(3)))))));
        table.command("DISJOINT IND").args("ind", "ind").variadic()
                .summary("assert that the individuals are different").manipulation(c -> c.change(adds(c, List.of(
                c.factory().getOWLDifferentIndividualsAxiom(all(c, CommandContext::individual))))));
        table.command("DISJOINT CLASS").args("class", "class").variadic()
                .summary("assert that the classes are disjoint").manipulation(c -> c.change(adds(c, List.of(
                c.factory().getOWLDisjointClassesAxiom(all(c, CommandContext::owlClass))))));
        table.command("DISJOINT IND CLASS").args("class").emptySurplusIgnored()
                .summary("make all instances of the class different from each other").manipulation(c -> {
            Set<OWLNamedIndividual> members = Inferences.instances(c.reference(), c.owlClass(0), false);
            return c.change(members.size() < 2 ? List.of()
                    : adds(c, List.of(c.factory().getOWLDifferentIndividualsAxiom(members))));
        });
        table.command("DISJOINT CLASS CLASS").args("class").emptySurplusIgnored()
                .summary("make the direct subclasses of the class disjoint").manipulation(c -> {
            Set<OWLClass> children = Inferences.subClasses(c.reference(), c.owlClass(0), true);
            return c.change(children.size() < 2 ? List.of()
                    : adds(c, List.of(c.factory().getOWLDisjointClassesAxiom(children))));
        });
        table.command("MAKE EQUIVALENT CLASS").args("class").emptySurplusIgnored()
                        .summary("turn its SubClassOf axioms into one EquivalentClasses")
                        .manipulation(c -> c.change(makeEquivalentChanges(c)));
        table.command("REMOVE IND").args("ind").emptySurplusIgnored()
                .summary("remove every axiom that mentions the individual")
                .manipulation(c -> c.change(removeEntity(c.reference(),
                c.individual(0))));
        table.command("REMOVE CLASS").args("class").emptySurplusIgnored()
                .summary("remove every axiom that mentions the class")
                .manipulation(c -> c.change(removeEntity(c.reference(),
                c.owlClass(0))));
        table.command("REPLACE DATAPROP IND").args("prop", "ind", "type", "new value", "old value")
                .emptySurplusIgnored()
                .summary("replace one data property value by another")
                .manipulation(Manipulations::replaceDataValue);
        table.command("ADD DATAPROP IND").args("prop", "ind", "type", "value").emptySurplusIgnored()
                .summary("give the individual a data property value").manipulation(c -> c.change(adds(c,
                List.of(c.factory().getOWLDataPropertyAssertionAxiom(c.dataProperty(0), c.individual(1),
                        c.literal(2, 3))))));
        table.command("REMOVE DATAPROP IND").args("prop", "ind", "type", "value").emptySurplusIgnored()
                .summary("remove that data property value").manipulation(c -> c.change(
                removes(c, List.of(c.factory().getOWLDataPropertyAssertionAxiom(c.dataProperty(0), c.individual(1),
                        Literals.stored(c.reference().ontology(), c.dataProperty(0), c.individual(1),
                                c.literal(2, 3)))))));
        table.command("REPLACE OBJECTPROP IND").args("prop", "ind", "new value", "old value").emptySurplusIgnored()
                .summary("replace one related individual by another")
                .manipulation(c -> {
                    OWLDataFactory f = c.factory();
                    List<OWLOntologyChange> changes = new ArrayList<>(removes(c, List.of(
                            f.getOWLObjectPropertyAssertionAxiom(c.objectProperty(0), c.individual(1),
                                    c.individual(3)))));
                    changes.addAll(adds(c, List.of(f.getOWLObjectPropertyAssertionAxiom(c.objectProperty(0),
                            c.individual(1), c.individual(2)))));
                    return c.change(changes);
                });
    }

    // The pairs ROS 1 ARMOR had (both ADD and REMOVE): they ignore empty surplus arguments as it did.
    private static final Set<String> ARMOR_PAIRS = Set.of("IND CLASS", "CLASS CLASS", "OBJECTPROP IND");

    /** Commands that exist as ADD X and REMOVE X over the same axioms. */
    private static void registerPairs(CommandTable table) {
        pair(table, "IND CLASS", new String[] {"ind", "class"}, false,
                "assert that the individual belongs to the class", "remove that class assertion",
                c -> List.of(c.factory().getOWLClassAssertionAxiom(c.owlClass(1), c.individual(0))));
        pair(table, "CLASS CLASS", new String[] {"sub", "super"}, false,
                "assert that sub is a subclass of super", "remove that SubClassOf axiom",
                c -> List.of(c.factory().getOWLSubClassOfAxiom(c.owlClass(0), c.owlClass(1))));
        pair(table, "OBJECTPROP IND", new String[] {"prop", "ind", "value ind"}, false,
                "relate the individual to another", "remove that relation",
                c -> List.of(c.factory().getOWLObjectPropertyAssertionAxiom(c.objectProperty(0), c.individual(1),
                        c.individual(2))));
        pair(table, "OBJECTPROP OBJECTPROP", new String[] {"sub", "super"}, false,
                "assert an object sub-property", "remove that sub-property axiom",
                c -> List.of(c.factory().getOWLSubObjectPropertyOfAxiom(c.objectProperty(0), c.objectProperty(1))));
        pair(table, "DATAPROP DATAPROP", new String[] {"sub", "super"}, false,
                "assert a data sub-property", "remove that sub-property axiom",
                c -> List.of(c.factory().getOWLSubDataPropertyOfAxiom(c.dataProperty(0), c.dataProperty(1))));
        pair(table, "OBJECTPROP INVERSE", new String[] {"prop", "inverse prop"}, false,
                "assert that two object properties are inverses", "remove that inverse axiom",
                c -> List.of(c.factory().getOWLInverseObjectPropertiesAxiom(c.objectProperty(0),
                        c.objectProperty(1))));
        pair(table, "OBJECTPROP CHARACTERISTIC", new String[] {"prop", "characteristic"}, false,
                "FUNCTIONAL, TRANSITIVE, SYMMETRIC, ...", "remove that characteristic",
                c -> List.of(objectCharacteristic(c.factory(), c.objectProperty(0), c.arg(1))));
        pair(table, "DATAPROP CHARACTERISTIC", new String[] {"prop", "characteristic"}, false,
                "make a data property FUNCTIONAL", "remove that characteristic",
                c -> List.of(dataCharacteristic(c.factory(), c.dataProperty(0), c.arg(1))));
        pair(table, "OBJECTPROP DOMAIN", new String[] {"prop", "class"}, false,
                "object property domain", "remove that domain",
                c -> List.of(c.factory().getOWLObjectPropertyDomainAxiom(c.objectProperty(0), c.owlClass(1))));
        pair(table, "OBJECTPROP RANGE", new String[] {"prop", "class"}, false,
                "object property range", "remove that range",
                c -> List.of(c.factory().getOWLObjectPropertyRangeAxiom(c.objectProperty(0), c.owlClass(1))));
        pair(table, "DATAPROP DOMAIN", new String[] {"prop", "class"}, false,
                "data property domain", "remove that domain",
                c -> List.of(c.factory().getOWLDataPropertyDomainAxiom(c.dataProperty(0), c.owlClass(1))));
        pair(table, "DATAPROP RANGE", new String[] {"prop", "datatype"}, false,
                "data property range", "remove that range",
                c -> List.of(c.factory().getOWLDataPropertyRangeAxiom(c.dataProperty(0),
                        Literals.datatype(c.factory(), c.reference().names(), c.arg(1)))));
        pair(table, "IND SAME", new String[] {"ind", "ind"}, true,
                "assert that the individuals are the same", "remove that SameIndividual axiom",
                c -> List.of(c.factory().getOWLSameIndividualAxiom(all(c, CommandContext::individual))));
        pair(table, "CLASS EQUIVALENT", new String[] {"class", "class expression"}, false,
                "define the class by a Manchester class expression", "remove that definition",
                c -> List.of(c.factory().getOWLEquivalentClassesAxiom(c.owlClass(0),
                        c.classExpression(1))));
        pair(table, "AXIOM", new String[] {"axiom"}, false,
                "one axiom in Manchester or functional syntax", "remove that axiom",
                c -> List.of(Syntax.axiom(c.reference(), c.arg(0))));
        pair(table, "SWRL", new String[] {"rule name", "rule"}, false,
                "add a SWRL rule", "remove a SWRL rule",
                c -> List.of(Syntax.rule(c.reference(), c.arg(0), c.arg(1))));
    }

    private static final List<String> NAMES = List.of("an individual", "a class", "a data property",
            "an object property");

    private static void registerRenames(CommandTable table) {
        List<EntityType<?>> kinds = List.of(EntityType.NAMED_INDIVIDUAL, EntityType.CLASS, EntityType.DATA_PROPERTY,
                EntityType.OBJECT_PROPERTY);
        List<String> words = List.of("IND", "CLASS", "DATAPROP", "OBJECTPROP");
        for (int i = 0; i < kinds.size(); i++) {
            EntityType<?> kind = kinds.get(i);
            table.command("RENAME " + words.get(i)).args("old name", "new name").emptySurplusIgnored()
                    .summary("rename " + NAMES.get(i) + " everywhere").manipulation(c -> {
                Reference reference = c.reference();
                IRI from = reference.names().iri(kind, c.arg(0));
                IRI to = reference.names().iri(kind, c.arg(1));
                OWLEntityRenamer renamer = new OWLEntityRenamer(reference.manager(),
                        Collections.singleton(reference.ontology()));
                return c.change(renamer.changeIRI(from, to));
            });
        }
    }

    private static void pair(CommandTable table, String words, String[] args, boolean variadic, String addSummary,
                             String removeSummary, Function<CommandContext, List<? extends OWLAxiom>> axioms) {
        CommandTable.Builder add = table.command("ADD " + words).args(args).summary(addSummary);
        CommandTable.Builder remove = table.command("REMOVE " + words).args(args).summary(removeSummary);
        if (variadic) {
            add.variadic();
            remove.variadic();
        }
        if (ARMOR_PAIRS.contains(words)) {
            add.emptySurplusIgnored();
            remove.emptySurplusIgnored();
        }
        add.manipulation(c -> c.change(adds(c, axioms.apply(c))));
        remove.manipulation(c -> c.change(removes(c, axioms.apply(c))));
    }


    private static OWLAxiom objectCharacteristic(OWLDataFactory f, OWLObjectProperty p, String characteristic) {
        return switch (characteristic.trim().toUpperCase(Locale.ROOT)) {
            case "FUNCTIONAL" -> f.getOWLFunctionalObjectPropertyAxiom(p);
            case "INVERSE_FUNCTIONAL" -> f.getOWLInverseFunctionalObjectPropertyAxiom(p);
            case "TRANSITIVE" -> f.getOWLTransitiveObjectPropertyAxiom(p);
            case "SYMMETRIC" -> f.getOWLSymmetricObjectPropertyAxiom(p);
            case "ASYMMETRIC" -> f.getOWLAsymmetricObjectPropertyAxiom(p);
            case "REFLEXIVE" -> f.getOWLReflexiveObjectPropertyAxiom(p);
            case "IRREFLEXIVE" -> f.getOWLIrreflexiveObjectPropertyAxiom(p);
            default -> throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "unknown characteristic '" + characteristic
                    + "': expected FUNCTIONAL, INVERSE_FUNCTIONAL, TRANSITIVE, SYMMETRIC, ASYMMETRIC, REFLEXIVE"
                    + " or IRREFLEXIVE");
        };
    }

    private static OWLAxiom dataCharacteristic(OWLDataFactory f, OWLDataProperty p, String characteristic) {
        if (!characteristic.trim().equalsIgnoreCase("FUNCTIONAL")) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "a data property can only be FUNCTIONAL in OWL 2, not '"
                    + characteristic + "'");
        }
        return f.getOWLFunctionalDataPropertyAxiom(p);
    }



    /**
     * Removes the stored value the old value means (see {@link Literals#stored}) and adds the new
     * one. An old value that matches nothing stored removes nothing, as in ARMOR; when the
     * individual keeps other values the answer says so, since the property now has several.
     */
    private static io.github.armor.core.api.Response replaceDataValue(CommandContext c) {
        OWLDataFactory f = c.factory();
        OWLDataProperty property = c.dataProperty(0);
        OWLNamedIndividual individual = c.individual(1);
        org.semanticweb.owlapi.model.OWLLiteral given = c.literal(2, 4);
        org.semanticweb.owlapi.model.OWLLiteral old = Literals.stored(c.reference().ontology(), property, individual,
                given);
        org.semanticweb.owlapi.model.OWLLiteral added = c.literal(2, 3);
        List<org.semanticweb.owlapi.model.OWLLiteral> before = Literals.values(c.reference().ontology(), property,
                individual);
        List<OWLOntologyChange> changes = new ArrayList<>(removes(c, List.of(
                f.getOWLDataPropertyAssertionAxiom(property, individual, old))));
        changes.addAll(adds(c, List.of(f.getOWLDataPropertyAssertionAxiom(property, individual, added))));
        io.github.armor.core.api.Response response = c.change(changes);
        List<org.semanticweb.owlapi.model.OWLLiteral> kept = before.stream()
                .filter(v -> !v.equals(old) && !v.equals(added)).toList();
        if (!before.contains(old) && !kept.isEmpty()) {
            return response.withDescription("old value " + Rendering.literal(given) + " was not stored, nothing"
                    + " removed; " + property.getIRI().getShortForm() + " of " + individual.getIRI().getShortForm()
                    + " keeps " + kept.stream().map(Rendering::literal).collect(Collectors.joining(", "))
                    + " beside " + Rendering.literal(added));
        }
        return response;
    }

    private static List<OWLOntologyChange> makeEquivalentChanges(CommandContext c) {
        Reference reference = c.reference();
        OWLClass owlClass = c.owlClass(0);
        List<OWLSubClassOfAxiom> subClassOf = reference.ontology().subClassAxiomsForSubClass(owlClass).toList();
        if (subClassOf.isEmpty()) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "class '" + c.arg(0)
                    + "' has no superclasses to make it equivalent to");
        }
        Set<OWLClassExpression> supers = subClassOf.stream().map(OWLSubClassOfAxiom::getSuperClass)
                .collect(Collectors.toCollection(LinkedHashSet::new));
        OWLClassExpression definition = supers.size() == 1 ? supers.iterator().next()
                : c.factory().getOWLObjectIntersectionOf(supers);
        List<OWLOntologyChange> changes = new ArrayList<>(removes(c, subClassOf));
        changes.addAll(adds(c, List.of(c.factory().getOWLEquivalentClassesAxiom(owlClass, definition))));
        return changes;
    }


    private static List<OWLOntologyChange> removeEntity(Reference reference, OWLEntity entity) {
        OWLEntityRemover remover = new OWLEntityRemover(reference.ontology().importsClosure());
        entity.accept(remover);
        return new ArrayList<>(remover.getChanges());
    }

    /** The operands of an n-ary axiom: two different ones at least, which OWL needs to write it down. */
    private static <T> Set<T> all(CommandContext c, java.util.function.BiFunction<CommandContext, Integer, T> entity) {
        Set<T> operands = IntStream.range(0, c.args().size()).mapToObj(i -> entity.apply(c, i))
                .collect(Collectors.toCollection(LinkedHashSet::new));
        if (operands.size() < 2) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, c.directive().describe()
                    + " needs two different names at least; it was given " + c.args());
        }
        return operands;
    }

    static int cardinality(String text) {
        try {
            int n = Integer.parseInt(text.trim());
            if (n >= 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // answered below
        }
        throw new ArmorException(ExitCode.BAD_DATA_TYPE, "cardinality must be a whole number >= 0, got '" + text + "'");
    }

    static List<OWLOntologyChange> adds(CommandContext c, List<? extends OWLAxiom> axioms) {
        return axioms.stream().map(a -> (OWLOntologyChange) new AddAxiom(c.reference().ontology(), a)).toList();
    }

    static List<OWLOntologyChange> removes(CommandContext c, List<? extends OWLAxiom> axioms) {
        return axioms.stream().map(a -> (OWLOntologyChange) new RemoveAxiom(c.reference().ontology(), a)).toList();
    }
}
