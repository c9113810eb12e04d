// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.reasoning.AboxModules.Module;
import io.github.armor.core.reference.ReasonerRegistry;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.io.StringDocumentSource;
import org.semanticweb.owlapi.model.AddAxiom;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.RemoveAxiom;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;

/**
 * Twins collapsed ({@link ModuleTwins}): which members are twins, and that reasoning on modules
 * with their twins collapsed answers as a reasoner on the whole ontology does where counting,
 * difference and cardinality limits could tell twins apart.
 */
class ModuleTwinsTest {
    private static final String NS = "http://www.example.org/twins#";
    private static final String ONTOLOGY = """
            Prefix(:=<http://www.example.org/twins#>)
            Ontology(<http://www.example.org/twins>
            SubClassOf(:Drawer :Container) SubClassOf(:Cupboard :Container)
            SubClassOf(:Cup :Tableware) SubClassOf(:Plate :Tableware) DisjointClasses(:Cup :Plate)
            InverseObjectProperties(:contains :isInsideOf) SubObjectPropertyOf(:isInsideOf :within)
            TransitiveObjectProperty(:within)
            EquivalentClasses(:CupSomewhereInside ObjectSomeValuesFrom(ObjectInverseOf(:within) :Cup))
            EquivalentClasses(:WithCup ObjectIntersectionOf(:Container ObjectSomeValuesFrom(:contains :Cup)))
            EquivalentClasses(:TwoTableware ObjectIntersectionOf(:Container ObjectMinCardinality(2 :contains :Tableware)))
            EquivalentClasses(:Crowded ObjectMinCardinality(3 :contains owl:Thing))
            SubClassOf(:SmallDrawer ObjectMaxCardinality(1 :contains :Cup))
            ClassAssertion(:Drawer :drawer1) ClassAssertion(:Cup :cup1) ClassAssertion(:Cup :cup2) ClassAssertion(:Cup :cup3)
            ObjectPropertyAssertion(:isInsideOf :cup1 :drawer1) ObjectPropertyAssertion(:isInsideOf :cup2 :drawer1)
            ObjectPropertyAssertion(:isInsideOf :cup3 :drawer1)
            ClassAssertion(:Drawer :drawer2) ClassAssertion(:Cup :cup4) ClassAssertion(:Plate :plate1)
            ObjectPropertyAssertion(:isInsideOf :cup4 :drawer2) ObjectPropertyAssertion(:isInsideOf :plate1 :drawer2)
            ClassAssertion(:Drawer :drawer3) ClassAssertion(:Cup :cup5) ClassAssertion(:Cup :cup6)
            ObjectPropertyAssertion(:isInsideOf :cup5 :drawer3) ObjectPropertyAssertion(:isInsideOf :cup6 :drawer3)
            DifferentIndividuals(:cup5 :cup6)
            ClassAssertion(:SmallDrawer :drawer4) ClassAssertion(:Cup :cup7) ClassAssertion(:Cup :cup8)
            ObjectPropertyAssertion(:isInsideOf :cup7 :drawer4) ObjectPropertyAssertion(:isInsideOf :cup8 :drawer4)
            ClassAssertion(:Cupboard :cupboard1) ClassAssertion(:Drawer :drawer5) ClassAssertion(:Drawer :drawer6)
            ObjectPropertyAssertion(:isInsideOf :drawer5 :cupboard1) ObjectPropertyAssertion(:isInsideOf :drawer6 :cupboard1)
            ClassAssertion(:Cup :cup9) ClassAssertion(:Cup :cup10) ClassAssertion(:Plate :plate2)
            ObjectPropertyAssertion(:isInsideOf :cup9 :drawer5) ObjectPropertyAssertion(:isInsideOf :cup10 :drawer5)
            ObjectPropertyAssertion(:isInsideOf :plate2 :drawer6)
            ClassAssertion(:Drawer :drawer7) ClassAssertion(:Cup :cup11)
            ObjectPropertyAssertion(:isInsideOf :cup11 :drawer7)
            ClassAssertion(:Drawer :drawer8)
            )""";

    private OWLOntologyManager manager;
    private OWLDataFactory factory;
    private OWLOntology ontology;

    private void load() throws Exception {
        manager = OWLManager.createOWLOntologyManager();
        factory = manager.getOWLDataFactory();
        ontology = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(ONTOLOGY));
    }

    @Test
    void membersAlikeButForThemselvesAreTwinsAndNothingElseIs() throws Exception {
        load();
        ModuleTwins twins = new ModuleTwins(manager);
        ModuleTwins.Collapsed drawer1 = twins.collapse(module("drawer1", "cup1", "cup2", "cup3"),
                assertionsOf("drawer1", "cup1", "cup2", "cup3"));
        assertEquals(Set.of("drawer1", "cup1"), WholeOntologyAnswers.names(drawer1.kept().stream()));
        assertEquals(individual("cup1"), drawer1.twinOf().get(individual("cup3")));
        assertTrue(drawer1.axioms().stream().noneMatch(a -> a.containsEntityInSignature(individual("cup2"))));
        // Told different: the axiom names both, so they stay apart (and the drawer holds two tableware).
        ModuleTwins.Collapsed drawer3 = twins.collapse(module("drawer3", "cup5", "cup6"),
                assertionsOf("drawer3", "cup5", "cup6"));
        assertEquals(3, drawer3.kept().size(), () -> "kept " + drawer3.kept());
        // A cup and a plate are told apart by their classes; drawers holding different cups by those cups.
        assertEquals(3, twins.collapse(module("drawer2", "cup4", "plate1"),
                assertionsOf("drawer2", "cup4", "plate1")).kept().size());
        ModuleTwins.Collapsed cupboard = twins.collapse(
                module("cupboard1", "drawer5", "drawer6", "cup9", "cup10", "plate2"),
                assertionsOf("cupboard1", "drawer5", "drawer6", "cup9", "cup10", "plate2"));
        assertEquals(Set.of("cupboard1", "drawer5", "drawer6", "cup10", "plate2"), WholeOntologyAnswers.names(cupboard.kept().stream()));
    }

    @Test
    void membersTiedToEachOtherAreNotTwins() throws Exception {
        load();
        OWLNamedIndividual a = individual("a");
        OWLNamedIndividual b = individual("b");
        Set<OWLAxiom> axioms = new LinkedHashSet<>(List.of(
                factory.getOWLObjectPropertyAssertionAxiom(factory.getOWLObjectProperty(IRI.create(NS + "near")), a, b),
                factory.getOWLObjectPropertyAssertionAxiom(factory.getOWLObjectProperty(IRI.create(NS + "near")), b, a)));
        assertEquals(2, new ModuleTwins(manager).collapse(module("a", "b"), axioms).kept().size());
    }

    @ParameterizedTest
    @ValueSource(strings = {"HERMIT", "PELLET", "JFACT"})
    void modulesWithTwinsCollapsedAnswerAsTheWholeOntology(String reasonerName) throws Exception {
        load();
        OWLReasonerFactory reasonerFactory = ReasonerRegistry.factory(reasonerName);
        ModularReasoner modular = new ModularReasoner(reasonerName, reasonerFactory, ontology, new SimpleConfiguration());
        compare(reasonerFactory, modular, "the loaded kitchen");
        assertTrue(modular.handlesRemovals(), modular.wholeBecause());
        // drawer1 with its three cups collapsed is drawer7 with its one: reasoned on once.
        assertTrue(modular.reusedShapes() >= 1, () -> "shapes reused: " + modular.reusedShapes());
        // Told different, two cups overfill the small drawer; no longer told, they may be one cup again.
        OWLAxiom different = factory.getOWLDifferentIndividualsAxiom(individual("cup7"), individual("cup8"));
        List<List<OWLOntologyChange>> steps = List.of(
                List.of(new AddAxiom(ontology, different)),
                List.of(new RemoveAxiom(ontology, different)),
                move("cup3", "drawer1", "drawer8"),
                move("cup2", "drawer1", "drawer8"),
                List.of(new AddAxiom(ontology, factory.getOWLClassAssertionAxiom(cls("Cup"), individual("cup12"))),
                        new AddAxiom(ontology, factory.getOWLObjectPropertyAssertionAxiom(
                                factory.getOWLObjectProperty(IRI.create(NS + "isInsideOf")), individual("cup12"),
                                individual("drawer7")))),
                move("cup9", "drawer5", "drawer2"));
        for (List<OWLOntologyChange> step : steps) {
            manager.applyChanges(step);
            modular.flush();
            compare(reasonerFactory, modular, "after " + step);
        }
        modular.dispose();
    }

    private List<OWLOntologyChange> move(String item, String from, String to) {
        var property = factory.getOWLObjectProperty(IRI.create(NS + "isInsideOf"));
        return List.of(
                new RemoveAxiom(ontology, factory.getOWLObjectPropertyAssertionAxiom(property, individual(item), individual(from))),
                new AddAxiom(ontology, factory.getOWLObjectPropertyAssertionAxiom(property, individual(item), individual(to))));
    }

    private void compare(OWLReasonerFactory reasonerFactory, ModularReasoner modular, String when) {
        WholeOntologyAnswers.assertSameAnswers(reasonerFactory, ontology, modular, when);
        if (modular.isConsistent()) {
            assertFalse(modular.getInstances(cls("WithCup"), false).isEmpty(), "the kitchen must have drawers with cups");
        }
    }

    /** A module of these individuals (as AboxModules makes them: every assertion about them). */
    private Module module(String... members) {
        Set<OWLIndividual> individuals = new LinkedHashSet<>();
        for (String member : members) {
            individuals.add(individual(member));
        }
        return new Module(individuals);
    }

    private Set<OWLAxiom> assertionsOf(String... members) {
        Set<OWLAxiom> axioms = new LinkedHashSet<>();
        for (String member : members) {
            axioms.add(factory.getOWLDeclarationAxiom(individual(member)));
            ontology.referencingAxioms(individual(member)).filter(OWLAxiom::isLogicalAxiom).forEach(axioms::add);
        }
        return axioms;
    }

    private OWLNamedIndividual individual(String name) {
        return factory.getOWLNamedIndividual(IRI.create(NS + name));
    }

    private OWLClass cls(String name) {
        return factory.getOWLClass(IRI.create(NS + name));
    }
}
