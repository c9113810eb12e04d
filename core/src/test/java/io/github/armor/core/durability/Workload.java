// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import com.google.common.util.concurrent.MoreExecutors;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.ListResponse;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandTable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A run of changes of every kind the journal keeps (single changes, removals, property changes,
 * lists on one and on two references, mounts, a DROP) on cores whose state goes through a
 * {@link Storage} of the test's, checkpointing every few changes in the caller's thread, so that
 * the k-th I/O call of a run is always the same one. Its oracle is a core without state that is
 * given only the steps a run acknowledged: a restored core must answer what it answers.
 */
final class Workload {
    static final Path ONTOLOGIES = Path.of("..", "ontologies").toAbsolutePath().normalize();
    static final String ROBOTICS = ONTOLOGIES.resolve("robotics.owl").toString();
    // Where digests SAVE (the one writable directory of every workload core).
    private static final Path SAVES;

    static {
        try {
            SAVES = Files.createTempDirectory("armor-digests");
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** One step: a directive, or a list run atomically. */
    record Step(List<Directive> directives) {
        boolean isList() {
            return directives.size() > 1;
        }
    }

    static Directive d(String client, String reference, String words, String... args) {
        String[] parts = (words + " - -").trim().split("\\s+");
        return Directive.of(client, reference, parts[0], parts[1], parts[2], args);
    }

    private static Step one(String reference, String words, String... args) {
        return new Step(List.of(d("w", reference, words, args)));
    }

    static List<Step> steps(int rounds) {
        List<Step> steps = new ArrayList<>();
        steps.add(one("map", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true"));
        steps.add(one("other", "LOAD FILE", ROBOTICS, "", "false", "HERMIT", "true"));
        for (int round = 0; round < rounds; round++) {
            String r = "r" + (round * 4 + 1);
            String s = "r" + (round * 4 + 2);
            String t = "r" + (round * 4 + 3);
            steps.add(one("map", "ADD IND CLASS", r, "Robot"));
            steps.add(one("map", "ADD DATAPROP IND", "batteryLevel", r, "INT", "50"));
            steps.add(one("map", "REPLACE DATAPROP IND", "batteryLevel", r, "INT", "60", "50"));
            steps.add(one("map", "ADD OBJECTPROP IND", "isIn", r, "kitchen"));
            steps.add(new Step(List.of(d("w", "map", "ADD IND CLASS", s, "Robot"),
                    d("w", "map", "ADD OBJECTPROP IND", "isIn", s, "bedroom"))));
            steps.add(one("map", "REMOVE IND CLASS", round == 0 ? "robot1" : r, "Robot"));
            steps.add(new Step(List.of(d("m", "map", "MOUNT"))));
            steps.add(new Step(List.of(d("m", "map", "ADD IND CLASS", t, "Robot"))));
            steps.add(new Step(List.of(d("m", "map", "UNMOUNT"))));
            steps.add(new Step(List.of(d("w", "map", "ADD IND CLASS", t, "Agent"),
                    d("w", "other", "ADD IND CLASS", t, "Robot"))));
            steps.add(one("map", "REPLACE OBJECTPROP IND", "isIn", r, "bedroom", "kitchen"));
            steps.add(one("map", "REMOVE DATAPROP IND", "batteryLevel", r, "INT", "60"));
        }
        steps.add(one("other", "DROP"));
        steps.add(one("map", "ADD IND CLASS", "r8", "Robot"));
        return steps;
    }

    static CoreConfig config(Path stateDir, int checkpointEvery) {
        return new CoreConfig(true, "HERMIT", List.of(ONTOLOGIES, SAVES), false, 30_000, 0, 0,
                stateDir == null ? CoreConfig.Durability.NONE
                        : new CoreConfig.Durability(stateDir, true, true, checkpointEvery, 3600))
                .withWriting(CoreConfig.Writing.into(SAVES));
    }

    /** A core on {@code stateDir} whose files go through {@code storage}, restored. */
    static ArmorCore core(Path stateDir, Storage storage, int checkpointEvery) {
        CoreConfig config = config(stateDir, checkpointEvery);
        ArmorCore core = new ArmorCore(config, CommandTable.standard(),
                new StateStore(config.durability(), storage, MoreExecutors.newDirectExecutorService()));
        core.restoreState();
        return core;
    }

    /** Whether a step was acknowledged. */
    static boolean run(ArmorCore core, Step step) {
        if (step.isList()) {
            return core.executeList(step.directives()).success();
        }
        return core.execute(step.directives().get(0)).success();
    }

    static Response answer(ArmorCore core, Step step) {
        if (step.isList()) {
            ListResponse list = core.executeList(step.directives());
            return list.responses().stream().filter(r -> !r.success()).findFirst()
                    .orElse(list.responses().get(0));
        }
        return core.execute(step.directives().get(0));
    }

    /**
     * What a core holds of the workload's references, which the oracle compares: each one's
     * revision, mount holder and asserted axioms (saved in functional syntax: no reasoning).
     */
    static List<String> digest(ArmorCore core) {
        List<String> digest = new ArrayList<>();
        List<String> refs = core.execute(d("q", "", "GET ALL REFS")).queriedObjects().stream().sorted().toList();
        digest.add("refs " + refs);
        for (String ref : refs) {
            digest.add(ref + " revision " + core.execute(d("q", "", "GET REF REVISION", ref)).queriedObjects());
            digest.add(ref + " mount " + core.execute(d("q", "", "GET REF CLIENT", ref)).queriedObjects());
            Path saved = SAVES.resolve(ref + "-" + System.nanoTime() + ".ofn");
            Response answer = core.execute(d("q", ref, "SAVE", saved.toString(), "functional"));
            if (!answer.success()) {
                throw new AssertionError("SAVE for the digest failed: " + answer.errorDescription());
            }
            try {
                Files.readAllLines(saved).stream()
                        .filter(line -> !line.isBlank() && !line.startsWith("Prefix(") && !line.startsWith("Ontology(")
                                && !line.startsWith("#") && !line.equals(")"))
                        .sorted().forEach(line -> digest.add(ref + " " + line));
                Files.delete(saved);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return digest;
    }

    /** The oracle: a core without state given only {@code acknowledged}, in order. */
    static List<String> oracle(List<Step> acknowledged) {
        ArmorCore shadow = new ArmorCore(config(null, 0));
        try {
            for (Step step : acknowledged) {
                if (!run(shadow, step)) {
                    throw new AssertionError("an acknowledged step fails on the oracle: " + step);
                }
            }
            return digest(shadow);
        } finally {
            shadow.close();
        }
    }
}
