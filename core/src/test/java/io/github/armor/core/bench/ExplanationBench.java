// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.bench;

import com.google.gson.Gson;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.util.AutoIRIMapper;
import org.semanticweb.owlapi.util.SimpleIRIMapper;

/**
 * Time to the first justification (EXPLAIN ... 1), in this JVM with no service around it, on a
 * reference loaded from a file and reasoned once: each question is a fact that holds and is not
 * asserted, so every answer is a real search. bench/explanations.py writes the files and runs
 * it, one JVM per map, size and kind of fact.
 *
 * <pre>ExplanationBench ONTOLOGY REASONER SAMPLES KIND ARGS...</pre>
 * KIND is the directive's words joined by '+' ({@code EXPLAIN+IND+CLASS}); ARGS are groups of
 * its arguments joined by ',' (one group per sample, used in turn; names or full IRIs). Prints
 * one JSON object: the load time, the seconds of each answer, each answer's description (which
 * says how many axioms were searched), and, checked after the timing as ExplanationsTest checks
 * them, how many justifications were right and what was wrong with the others: each line an
 * axiom of the ontology (read again with the OWL API, imports through the files beside it), the
 * set entailing the fact (HermiT, on the set alone), no axiom of it left out without losing the
 * fact. A failed answer stops it with its code.
 */
public final class ExplanationBench {
    private ExplanationBench() {}

    public static void main(String[] args) throws Exception {
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
        Map<Integer, List<String>> answers = new LinkedHashMap<>();
        try (ArmorCore core = new ArmorCore(config)) {
            long start = System.nanoTime();
            check(core.execute(Directive.of("bench", "ref", "LOAD", "FILE", "", ontology.toString(), "",
                    "false", reasoner, "true")));
            check(core.execute(Directive.of("bench", "ref", "REASON", "", "")));
            result.put("load_s", (System.nanoTime() - start) / 1e9);
            List<Double> seconds = new ArrayList<>();
            List<String> descriptions = new ArrayList<>();
            for (int i = 0; i < samples; i++) {
                String[] question = questions.get(i % questions.size());
                String[] withLimit = Arrays.copyOf(question, question.length + 1);
                withLimit[question.length] = "1";
                long asked = System.nanoTime();
                Response answer = core.execute(Directive.of("bench", "ref", words[0], words[1],
                        words.length > 2 ? words[2] : "", withLimit));
                seconds.add((System.nanoTime() - asked) / 1e9);
                check(answer);
                descriptions.add(answer.errorDescription());
                answers.putIfAbsent(i % questions.size(), answer.queriedObjects());
            }
            result.put("seconds", seconds);
            result.put("descriptions", descriptions);
        }
        List<String> wrong = new ArrayList<>();
        result.put("right", new Checker(ontology, config.fullEntityIri()).check(words, questions, answers, wrong));
        result.put("wrong", wrong);
        System.out.println(new Gson().toJson(result));
    }

    private static void check(Response response) {
        if (!response.success()) {
            System.err.println("failed: " + response.exitCode() + " " + response.errorDescription());
            System.exit(1);
        }
    }

    /** The ontology as the OWL API reads it, and HermiT on each justification alone. */
    private static final class Checker {
        private static final Pattern CATALOG_ENTRY = Pattern.compile("<uri\\b[^>]*\\bname=\"([^\"]+)\"[^>]*\\buri=\"([^\"]+)\"");
        private final OWLOntology ontology;
        private final OWLDataFactory factory;
        private final JustificationCheck justifications;

        Checker(Path file, boolean fullIri) throws Exception {
            OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
            manager.getIRIMappers().add(new AutoIRIMapper(file.getParent().toFile(), false));
            // Protégé's catalog beside the file, as the core reads it (SOMA's imports name no file otherwise).
            Path catalog = file.resolveSibling("catalog-v001.xml");
            if (Files.isRegularFile(catalog)) {
                Matcher entry = CATALOG_ENTRY.matcher(Files.readString(catalog));
                while (entry.find()) {
                    manager.getIRIMappers().add(new SimpleIRIMapper(IRI.create(entry.group(1)),
                            IRI.create(file.resolveSibling(entry.group(2)).toUri())));
                }
            }
            ontology = manager.loadOntologyFromOntologyDocument(file.toFile());
            factory = manager.getOWLDataFactory();
            justifications = new JustificationCheck(ontology, fullIri);
        }

        /** How many justifications of the answers are right; what is wrong with the others goes to {@code wrong}. */
        int check(String[] words, List<String[]> questions, Map<Integer, List<String>> answers, List<String> wrong) {
            int right = 0;
            for (Map.Entry<Integer, List<String>> answer : answers.entrySet()) {
                String[] question = questions.get(answer.getKey());
                JustificationCheck.Verdict verdict = justifications.check(fact(String.join(" ", words), question),
                        answer.getValue());
                right += verdict.right();
                verdict.problems().forEach(problem -> wrong.add(String.join(",", question) + ": " + problem));
            }
            return right;
        }

        private OWLAxiom fact(String directive, String[] a) {
            return switch (directive) {
                case "EXPLAIN IND CLASS" -> factory.getOWLClassAssertionAxiom(
                        entity(EntityType.CLASS, a[1]), entity(EntityType.NAMED_INDIVIDUAL, a[0]));
                case "EXPLAIN OBJECTPROP IND" -> factory.getOWLObjectPropertyAssertionAxiom(
                        entity(EntityType.OBJECT_PROPERTY, a[0]), entity(EntityType.NAMED_INDIVIDUAL, a[1]),
                        entity(EntityType.NAMED_INDIVIDUAL, a[2]));
                case "EXPLAIN CLASS CLASS" -> factory.getOWLSubClassOfAxiom(entity(EntityType.CLASS, a[0]),
                        entity(EntityType.CLASS, a[1]));
                default -> throw new IllegalArgumentException("no check for " + directive);
            };
        }

        /** The entity of that type named by its full IRI or, in the ontology, by the end of its IRI. */
        private <E extends OWLEntity> E entity(EntityType<E> type, String name) {
            if (name.contains("://")) {
                return factory.getOWLEntity(type, IRI.create(name));
            }
            return ontology.signature(Imports.INCLUDED).filter(e -> e.isType(type))
                    .filter(e -> e.getIRI().toString().endsWith("#" + name)).map(e -> factory.getOWLEntity(type,
                            e.getIRI())).findFirst().orElseThrow(() -> new IllegalArgumentException(name));
        }
    }
}
