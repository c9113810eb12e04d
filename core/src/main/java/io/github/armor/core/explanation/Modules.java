// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.explanation;

import java.util.Set;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.modularity.locality.LocalityClass;
import org.semanticweb.owlapi.modularity.locality.SyntacticLocalityModuleExtractor;

/**
 * Syntactic locality (STAR) modules of sets of axioms, with the OWL API's extractor that reads the
 * axioms as they are: its older one (uk.ac.manchester.cs.owlapi.modularity) first copies them into
 * a new ontology, on each of the twenty or so small sets a search checks. (The search's first
 * module and the library's keep the older extractor: the order of the axioms it returns decides
 * which justification the library finds first, and tests and users expect that one.)
 */
final class Modules {
    private Modules() {}

    /** The STAR module of {@code signature} in {@code axioms}. */
    static Set<OWLAxiom> star(Set<OWLAxiom> axioms, Set<OWLEntity> signature) {
        // The extractor fails on an entity no axiom mentions (OWL API 5.5.1); such an entity
        // cannot make an axiom non-local, so leaving it out changes no module.
        Set<OWLEntity> mentioned = axioms.stream().flatMap(OWLAxiom::signature).collect(Collectors.toSet());
        return new SyntacticLocalityModuleExtractor(LocalityClass.STAR, axioms.stream())
                .extract(signature.stream().filter(mentioned::contains)).collect(Collectors.toSet());
    }
}
