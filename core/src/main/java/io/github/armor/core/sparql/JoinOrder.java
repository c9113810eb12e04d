// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import org.apache.jena.graph.Graph;
import org.apache.jena.graph.Node;
import org.apache.jena.sparql.core.BasicPattern;
import org.apache.jena.sparql.core.Var;
import org.apache.jena.sparql.engine.ExecutionContext;
import org.apache.jena.sparql.engine.QueryIterator;
import org.apache.jena.sparql.engine.main.StageBuilder;
import org.apache.jena.sparql.engine.main.StageGenerator;
import org.apache.jena.sparql.engine.main.StageGeneratorGeneric;
import org.apache.jena.sparql.engine.optimizer.reorder.PatternElements;
import org.apache.jena.sparql.engine.optimizer.reorder.PatternTriple;
import org.apache.jena.sparql.engine.optimizer.reorder.ReorderTransformationSubstitution;
import org.apache.jena.sparql.sse.Item;

/**
 * The order in which ARQ joins the triple patterns of a query, chosen from the graph's own
 * counts (triples per predicate, subjects and objects per predicate, instances per class)
 * rather than ARQ's fixed rules, which know nothing of the data: on LUBM query 2 they start
 * from every graduate student where the one department narrows it to a handful.
 *
 * <p>Each step takes the pattern expected to match fewest triples given the variables bound so
 * far (ARQ's substitution machinery). Counts are taken once per fresh graph; graphs derived from
 * it after small changes keep them, as a plan needs proportions, not exact figures.
 */
final class JoinOrder extends ReorderTransformationSubstitution {
    private final long triples;
    private final Map<Node, PredicateCounts> predicates;
    private final Map<Node, Long> instances;
    private final StageGenerator stages = new Stages();

    private record PredicateCounts(long triples, long subjects, long objects) {
        double perSubject() {
            return (double) triples / Math.max(1, subjects);
        }

        double perObject() {
            return (double) triples / Math.max(1, objects);
        }
    }

    private JoinOrder(long triples, Map<Node, PredicateCounts> predicates, Map<Node, Long> instances) {
        this.triples = triples;
        this.predicates = predicates;
        this.instances = instances;
    }

    /** Counts the graph's triples (one pass). */
    static JoinOrder of(Graph graph) {
        Map<Node, Long> count = new HashMap<>();
        Map<Node, Set<Node>> subjects = new HashMap<>();
        Map<Node, Set<Node>> objects = new HashMap<>();
        Map<Node, Long> instances = new HashMap<>();
        long[] all = {0};
        graph.find().forEachRemaining(t -> {
            all[0]++;
            Node predicate = t.getPredicate();
            count.merge(predicate, 1L, Long::sum);
            subjects.computeIfAbsent(predicate, p -> new HashSet<>()).add(t.getSubject());
            objects.computeIfAbsent(predicate, p -> new HashSet<>()).add(t.getObject());
            if (predicate.equals(RdfTerms.TYPE)) {
                instances.merge(t.getObject(), 1L, Long::sum);
            }
        });
        Map<Node, PredicateCounts> predicates = new HashMap<>();
        count.forEach((p, n) -> predicates.put(p, new PredicateCounts(n, subjects.get(p).size(), objects.get(p).size())));
        return new JoinOrder(all[0], predicates, instances);
    }

    /** Hands ARQ's basic graph patterns to ARQ's own evaluation, in this order (set per query execution). */
    void plan(org.apache.jena.sparql.util.Context context) {
        StageBuilder.setGenerator(context, stages);
    }

    private final class Stages extends StageGeneratorGeneric {
        @Override
        public QueryIterator execute(BasicPattern pattern, QueryIterator input, ExecutionContext context) {
            return execute(pattern, JoinOrder.this, StageBuilder.executeInline, input, context);
        }
    }

    /** Expected matches of the pattern; bound and constant terms narrow it, unknown predicates match nothing. */
    @Override
    protected double weight(PatternTriple pattern) {
        boolean subjectFixed = fixed(pattern.subject);
        boolean objectFixed = fixed(pattern.object);
        if (!fixed(pattern.predicate) || !pattern.predicate.isNode()) {
            double matches = triples;
            if (subjectFixed) {
                matches /= Math.max(1, predicates.size());
            }
            if (objectFixed) {
                matches /= Math.max(1, predicates.size());
            }
            return matches;
        }
        Node predicate = pattern.predicate.getNode();
        PredicateCounts counts = predicates.get(predicate);
        if (counts == null) {
            return 0;
        }
        if (predicate.equals(RdfTerms.TYPE) && pattern.object.isNode() && !Var.isVar(pattern.object.getNode())) {
            long members = instances.getOrDefault(pattern.object.getNode(), 0L);
            return subjectFixed ? Math.min(1, members) : members;
        }
        if (subjectFixed && objectFixed) {
            return Math.min(1, counts.triples());
        }
        if (subjectFixed) {
            return counts.perSubject();
        }
        if (objectFixed) {
            return counts.perObject();
        }
        return counts.triples();
    }

    /** A constant, or a variable bound by an earlier pattern. */
    private static boolean fixed(Item item) {
        if (item.equals(PatternElements.TERM)) {
            return true;
        }
        return item.isNode() && !Var.isVar(item.getNode());
    }
}
