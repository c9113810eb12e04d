// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonParser;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandTable;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Recognition by counting (a plain reference) answers what the reference's reasoner answers:
 * the same generated scenes, sent to a plain reference and to one whose scene property has a
 * super-property (an axiom that makes it not plain, and changes no answer), give the same
 * classes learned and the same recognitions. And a reference that builds on learned classes is
 * answered by its reasoner, its own classes included.
 */
class SceneWaysTest {
    @TempDir
    Path scratch;

    private ArmorCore core;

    @AfterEach
    void close() {
        if (core != null) {
            core.close();
        }
    }

    private Response run(String reference, String words, String... args) {
        String[] parts = (words + " - -").split("\\s+");
        Response response = core.execute(Directive.of("test", reference, parts[0], parts[1], parts[2], args));
        assertTrue(response.success(), () -> words + ": " + response.exitCode() + " " + response.errorDescription());
        return response;
    }

    private String recognisedBy(String reference) {
        return JsonParser.parseString(run(reference, "QUERY SIT RECENT").queriedObjects().get(0)).getAsJsonObject()
                .get("recognised_by").getAsString();
    }

    private void start(String reasoner) {
        core = new ArmorCore(CoreConfig.defaults(scratch), CommandTable.load(SceneWaysTest.class.getClassLoader()));
        for (String reference : List.of("counted", "reasoned")) {
            run(reference, "CREATE", SceneBench.IRI_BASE, "false", reasoner, "false");
        }
        run("reasoned", "ADD OBJECTPROP OBJECTPROP", "rightSPHERE", "sceneRelation");
    }

    @ParameterizedTest
    // HermiT takes seconds to minutes on cardinalities of 3 and more (docs/scenes.md): smaller scenes.
    @CsvSource({"PELLET, 10, 4", "HERMIT, 3, 2"})
    void countingAndTheReasonerAgreeOnGeneratedScenes(String reasoner, int scenes, int largest) {
        start(reasoner);
        // First a scene whose relations have the properties of the learned one but objects of
        // other types: not an instance (a count that forgot the types would say it is).
        for (String scene : List.of("SPHERE 0 0 0; SPHERE 0 1 0", "CONE 0 0 0; SPHERE 0 1 0; CYLINDER 0 2 0")) {
            assertEquals(run("reasoned", "SIT SCENE", "0.9", "0.03", "0.05", scene).queriedObjects(),
                    run("counted", "SIT SCENE", "0.9", "0.03", "0.05", scene).queriedObjects(), scene);
        }
        Random random = new Random(32);
        double[] thresholds = {1.0, 0.9, 0.5, 0.0};
        List<String> shown = new ArrayList<>();
        for (int i = 0; i < scenes; i++) {
            // New scenes, scenes shown before, and scenes that contain one shown before.
            String scene = shown.isEmpty() || random.nextInt(3) == 0 ? SceneBench.generated(random, 2 + random.nextInt(largest - 1))
                    : random.nextBoolean() ? shown.get(random.nextInt(shown.size()))
                    : shown.get(random.nextInt(shown.size())) + "; " + SceneBench.generated(random, 1);
            shown.add(scene);
            String threshold = String.valueOf(thresholds[random.nextInt(thresholds.length)]);
            List<String> counted = run("counted", "SIT SCENE", threshold, "0.03", "0.05", scene).queriedObjects();
            List<String> reasoned = run("reasoned", "SIT SCENE", threshold, "0.03", "0.05", scene).queriedObjects();
            assertEquals(reasoned, counted, "scene " + i + " (" + scene + ") at threshold " + threshold);
            assertEquals("counting", recognisedBy("counted"));
            assertEquals("reasoner", recognisedBy("reasoned"));
        }
        // The hierarchy compared directly (plain) is the reasoner's (not plain).
        assertEquals(hierarchy("reasoned"), hierarchy("counted"));
        assertTrue(hierarchy("counted").stream().anyMatch(line -> !line.contains("under []")),
                "the generated scenes contain one another somewhere: " + hierarchy("counted"));
    }

    /** Each learned class with the learned classes it is placed under and is equivalent to. */
    private List<String> hierarchy(String reference) {
        List<String> placed = new ArrayList<>();
        for (String line : run(reference, "QUERY SIT SCENES").queriedObjects()) {
            var item = JsonParser.parseString(line).getAsJsonObject();
            placed.add(item.get("name").getAsString() + " under " + item.get("superscenes") + " same as "
                    + item.get("equivalent"));
        }
        return placed;
    }

    @Test
    void classesBuiltOnLearnedScenesAreRecognisedByTheReasoner() {
        start("PELLET");
        run("counted", "SIT SCENE", "0.9", "0.03", "0.05", "SPHERE 0 0 0; SPHERE 0.8 0 0.8");
        run("counted", "ADD CLASS EQUIVALENT", "Tabletop", "SCENE-1");
        List<String> answer = run("counted", "SIT SCENE", "0.9", "0.03", "0.05", "SPHERE 0 0 0; SPHERE 0.8 0 0.8")
                .queriedObjects();
        assertEquals("reasoner", recognisedBy("counted"));
        assertEquals(List.of("recognised <" + SceneBench.IRI_BASE + "#SCENE-1> 1.0",
                "recognised <" + SceneBench.IRI_BASE + "#Tabletop> 0.0"), answer);
    }
}
