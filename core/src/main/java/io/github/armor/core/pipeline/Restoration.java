// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.pipeline;

import io.github.armor.core.api.AcknowledgedChange;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.durability.StateStore;
import io.github.armor.core.reference.OntologyFiles;
import io.github.armor.core.reference.Reference;
import java.util.ArrayList;
import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Brings back every reference kept in the state directory: its last checkpoint, then its
 * journal replayed through the replaying pipeline.
 */
public final class Restoration {
    private static final Logger LOG = LoggerFactory.getLogger(Restoration.class);

    private Restoration() {}

    public static void restore(Pipeline.Stages stages) {
        StateStore state = stages.state();
        if (state == null) {
            return;
        }
        Pipeline replay = Pipeline.replaying(stages);
        for (StateStore.Restorable restorable : state.recoverAll(new OntologyFiles(stages.config()))) {
            long start = System.nanoTime();
            try {
                Reference reference = Reference.open(restorable.name(), restorable.ontology(), restorable.settings(),
                        stages.config().reasonerTimeoutMs());
                reference.setMountedBy(restorable.mountedBy());
                stages.references().register(reference);
                List<String> failures = new ArrayList<>();
                restorable.records().forEach(record -> failures.addAll(replay(replay, record)));
                reference.setRevision(restorable.revision());
                reference.changeHistory().addAll(restorable.history());
                reference.synchroniseReasoner();
                state.adopt(restorable, restorable.revision(), failures);
                LOG.info("restored reference '{}' from the state directory {}: {} axioms, {} individuals,"
                        + " {} journal record(s) of earlier sessions replayed, in {} ms", restorable.name(),
                        stages.config().durability().stateDir(), reference.ontology().getAxiomCount(),
                        reference.ontology().getIndividualsInSignature().size(), restorable.records().size(),
                        (System.nanoTime() - start) / 1_000_000);
            } catch (RuntimeException e) {
                LOG.error("could not restore reference '{}'", restorable.name(), e);
                stages.references().find(restorable.name()).ifPresent(stages.references()::remove);
                state.notRestored(restorable, "restoring it failed: " + e);
            }
        }
    }

    /** Replays one journal record; what failed, described (a restored state that differs must say so). */
    private static List<String> replay(Pipeline replay, AcknowledgedChange record) {
        List<String> failures = new ArrayList<>();
        for (Directive directive : record.directives()) {
            Response response = replay.run(directive);
            if (!response.success()) {
                failures.add("replaying revision " + record.revision() + " (" + directive.describe()
                        + ") failed: " + response.exitCode() + " " + response.errorDescription());
            }
        }
        return failures;
    }
}
