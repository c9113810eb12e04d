// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.Map;
import java.util.WeakHashMap;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyManager;

/**
 * How often the ontologies of a manager have changed, counted by a listener on it: what is
 * derived from an ontology (its learned classes, its schema reasoned on) is kept while the count
 * stays the same. Counted per manager, which holds the ontology and its imports (a reference has
 * a manager of its own), and compared by identity (ontologies are equal when their IRIs are);
 * weak keys: a manager that is gone takes its count with it.
 */
final class OntologyVersions {
    private static final Map<OWLOntologyManager, long[]> CHANGES = new WeakHashMap<>();

    private OntologyVersions() {}

    /** The number of changes made in the ontology's manager since it was first asked about. */
    static synchronized long of(OWLOntology ontology) {
        OWLOntologyManager manager = ontology.getOWLOntologyManager();
        long[] count = CHANGES.get(manager);
        if (count == null) {
            long[] made = new long[1];
            CHANGES.put(manager, made);
            // The listener holds the count, not the manager: the weak key can still go.
            manager.addOntologyChangeListener(changes -> {
                synchronized (OntologyVersions.class) {
                    made[0]++;
                }
            });
            count = made;
        }
        return count[0];
    }
}
