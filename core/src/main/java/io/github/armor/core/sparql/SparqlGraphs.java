// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import io.github.armor.core.reference.Reference;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.WeakHashMap;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyChangeListener;

/**
 * Each reference's SPARQL graph ({@link InferredGraph}), made once per state of the reference and
 * shared by every query until the reference changes (its modification count moves). The first
 * query after a change pays for the new graph: derived from the last one when the ontology
 * changes since allow it, built afresh otherwise.
 *
 * <p>A reference gets a graph at its first SPARQL query; from then on the ontology changes are
 * recorded (an OWL API change listener), so that the next graph knows what changed. The map
 * holds references weakly: a dropped reference takes its graph with it.
 */
final class SparqlGraphs {
    /** Beyond this many changes between two queries, a fresh build is cheaper than replaying them. */
    static final int MAX_CHANGES_TO_REPLAY = 2000;

    private static final Map<Reference, Tracker> TRACKERS = Collections.synchronizedMap(new WeakHashMap<>());

    private SparqlGraphs() {}

    /** The graph of the reference as it is now; under the reference's lock. */
    static InferredGraph current(Reference reference) {
        return TRACKERS.computeIfAbsent(reference, r -> new Tracker(r.ontology())).current(reference);
    }

    /**
     * One reference's last graph and the ontology changes since it was made. Holds no reference
     * to the {@link Reference} itself (the map's key must stay weakly held).
     */
    private static final class Tracker implements OWLOntologyChangeListener {
        private final OWLOntology ontology;
        private final List<OWLOntologyChange> changes = new ArrayList<>();
        private boolean mustRebuild;
        private InferredGraph graph;

        Tracker(OWLOntology ontology) {
            this.ontology = ontology;
            ontology.getOWLOntologyManager().addOntologyChangeListener(this);
        }

        InferredGraph current(Reference reference) {
            reference.reasonerForQuery(); // an inconsistent reference answers INCONSISTENT, as to every query
            long version = reference.modificationCount();
            if (graph != null && graph.version() == version) {
                return graph;
            }
            InferredGraph next = graph != null && !mustRebuild
                    ? graph.updated(reference, List.copyOf(changes), version) : null;
            if (next == null) {
                next = InferredGraph.build(reference, version);
            }
            graph = next;
            changes.clear();
            mustRebuild = false;
            return graph;
        }

        /** Called by the OWL API inside every change of the reference's manager, under the reference's lock. */
        @Override
        public void ontologiesChanged(List<? extends OWLOntologyChange> enacted) {
            if (graph == null || mustRebuild) {
                return;
            }
            for (OWLOntologyChange change : enacted) {
                if (change.getOntology() == ontology) {
                    changes.add(change);
                } else if (ontology.importsClosure().anyMatch(imported -> imported == change.getOntology())) {
                    mustRebuild = true;
                }
            }
            if (changes.size() > MAX_CHANGES_TO_REPLAY) {
                mustRebuild = true;
            }
            if (mustRebuild) {
                changes.clear();
            }
        }
    }
}
