// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.reference.ReasonerRegistry;
import org.junit.jupiter.api.Test;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.io.StringDocumentSource;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;

/** What the kept class hierarchy is classified from: SWRL rules only where they can fire. */
class ClassifiedSchemaTest {
    private static final String NS = "http://www.example.org/schema#";
    // The course map's kind of rule: a built-in HermiT refuses.
    private static final String URGENT_RULE = """
            DLSafeRule(Body(ClassAtom(:Location Variable(<urn:v#l>))
                DataPropertyAtom(:visitedAt Variable(<urn:v#l>) Variable(<urn:v#t>))
                BuiltInAtom(<http://www.w3.org/2003/11/swrlb#greaterThan> Variable(<urn:v#t>) "10"^^xsd:integer))
                Head(ClassAtom(:Urgent Variable(<urn:v#l>))))
            """;

    private static OWLOntology ontology(String axioms) throws Exception {
        return OWLManager.createOWLOntologyManager().loadOntologyFromOntologyDocument(new StringDocumentSource(
                "Prefix(:=<" + NS + ">) Prefix(xsd:=<http://www.w3.org/2001/XMLSchema#>) Ontology(<" + NS + "o> "
                        + axioms + ")"));
    }

    private static OWLClass named(String name) {
        return OWLManager.getOWLDataFactory().getOWLClass(IRI.create(NS + name));
    }

    @Test
    void aSchemaWithRulesButNoIndividualsIsClassifiedWithoutThem() throws Exception {
        OWLOntology map = ontology("SubClassOf(:Room :Location) SubClassOf(:Corridor :Location) "
                + "ClassAssertion(:Room :kitchen) " + URGENT_RULE);
        ClassifiedSchema.Input input = ClassifiedSchema.inputOf(map, "HERMIT");
        assertFalse(input.axioms().stream().anyMatch(axiom -> axiom.isOfType(AxiomType.SWRL_RULE)), input::toString);
        ClassifiedSchema classified = ClassifiedSchema.classify(input,
                ReasonerRegistry.factory("HERMIT").createReasoner(
                        OWLManager.createOWLOntologyManager().createOntology(input.axioms().stream()),
                        new SimpleConfiguration()));
        assertNotNull(classified);
        assertTrue(classified.superClasses(named("Room"), true).containsEntity(named("Location")));
    }

    @Test
    void aSchemaNamingIndividualsKeepsItsRules() throws Exception {
        OWLOntology map = ontology("EquivalentClasses(:Home ObjectOneOf(:kitchen)) " + URGENT_RULE);
        assertTrue(ClassifiedSchema.inputOf(map, "HERMIT").axioms().stream()
                .anyMatch(axiom -> axiom.isOfType(AxiomType.SWRL_RULE)));
    }
}
