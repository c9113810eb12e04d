// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import org.apache.jena.graph.Graph;
import org.apache.jena.graph.Node;
import org.apache.jena.graph.Triple;
import org.apache.jena.graph.impl.GraphBase;
import org.apache.jena.util.iterator.ExtendedIterator;
import org.apache.jena.util.iterator.NullIterator;
import org.apache.jena.util.iterator.WrappedIterator;

/**
 * An immutable copy of a graph indexed for the lookups a query makes: by subject and predicate,
 * by object and predicate, by predicate. Jena's in-memory graph indexes single terms only, so a
 * pattern with its subject bound (a join's usual step: "is this student a member of that
 * department?") scans every triple of the subject; here it is one hash lookup. Literal objects
 * match by value, as in Jena's in-memory graph.
 */
final class IndexedGraph extends GraphBase {
    private final List<Triple> triples;
    private final Map<Node, Map<Node, List<Triple>>> bySubject = new HashMap<>();
    private final Map<Object, Map<Node, List<Triple>>> byObject = new HashMap<>();
    private final Map<Node, List<Triple>> byPredicate = new HashMap<>();

    private IndexedGraph(List<Triple> triples) {
        this.triples = triples;
        for (Triple triple : triples) {
            bySubject.computeIfAbsent(triple.getSubject(), s -> new HashMap<>())
                    .computeIfAbsent(triple.getPredicate(), p -> new ArrayList<>(2)).add(triple);
            byObject.computeIfAbsent(triple.getObject().getIndexingValue(), o -> new HashMap<>())
                    .computeIfAbsent(triple.getPredicate(), p -> new ArrayList<>(2)).add(triple);
            byPredicate.computeIfAbsent(triple.getPredicate(), p -> new ArrayList<>()).add(triple);
        }
    }

    /** The triples of {@code graph}, indexed (the graph's own duplicates rules hold: copy a graph, not a list). */
    static IndexedGraph copyOf(Graph graph) {
        List<Triple> triples = new ArrayList<>(graph.size());
        graph.find().forEachRemaining(triples::add);
        IndexedGraph indexed = new IndexedGraph(triples);
        LayeredGraph.prepareForReaders(indexed);
        return indexed;
    }

    @Override
    protected ExtendedIterator<Triple> graphBaseFind(Triple pattern) {
        Node subject = bound(pattern.getSubject());
        Node predicate = bound(pattern.getPredicate());
        Node object = bound(pattern.getObject());
        List<Triple> candidates;
        boolean objectChecked = false;
        if (subject != null) {
            Map<Node, List<Triple>> ofSubject = bySubject.get(subject);
            if (ofSubject == null) {
                return NullIterator.instance();
            }
            if (predicate != null) {
                candidates = ofSubject.getOrDefault(predicate, List.of());
            } else {
                return filtered(flatten(ofSubject), null, object);
            }
        } else if (object != null) {
            Map<Node, List<Triple>> ofObject = byObject.get(object.getIndexingValue());
            if (ofObject == null) {
                return NullIterator.instance();
            }
            objectChecked = !object.isLiteral();
            candidates = predicate != null ? ofObject.getOrDefault(predicate, List.of()) : flatten(ofObject);
        } else if (predicate != null) {
            candidates = byPredicate.getOrDefault(predicate, List.of());
        } else {
            candidates = triples;
        }
        return filtered(candidates, null, objectChecked ? null : object);
    }

    /** The node, or null for a wildcard (Node.ANY, a variable). */
    private static Node bound(Node node) {
        return node.isConcrete() ? node : null;
    }

    /** The candidates whose predicate and object match (null: any); objects compare by value. */
    private static ExtendedIterator<Triple> filtered(List<Triple> candidates, Node predicate, Node object) {
        if (candidates.isEmpty()) {
            return NullIterator.instance();
        }
        Iterator<Triple> all = Collections.unmodifiableList(candidates).iterator();
        if (predicate == null && object == null) {
            return WrappedIterator.create(all);
        }
        return WrappedIterator.create(all).filterKeep(t -> (predicate == null || predicate.equals(t.getPredicate()))
                && (object == null || object.sameValueAs(t.getObject())));
    }

    private static List<Triple> flatten(Map<Node, List<Triple>> byPredicate) {
        if (byPredicate.size() == 1) {
            return byPredicate.values().iterator().next();
        }
        List<Triple> all = new ArrayList<>();
        byPredicate.values().forEach(all::addAll);
        return all;
    }

    @Override
    protected int graphBaseSize() {
        return triples.size();
    }

    @Override
    public void performAdd(Triple triple) {
        throw new UnsupportedOperationException("an indexed graph is never changed");
    }

    @Override
    public void performDelete(Triple triple) {
        throw new UnsupportedOperationException("an indexed graph is never changed");
    }
}
