// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.view;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reference.Classification;
import io.github.armor.core.reference.Reference;
import java.util.function.ToLongFunction;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.parameters.Imports;

/**
 * Every reference at a glance: reasoner, buffering modes, mount holder and the lease it has left,
 * consistency, counts of entities and axioms, and the last reasoning's time and duration.
 */
final class Overview {
    /**
     * The longest an overview waits for a busy reference: a reference reasoning for a minute must
     * not hold up the page's view of the others, so it is shown as busy instead of its counts.
     */
    static final long BUSY_WAIT_MS = 200;

    private final ViewReads reads;
    private final ToLongFunction<String> leaseLeftMs;

    /** {@code leaseLeftMs}: for a mount holder, the ms its mount has left (negative: it never expires). */
    Overview(ViewReads reads, ToLongFunction<String> leaseLeftMs) {
        this.reads = reads;
        this.leaseLeftMs = leaseLeftMs;
    }

    JsonObject all() {
        JsonArray summaries = new JsonArray();
        for (String name : reads.references().names()) {
            reads.references().find(name).ifPresent(reference -> summaries.add(summary(reference, BUSY_WAIT_MS)));
        }
        JsonObject view = new JsonObject();
        view.add("references", summaries);
        return view;
    }

    /** One reference's summary, with its object and data properties (the page's graph and value choices). */
    JsonObject one(String name) {
        Reference reference = reads.reference(name);
        JsonObject summary = summary(reference, BUSY_WAIT_MS);
        reads.whole(reference, r -> {
            OWLOntology ontology = r.ontology();
            summary.add("object_properties", ViewJson.entities(ontology.getObjectPropertiesInSignature(
                    Imports.INCLUDED)));
            summary.add("data_properties", ViewJson.entities(ontology.getDataPropertiesInSignature(
                    Imports.INCLUDED)));
            return null;
        });
        return summary;
    }

    private JsonObject summary(Reference reference, long waitMs) {
        JsonObject summary = new JsonObject();
        summary.addProperty("name", reference.name());
        summary.addProperty("revision", reference.revision());
        summary.addProperty("source", reference.source() == null ? "" : reference.source());
        summary.addProperty("reasoner", reference.reasonerName());
        summary.addProperty("buffered_manipulation", reference.settings().bufferedManipulation());
        summary.addProperty("buffered_reasoner", reference.settings().bufferedReasoner());
        summary.addProperty("consistent", reference.isConsistent());
        summary.addProperty("reasoning", reference.reasoningPlan().describe());
        summary.addProperty("reasoned_on_whole", reference.reasoningPlan().whole());
        String holder = reference.mountedBy();
        summary.addProperty("mounted_by", holder);
        if (!holder.isEmpty()) {
            long left = leaseLeftMs.applyAsLong(holder);
            if (left >= 0) {
                summary.addProperty("lease_left_s", left / 1000.0);
            }
        }
        if (reference.lastReasoningEpochMs() > 0) {
            summary.addProperty("last_reasoning_at_ms", reference.lastReasoningEpochMs());
            summary.addProperty("last_reasoning_ms", reference.lastReasoningNanos() / 1e6);
        }
        summary.addProperty("profile", reference.coverage().profileName());
        if (reads.offLock(reference).isPresent()) {
            // Counted without the reference's lock: its ontology may be read while a writer changes it.
            counts(reference, summary);
            summary.addProperty("busy", reference.heldByDirective());
            return summary;
        }
        try {
            reference.lockedForView(waitMs, r -> {
                counts(r, summary);
                return null;
            });
            summary.addProperty("busy", false);
        } catch (ArmorException e) {
            if (e.exitCode() != ExitCode.TIMEOUT) {
                throw e;
            }
            summary.addProperty("busy", true);
        }
        return summary;
    }

    /** Entity and axiom counts, buffered changes, and the classes' cost (classification). */
    private static void counts(Reference r, JsonObject summary) {
        OWLOntology ontology = r.ontology();
        summary.addProperty("pending_changes", r.hasPending());
        Classification classification = r.classification();
        summary.addProperty("classification", classification.describe());
        if (classification.kept()) {
            summary.addProperty("classification_ms", classification.nanos() / 1e6);
        }
        summary.addProperty("classes", ontology.getClassesInSignature(Imports.INCLUDED).size());
        summary.addProperty("individuals", ontology.getIndividualsInSignature(Imports.INCLUDED).size());
        summary.addProperty("object_property_count",
                ontology.getObjectPropertiesInSignature(Imports.INCLUDED).size());
        summary.addProperty("data_property_count",
                ontology.getDataPropertiesInSignature(Imports.INCLUDED).size());
        summary.addProperty("axioms", ontology.importsClosure().mapToLong(OWLOntology::getAxiomCount).sum());
        summary.addProperty("logical_axioms",
                ontology.importsClosure().mapToLong(OWLOntology::getLogicalAxiomCount).sum());
    }
}
