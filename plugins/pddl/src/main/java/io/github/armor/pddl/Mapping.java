// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.pddl;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.yaml.snakeyaml.LoaderOptions;
import org.yaml.snakeyaml.Yaml;
import org.yaml.snakeyaml.constructor.SafeConstructor;
import org.yaml.snakeyaml.error.MarkedYAMLException;
import org.yaml.snakeyaml.error.YAMLException;
import org.yaml.snakeyaml.nodes.Tag;
import org.yaml.snakeyaml.representer.Representer;
import org.yaml.snakeyaml.resolver.Resolver;
import org.yaml.snakeyaml.DumperOptions;

/**
 * What a PDDL problem is made of, as a mapping file says (YAML or JSON; docs/pddl.md): which
 * classes become types and unary predicates, which object properties binary predicates, which
 * data properties numeric fluents, facts always true, and the goal. Names are kept as written;
 * {@link ProblemGenerator} resolves them against a reference.
 *
 * @param domain           the {@code :domain} the problem is for
 * @param problem          the problem's name (null: the reference's)
 * @param types            class name to PDDL type (null: derived from the class)
 * @param unaryPredicates  class name to predicate
 * @param binaryPredicates object property name to predicate
 * @param numericFluents   data property name to fluent
 * @param init             facts added to {@code :init}: predicate, then individual names
 * @param goal             facts and "every instance of a class must satisfy ..." requirements
 */
record Mapping(String domain, String problem, Map<String, String> types, Map<String, String> unaryPredicates,
               Map<String, String> binaryPredicates, Map<String, String> numericFluents, List<List<String>> init,
               List<Goal> goal) {

    /** One item of the goal. */
    sealed interface Goal permits Fact, ForAll {}

    /** A fact that must hold: predicate, then individual names. */
    record Fact(List<String> words) implements Goal {}

    /**
     * Every instance of {@code className} must satisfy each fact of {@code require}, where a word
     * starting with '?' stands for the instance.
     */
    record ForAll(String className, List<List<String>> require) implements Goal {}

    private static final Set<String> KEYS = Set.of("domain", "problem", "types", "unary_predicates",
            "binary_predicates", "numeric_fluents", "init", "goal");
    // A mapping is a few lines; this is far beyond any real one, and bounds what a client can make the core parse.
    static final int MAX_CODE_POINTS = 1 << 20;

    /**
     * Reads a mapping from YAML or JSON text.
     *
     * @throws ArmorException 208 for text that is not YAML, 207 for a mapping of the wrong shape
     */
    static Mapping parse(String text) {
        Object tree;
        try {
            tree = yaml().load(text);
        } catch (MarkedYAMLException e) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "mapping is not valid YAML or JSON: " + e.getProblem()
                    + " at line " + (e.getProblemMark().getLine() + 1) + ", column "
                    + (e.getProblemMark().getColumn() + 1));
        } catch (YAMLException e) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "mapping is not valid YAML or JSON: " + e.getMessage());
        }
        if (!(tree instanceof Map<?, ?> top)) {
            throw shape("a mapping is a YAML or JSON object with the keys " + sortedKeys() + ", got "
                    + describe(tree));
        }
        for (Object key : top.keySet()) {
            if (!KEYS.contains(String.valueOf(key))) {
                throw shape("unknown key '" + key + "'; a mapping has " + sortedKeys());
            }
        }
        String domain = text(top.get("domain"), "domain");
        if (domain == null) {
            throw shape("'domain' (the name of the PDDL domain the problem is for) is missing");
        }
        return new Mapping(domain, text(top.get("problem"), "problem"), names(top.get("types"), "types"),
                names(top.get("unary_predicates"), "unary_predicates"),
                names(top.get("binary_predicates"), "binary_predicates"),
                names(top.get("numeric_fluents"), "numeric_fluents"), facts(top.get("init"), "init"),
                goals(top.get("goal")));
    }

    /** SnakeYAML reading plain data only: no tags, no aliases bombs, no duplicate keys. */
    private static Yaml yaml() {
        LoaderOptions options = new LoaderOptions();
        options.setAllowDuplicateKeys(false);
        options.setMaxAliasesForCollections(20);
        options.setNestingDepthLimit(20);
        options.setCodePointLimit(MAX_CODE_POINTS);
        return new Yaml(new SafeConstructor(options), new Representer(new DumperOptions()), new DumperOptions(),
                options, new TextResolver());
    }

    /**
     * Every scalar a string but null: YAML 1.1 would read {@code on}, {@code yes} and {@code no}
     * (common PDDL names) as booleans and {@code 1e3} as a number.
     */
    private static final class TextResolver extends Resolver {
        @Override
        protected void addImplicitResolvers() {
            addImplicitResolver(Tag.NULL, NULL, "~nN\0");
            addImplicitResolver(Tag.NULL, EMPTY, null);
        }
    }

    private static String text(Object value, String where) {
        if (value == null) {
            return null;
        }
        if (value instanceof String string) {
            return string.isBlank() ? null : string.trim();
        }
        throw shape("'" + where + "' must be a name, got " + describe(value));
    }

    /** A section naming entities: an object (name to PDDL name, or to nothing) or a list of names. */
    private static Map<String, String> names(Object value, String where) {
        Map<String, String> names = new LinkedHashMap<>();
        if (value == null) {
            return names;
        }
        if (value instanceof List<?> list) {
            for (Object item : list) {
                names.put(entityName(item, where), null);
            }
            return names;
        }
        if (!(value instanceof Map<?, ?> map)) {
            throw shape("'" + where + "' must map names of the ontology to PDDL names, got " + describe(value));
        }
        map.forEach((key, name) -> names.put(entityName(key, where), text(name, where + "." + key)));
        return names;
    }

    private static String entityName(Object value, String where) {
        if (value instanceof String string && !string.isBlank()) {
            return string.trim();
        }
        throw shape("'" + where + "' lists " + describe(value) + " where a name of the ontology belongs");
    }

    private static List<List<String>> facts(Object value, String where) {
        List<List<String>> facts = new ArrayList<>();
        if (value == null) {
            return facts;
        }
        if (!(value instanceof List<?> list)) {
            throw shape("'" + where + "' must be a list of facts such as [at, robot1, kitchen], got "
                    + describe(value));
        }
        for (Object item : list) {
            facts.add(fact(item, where));
        }
        return facts;
    }

    private static List<String> fact(Object value, String where) {
        if (!(value instanceof List<?> words) || words.isEmpty()) {
            throw shape("'" + where + "': a fact is a list such as [at, robot1, kitchen], got " + describe(value));
        }
        List<String> fact = new ArrayList<>();
        for (Object word : words) {
            if (word instanceof Map<?, ?> map && map.size() == 1 && map.values().iterator().next() == null) {
                // YAML reads an unquoted ?x in [visited, ?x] as a one-key map.
                throw shape("'" + where + "': write the variable of " + describe(value) + " in quotes: \"?"
                        + map.keySet().iterator().next() + "\"");
            }
            if (!(word instanceof String string) || string.isBlank()) {
                throw shape("'" + where + "': " + describe(value) + " holds " + describe(word)
                        + " where a name belongs");
            }
            fact.add(string.trim());
        }
        return fact;
    }

    private static List<Goal> goals(Object value) {
        List<Goal> goals = new ArrayList<>();
        if (value == null) {
            return goals;
        }
        if (!(value instanceof List<?> items)) {
            throw shape("'goal' must be a list of facts and {forall: Class, require: fact} items, got "
                    + describe(value));
        }
        for (Object item : items) {
            if (item instanceof Map<?, ?> map) {
                goals.add(forAll(map));
            } else {
                goals.add(new Fact(fact(item, "goal")));
            }
        }
        return goals;
    }

    private static ForAll forAll(Map<?, ?> map) {
        if (!map.keySet().equals(Set.of("forall", "require"))) {
            throw shape("'goal': an item that is not a fact is {forall: Class, require: [predicate, \"?x\"]}, got "
                    + describe(map));
        }
        String className = text(map.get("forall"), "goal.forall");
        if (className == null) {
            throw shape("'goal': forall names no class");
        }
        Object require = map.get("require");
        List<List<String>> facts = require instanceof List<?> list && !list.isEmpty() && list.get(0) instanceof List<?>
                ? facts(require, "goal.require") : List.of(fact(require, "goal.require"));
        for (List<String> fact : facts) {
            if (fact.stream().noneMatch(word -> word.startsWith("?"))) {
                throw shape("'goal': require " + fact + " of forall " + className
                        + " names no variable such as \"?x\" for the instance");
            }
        }
        return new ForAll(className, facts);
    }

    private static String sortedKeys() {
        return KEYS.stream().sorted().toList().toString();
    }

    private static String describe(Object value) {
        return value == null ? "nothing" : value instanceof String ? "'" + value + "'" : value.toString();
    }

    private static ArmorException shape(String message) {
        return new ArmorException(ExitCode.WRONG_ARGUMENTS, "mapping: " + message);
    }
}
