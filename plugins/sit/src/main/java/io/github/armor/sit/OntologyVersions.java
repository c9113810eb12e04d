// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.Map;
import java.util.WeakHashMap;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyManager;

/**
 * How often each ontology has changed, counted by a listener on its manager: what is derived from
 * an ontology (its learned classes, its schema reasoned on) is kept while the count of it and of
 * its imports stays the same. Weak keys: an ontology that is gone takes its count with it.
 */
final class OntologyVersions {
    private static final Map<OWLOntology, long[]> CHANGES = new WeakHashMap<>();
    private static final Map<OWLOntologyManager, Boolean> WATCHED = new WeakHashMap<>();

    private OntologyVersions() {}

    /** The number of changes made to the ontology and its imports since it was first asked about. */
    static synchronized long of(OWLOntology ontology) {
        OWLOntologyManager manager = ontology.getOWLOntologyManager();
        if (WATCHED.put(manager, Boolean.TRUE) == null) {
            manager.addOntologyChangeListener(OntologyVersions::changed);
        }
        // Counts only grow, so their sum moves with any change (an import added or removed is one).
        return ontology.importsClosure().mapToLong(o -> CHANGES.computeIfAbsent(o, k -> new long[1])[0]).sum();
    }

    private static synchronized void changed(java.util.List<? extends OWLOntologyChange> changes) {
        for (OWLOntologyChange change : changes) {
            CHANGES.computeIfAbsent(change.getOntology(), k -> new long[1])[0]++;
        }
    }
}
