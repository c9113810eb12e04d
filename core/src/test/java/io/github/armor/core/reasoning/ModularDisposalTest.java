// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.armor.core.reference.ReasonerRegistry;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.io.StringDocumentSource;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;

/**
 * A call abandoned at a reasoner time limit can finish after the reference disposed its reasoner:
 * its failure must end there, not build a whole-ontology reasoner nobody will dispose.
 */
class ModularDisposalTest {
    private static final String NS = "http://www.example.org/disposal#";

    /** HermiT, counting the reasoners made. */
    private static final class CountingFactory implements OWLReasonerFactory {
        final OWLReasonerFactory hermit = ReasonerRegistry.factory("HERMIT");
        final AtomicInteger made = new AtomicInteger();

        @Override
        public String getReasonerName() {
            return hermit.getReasonerName();
        }

        @Override
        public OWLReasoner createNonBufferingReasoner(OWLOntology ontology) {
            made.incrementAndGet();
            return hermit.createNonBufferingReasoner(ontology);
        }

        @Override
        public OWLReasoner createReasoner(OWLOntology ontology) {
            made.incrementAndGet();
            return hermit.createReasoner(ontology);
        }

        @Override
        public OWLReasoner createNonBufferingReasoner(OWLOntology ontology, OWLReasonerConfiguration configuration) {
            made.incrementAndGet();
            return hermit.createNonBufferingReasoner(ontology, configuration);
        }

        @Override
        public OWLReasoner createReasoner(OWLOntology ontology, OWLReasonerConfiguration configuration) {
            made.incrementAndGet();
            return hermit.createReasoner(ontology, configuration);
        }
    }

    @Test
    void aCallFinishingAfterDisposalBuildsNoReasoner() throws Exception {
        OWLOntology ontology = OWLManager.createOWLOntologyManager().loadOntologyFromOntologyDocument(
                new StringDocumentSource("Prefix(:=<" + NS + ">) Ontology(<" + NS + "o> "
                        + "ClassAssertion(:Robot :r1) ObjectPropertyAssertion(:isIn :r1 :kitchen))"));
        CountingFactory factory = new CountingFactory();
        ModularReasoner reasoner = new ModularReasoner("HERMIT", factory, ontology, new SimpleConfiguration());
        assertTrue(reasoner.isConsistent());
        assertTrue(reasoner.plan().modular(), reasoner.plan()::describe);
        OWLDataFactory data = OWLManager.getOWLDataFactory();
        ontology.add(data.getOWLClassAssertionAxiom(data.getOWLClass(IRI.create(NS + "Robot")),
                data.getOWLNamedIndividual(IRI.create(NS + "r2"))));
        int madeBefore = factory.made.get();

        reasoner.dispose();
        // The change pending when the reference gave up on this reasoner, flushed by the abandoned call.
        assertThrows(RuntimeException.class, reasoner::flush);
        assertEquals(madeBefore, factory.made.get(), "a reasoner was built after dispose");
    }
}
