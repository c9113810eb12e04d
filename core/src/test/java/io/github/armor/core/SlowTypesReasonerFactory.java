// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.reasoner.BufferingMode;
import org.semanticweb.owlapi.reasoner.NodeSet;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;
import org.semanticweb.owlapi.reasoner.structural.StructuralReasoner;
import org.semanticweb.owlapi.reasoner.structural.StructuralReasonerFactory;
import org.semanticweb.owlapi.model.OWLClass;

/**
 * A reasoner (named by class) that takes {@link #TYPES_MS} to answer an individual's types, as
 * a real one may on a large ABox: a view over many individuals then takes long enough to show
 * whether it lets other directives in while it runs.
 */
public class SlowTypesReasonerFactory extends StructuralReasonerFactory {
    static final long TYPES_MS = 10;

    @Override
    public OWLReasoner createReasoner(OWLOntology ontology, OWLReasonerConfiguration config) {
        return new SlowTypesReasoner(ontology, config, BufferingMode.BUFFERING);
    }

    @Override
    public OWLReasoner createNonBufferingReasoner(OWLOntology ontology, OWLReasonerConfiguration config) {
        return new SlowTypesReasoner(ontology, config, BufferingMode.NON_BUFFERING);
    }

    static final class SlowTypesReasoner extends StructuralReasoner {
        SlowTypesReasoner(OWLOntology ontology, OWLReasonerConfiguration config, BufferingMode mode) {
            super(ontology, config, mode);
        }

        @Override
        public NodeSet<OWLClass> getTypes(OWLNamedIndividual individual, boolean direct) {
            try {
                Thread.sleep(TYPES_MS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return super.getTypes(individual, direct);
        }
    }
}
