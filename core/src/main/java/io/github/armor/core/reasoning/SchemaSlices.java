// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import uk.ac.manchester.cs.owlapi.modularity.ModuleType;
import uk.ac.manchester.cs.owlapi.modularity.SyntacticLocalityModuleExtractor;

/**
 * The part of a large schema that the assertions of some modules can use: its ⊥-locality module
 * for their classes and properties (and the classes asked about), found with the OWL API's
 * module extractor and kept per signature. A reasoner made on that part and the modules'
 * assertions gives the same consistency and the same types as one made on the whole schema:
 * every axiom left out stays true when every class and property outside the part's signature is
 * read as empty, so a model of the part extends to a model of the whole schema in which no
 * individual gets a class from outside the part (Cuenca Grau et al., "Modular Reuse of
 * Ontologies: Theory and Practice", JAIR 2008). SOMA's 2,447 schema axioms give a kitchen's
 * containers and tableware about 370.
 */
final class SchemaSlices {
    private static final int KEPT = 256;

    private final SyntacticLocalityModuleExtractor extractor;
    private final OWLDataFactory data;
    private final Map<Set<OWLEntity>, List<OWLAxiom>> kept = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Set<OWLEntity>, List<OWLAxiom>> eldest) {
            return size() > KEPT;
        }
    };

    SchemaSlices(OWLOntologyManager scratch, List<OWLAxiom> schema) {
        this.data = scratch.getOWLDataFactory();
        OWLOntology whole;
        try {
            whole = scratch.createOntology(schema.stream().filter(OWLAxiom::isLogicalAxiom));
        } catch (OWLOntologyCreationException e) {
            throw new IllegalStateException("could not create a scratch ontology", e);
        }
        this.extractor = new SyntacticLocalityModuleExtractor(scratch, whole, ModuleType.BOT);
    }

    /**
     * The schema part for assertions over {@code signature} (individuals are ignored), with a
     * declaration of every class and property the assertions use.
     */
    synchronized List<OWLAxiom> sliceFor(Set<OWLEntity> signature) {
        Set<OWLEntity> key = signature.stream().filter(e -> !e.isOWLNamedIndividual() && !e.isBuiltIn())
                .collect(Collectors.toUnmodifiableSet());
        return kept.computeIfAbsent(key, k -> {
            Set<OWLAxiom> slice = new HashSet<>(extractor.extract(k));
            k.forEach(entity -> slice.add(data.getOWLDeclarationAxiom(entity)));
            return List.copyOf(slice);
        });
    }
}
