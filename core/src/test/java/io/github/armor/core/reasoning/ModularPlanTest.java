// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.reference.ReasonerRegistry;
import org.junit.jupiter.api.Test;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.io.StringDocumentSource;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;

/**
 * How an ontology is cut into modules (issue 28 items 1, 3 and 4; issue 36 item 3): which shapes
 * tie nothing, which nominals leave the ABox modular, and what the plan says when it is not.
 */
class ModularPlanTest {
    private static final String NS = "http://www.example.org/shapes#";

    private ModularReasoner reasoned(String axioms) throws Exception {
        return reasoned(axioms, "HERMIT");
    }

    private ModularReasoner reasoned(String axioms, String reasonerName) throws Exception {
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        OWLOntology ontology = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(
                "Prefix(:=<" + NS + ">) Ontology(<" + NS + "o> " + axioms + ")"));
        ModularReasoner reasoner = new ModularReasoner(reasonerName, ReasonerRegistry.factory(reasonerName), ontology,
                new SimpleConfiguration());
        reasoner.isConsistent();
        return reasoner;
    }

    /** A depot: aisles in zones in the depot (transitive), aisles adjacent (symmetric), robots located at aisles. */
    private static String depot(int aisles) {
        StringBuilder abox = new StringBuilder("""
                TransitiveObjectProperty(:partOf) ObjectPropertyDomain(:partOf :Place)
                SymmetricObjectProperty(:adjacentTo) FunctionalObjectProperty(:locatedAt)
                EquivalentClasses(:BusyPlace ObjectIntersectionOf(:Place
                    ObjectSomeValuesFrom(ObjectInverseOf(:locatedAt) :Agent)))
                ObjectPropertyAssertion(:partOf :zone :depot)
                """);
        for (int i = 0; i < aisles; i++) {
            abox.append("ClassAssertion(:Place :aisle").append(i).append(") ObjectPropertyAssertion(:partOf :aisle")
                    .append(i).append(" :zone) ClassAssertion(:Agent :robot").append(i)
                    .append(") ObjectPropertyAssertion(:locatedAt :robot").append(i).append(" :aisle").append(i)
                    .append(")\n");
            if (i > 0) {
                abox.append("ObjectPropertyAssertion(:adjacentTo :aisle").append(i).append(" :aisle").append(i - 1)
                        .append(")\n");
            }
        }
        return abox.toString();
    }

    @Test
    void aPartOfTreeAndAnAdjacencyNothingObservesTieNothing() throws Exception {
        ModularReasoner reasoner = reasoned(depot(10));
        ReasoningPlan plan = reasoner.plan();
        assertTrue(plan.modular(), plan::describe);
        // Each aisle with its robot, the zone, the depot.
        assertEquals(12, plan.modules(), plan::describe);
        assertEquals(2, plan.largest(), plan::describe);
    }

    @Test
    void aChainWhoseSuperPropertyHasARangeTiesItsLinks() throws Exception {
        ModularReasoner reasoner = reasoned(depot(10) + """
                SubObjectPropertyOf(ObjectPropertyChain(:locatedAt :partOf) :within) ObjectPropertyRange(:within :Place)
                """);
        // locatedAt and partOf now link: the whole tree is one module.
        assertEquals(1, reasoner.plan().modules(), reasoner.plan()::describe);
    }

    @Test
    void differentIndividualsOfAWholeMapTieNothing() throws Exception {
        StringBuilder everyone = new StringBuilder("DifferentIndividuals(:zone :depot");
        for (int i = 0; i < 10; i++) {
            everyone.append(" :aisle").append(i).append(" :robot").append(i);
        }
        ModularReasoner reasoner = reasoned(depot(10) + everyone + ")");
        assertEquals(12, reasoner.plan().modules(), reasoner.plan()::describe);
    }

    /** SOMA's execution states: an enumeration of individuals only the upper ontology uses. */
    private static final String ENUMERATION = """
            EquivalentClasses(:ExecutionStateRegion ObjectOneOf(:active :failed)) SubClassOf(:ExecutionStateRegion :Region)
            ObjectPropertyRange(:hasExecutionState :ExecutionStateRegion)
            ClassAssertion(:ExecutionStateRegion :active) ClassAssertion(:ExecutionStateRegion :failed)
            """;

    @Test
    void anEnumerationTheAboxNeverReachesLeavesItModular() throws Exception {
        ModularReasoner reasoner = reasoned(depot(10) + ENUMERATION);
        ReasoningPlan plan = reasoner.plan();
        assertTrue(plan.modular(), plan::describe);
        assertEquals(2, plan.hub(), plan::describe);
        assertEquals(13, plan.modules(), plan::describe);
    }

    @Test
    void anAboxThatReachesTheEnumerationIsReasonedOnWholeAndSaysWhy() throws Exception {
        ModularReasoner reasoner = reasoned(depot(10) + ENUMERATION + "ObjectPropertyAssertion(:hasExecutionState "
                + ":robot1 :state)");
        ReasoningPlan plan = reasoner.plan();
        assertTrue(plan.whole(), plan::describe);
        assertTrue(plan.describe().contains("ExecutionStateRegion"), plan::describe);
    }

    @Test
    void aHasValueClassTiesOnlyWhatIsLinkedToItsIndividual() throws Exception {
        OWLDataFactory factory = OWLManager.getOWLDataFactory();
        ModularReasoner reasoner = reasoned(depot(10) + """
                EquivalentClasses(:AtDock ObjectIntersectionOf(:Agent ObjectHasValue(:locatedAt :aisle0)))
                """);
        ReasoningPlan plan = reasoner.plan();
        assertTrue(plan.modular(), plan::describe);
        assertEquals(2, plan.hub(), plan::describe);
        assertTrue(reasoner.getInstances(factory.getOWLClass(IRI.create(NS + "AtDock")), false).entities()
                .anyMatch(robot -> robot.getIRI().toString().equals(NS + "robot0")));
        assertFalse(reasoner.getInstances(factory.getOWLClass(IRI.create(NS + "AtDock")), false).entities()
                .anyMatch(robot -> robot.getIRI().toString().equals(NS + "robot1")));
    }

    @Test
    void rulesBesideAFunctionalPropertyMakeItWholeAndThePlanSaysWhy() throws Exception {
        ModularReasoner reasoner = reasoned(depot(3) + """
                DLSafeRule(Body(ClassAtom(:Agent Variable(<urn:v#x>))) Head(ClassAtom(:Robot Variable(<urn:v#x>))))
                """);
        assertEquals("on the whole ontology: SWRL rules with an axiom that can make two individuals one:"
                + " FunctionalObjectProperty(<" + NS + "locatedAt>)", reasoner.plan().describe());
    }

    /** The depot without its functional property: Horn, so the rules are evaluated beside the modules. */
    private static String hornDepot(String rules) {
        return depot(3).replace("FunctionalObjectProperty(:locatedAt)", "") + rules;
    }

    @Test
    void rulesOverAHornSchemaStayBesideTheModules() throws Exception {
        ModularReasoner reasoner = reasoned(hornDepot("""
                DLSafeRule(Body(ClassAtom(:Agent Variable(<urn:v#x>)) ObjectPropertyAtom(:locatedAt Variable(<urn:v#x>)
                    Variable(<urn:v#p>))) Head(ClassAtom(:Placed Variable(<urn:v#p>))))
                """));
        assertTrue(reasoner.plan().modular(), reasoner.plan()::describe);
        // Each aisle with its robot (BusyPlace observes locatedAt), the zone, the depot: the rule ties nothing.
        assertEquals(5, reasoner.plan().modules(), reasoner.plan()::describe);
        OWLDataFactory factory = OWLManager.getOWLDataFactory();
        assertEquals(3, reasoner.getInstances(factory.getOWLClass(IRI.create(NS + "Placed")), false).nodes().count());
    }

    @Test
    void rulesThatCannotBeEvaluatedBesideTheModulesSayWhy() throws Exception {
        String rule = "DLSafeRule(Body(ObjectPropertyAtom(:%s Variable(<urn:v#x>) Variable(<urn:v#y>)))"
                + " Head(ObjectPropertyAtom(:%s Variable(<urn:v#x>) Variable(<urn:v#y>))))\n";
        assertTrue(reasoned(hornDepot(String.format(rule, "partOf", "near"))).plan().describe()
                .startsWith("on the whole ontology: SWRL rules over partOf, whose edges TransitiveObjectProperty"));
        assertTrue(reasoned(hornDepot(String.format(rule, "near", "near"))).plan().describe()
                .startsWith("on the whole ontology: SWRL rules whose conclusions feed one another"));
        // Openllet on the whole ontology: HermiT refuses built-ins.
        assertTrue(reasoned(hornDepot("""
                DLSafeRule(Body(DataPropertyAtom(:name Variable(<urn:v#x>) Variable(<urn:v#n>))
                    BuiltInAtom(<http://www.w3.org/2003/11/swrlb#stringLength> Variable(<urn:v#l>) Variable(<urn:v#n>)))
                    Head(ClassAtom(:Named Variable(<urn:v#x>))))
                """), "PELLET").plan().describe().contains("built-in http://www.w3.org/2003/11/swrlb#stringLength"));
    }
}
