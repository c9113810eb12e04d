// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.bench;

import com.google.gson.Gson;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Time to the first justification (EXPLAIN ... 1), in this JVM with no service around it, on a
 * reference loaded from a file and reasoned once: each question is a fact that holds and is not
 * asserted, so every answer is a real search. bench/explanations.py writes the files and runs
 * it, one JVM per size.
 *
 * <pre>ExplanationBench ONTOLOGY REASONER SAMPLES KIND ARGS...</pre>
 * KIND is the directive's words joined by '+' ({@code EXPLAIN+IND+CLASS}); ARGS are groups of
 * its arguments joined by ',' (one group per sample, used in turn). Prints one JSON object:
 * the load time, the seconds of each answer, and each answer's description (which says how many
 * axioms were searched). A failed answer stops it with its code.
 */
public final class ExplanationBench {
    private ExplanationBench() {}

    public static void main(String[] args) {
        Path ontology = Path.of(args[0]).toAbsolutePath();
        String reasoner = args[1];
        int samples = Integer.parseInt(args[2]);
        String[] words = args[3].split("\\+");
        List<String[]> questions = new ArrayList<>();
        for (int i = 4; i < args.length; i++) {
            questions.add(args[i].split(","));
        }
        CoreConfig config = CoreConfig.defaults(ontology.getParent());
        Map<String, Object> result = new LinkedHashMap<>();
        try (ArmorCore core = new ArmorCore(config)) {
            long start = System.nanoTime();
            check(core.execute(Directive.of("bench", "ref", "LOAD", "FILE", "", ontology.toString(),
                    "http://www.example.org/robotics", "false", reasoner, "true")));
            check(core.execute(Directive.of("bench", "ref", "REASON", "", "")));
            result.put("load_s", (System.nanoTime() - start) / 1e9);
            List<Double> seconds = new ArrayList<>();
            List<String> descriptions = new ArrayList<>();
            for (int i = 0; i < samples; i++) {
                String[] question = questions.get(i % questions.size());
                String[] withLimit = java.util.Arrays.copyOf(question, question.length + 1);
                withLimit[question.length] = "1";
                long asked = System.nanoTime();
                Response answer = core.execute(Directive.of("bench", "ref", words[0], words[1],
                        words.length > 2 ? words[2] : "", withLimit));
                seconds.add((System.nanoTime() - asked) / 1e9);
                check(answer);
                descriptions.add(answer.errorDescription());
            }
            result.put("seconds", seconds);
            result.put("descriptions", descriptions);
        }
        System.out.println(new Gson().toJson(result));
    }

    private static void check(Response response) {
        if (!response.success()) {
            System.err.println("failed: " + response.exitCode() + " " + response.errorDescription());
            System.exit(1);
        }
    }
}
