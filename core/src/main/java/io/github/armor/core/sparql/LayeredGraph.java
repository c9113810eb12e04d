// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import java.util.Collection;
import java.util.HashSet;
import java.util.Set;
import org.apache.jena.graph.Graph;
import org.apache.jena.graph.GraphUtil;
import org.apache.jena.graph.Triple;
import org.apache.jena.graph.impl.GraphBase;
import org.apache.jena.sparql.graph.GraphFactory;
import org.apache.jena.util.iterator.ExtendedIterator;

/**
 * A graph that is never changed once made, so that any number of queries may read it at once:
 * a base graph, a few of its triples hidden and a few triples added. A small change to a large
 * graph thus makes a new graph in time proportional to the change, not to the graph; when the
 * layers grow past a fraction of the base, they are folded into a new base.
 */
final class LayeredGraph extends GraphBase {
    /** Layers up to this many triples are always kept as layers (folding costs a full copy). */
    private static final int MIN_FOLD_SIZE = 4096;
    /** Layers are folded when they exceed this fraction of the base: 1/8. */
    private static final int FOLD_DIVISOR = 8;

    private final Graph base;
    private final Graph added;
    private final Set<Triple> hidden;

    private LayeredGraph(Graph base, Graph added, Set<Triple> hidden) {
        this.base = base;
        this.added = added;
        this.hidden = hidden;
        prepareForReaders(this);
    }

    /**
     * {@code previous} with {@code additions} (triples it lacks) and without {@code removals}
     * (triples it has); {@code previous} itself is left as it was.
     */
    static Graph apply(Graph previous, Collection<Triple> additions, Collection<Triple> removals) {
        if (additions.isEmpty() && removals.isEmpty()) {
            return previous;
        }
        Graph base = previous;
        Graph added = GraphFactory.createGraphMem();
        Set<Triple> hidden = new HashSet<>();
        if (previous instanceof LayeredGraph layered) {
            base = layered.base;
            GraphUtil.addInto(added, layered.added);
            hidden.addAll(layered.hidden);
        }
        for (Triple triple : removals) {
            if (added.contains(triple)) {
                added.delete(triple);
            } else {
                hidden.add(triple);
            }
        }
        for (Triple triple : additions) {
            if (!hidden.remove(triple)) {
                added.add(triple);
            }
        }
        if (added.size() + hidden.size() > Math.max(MIN_FOLD_SIZE, base.size() / FOLD_DIVISOR)) {
            Graph folded = GraphFactory.createGraphMem();
            GraphUtil.addInto(folded, new LayeredGraph(base, added, hidden));
            return IndexedGraph.copyOf(folded);
        }
        return new LayeredGraph(base, IndexedGraph.copyOf(added), Set.copyOf(hidden));
    }

    /**
     * Creates what a graph otherwise creates on first use (prefixes, capabilities, event manager,
     * statistics), so that concurrent readers of a finished graph never race to create them.
     */
    static Graph prepareForReaders(Graph graph) {
        graph.getPrefixMapping();
        graph.getCapabilities();
        graph.getEventManager();
        graph.getStatisticsHandler();
        return graph;
    }

    @Override
    protected ExtendedIterator<Triple> graphBaseFind(Triple pattern) {
        ExtendedIterator<Triple> found = base.find(pattern);
        if (!hidden.isEmpty()) {
            found = found.filterDrop(hidden::contains);
        }
        ExtendedIterator<Triple> more = added.find(pattern);
        return more.hasNext() ? found.andThen(more) : found;
    }

    @Override
    protected boolean graphBaseContains(Triple triple) {
        if (!triple.isConcrete()) {
            return containsByFind(triple);
        }
        return added.contains(triple) || (!hidden.contains(triple) && base.contains(triple));
    }

    @Override
    protected int graphBaseSize() {
        return base.size() - hidden.size() + added.size();
    }

    @Override
    public void performAdd(Triple triple) {
        throw new UnsupportedOperationException("a layered graph is never changed; apply() makes a new one");
    }

    @Override
    public void performDelete(Triple triple) {
        throw new UnsupportedOperationException("a layered graph is never changed; apply() makes a new one");
    }
}
