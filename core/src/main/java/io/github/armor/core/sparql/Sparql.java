// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import io.github.armor.core.answers.Rendering;
import io.github.armor.core.answers.Syntax;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.api.Response.QueryItem;
import io.github.armor.core.api.SizeLimits;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.reference.Reference;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.apache.jena.graph.Node;
import org.apache.jena.query.Query;
import org.apache.jena.query.QueryCancelledException;
import org.apache.jena.query.QueryExecution;
import org.apache.jena.query.QueryExecutionFactory;
import org.apache.jena.query.QueryFactory;
import org.apache.jena.query.QueryParseException;
import org.apache.jena.query.ResultSet;
import org.apache.jena.rdf.model.ModelFactory;
import org.apache.jena.shared.PrefixMapping;
import org.apache.jena.sparql.core.Var;
import org.apache.jena.sparql.engine.binding.Binding;
import org.apache.jena.sparql.engine.http.Service;

/**
 * QUERY SPARQL with Apache Jena ARQ over the ontology plus its inferences (class and property
 * assertions, hierarchy), so that answers agree with the other queries. The reference's
 * declared prefixes are predefined in every query.
 *
 * <p>Two phases: under the reference's lock, the query is parsed and checked and the reference's
 * graph for its current state is taken ({@link SparqlGraphs}: made by the first query after a
 * change, shared by the next ones); the graph is never changed, so the query is evaluated after
 * the lock is released, in parallel with other queries, within the time limit (node parameter
 * sparql_timeout_ms).
 */
public final class Sparql {
    private Sparql() {}

    public static Response answer(CommandContext c, boolean formatted) {
        List<String> args = c.args();
        long requestedMs = 0;
        List<String> parts = args;
        if (args.size() == 2 || args.size() == 4) {
            requestedMs = timeout(args.get(args.size() - 1));
            parts = args.subList(0, args.size() - 1);
        } else if (args.size() != 1 && args.size() != 3) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "QUERY SPARQL takes (query[, timeout ms]) or "
                    + "(prefix, select, where[, timeout ms]), got " + args.size() + " arguments");
        }
        String text = parts.size() == 1 ? parts.get(0) : joinSplitForm(parts.get(0), parts.get(1), parts.get(2));
        Query query = parse(c.reference(), text);
        if (!query.isSelectType() && !query.isAskType()) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "only SELECT and ASK queries are answered");
        }
        CoreConfig.Safeguards safeguards = c.config().safeguards();
        if (!safeguards.sparqlFederated() && FederatedQueries.uses(query)) {
            throw new ArmorException(ExitCode.FEDERATED_QUERY_DISABLED, "the query has a SERVICE clause (a federated"
                    + " query, which would connect to another endpoint); start the node with sparql_federated:=true"
                    + " to allow it");
        }
        long limitMs = timeLimit(requestedMs, safeguards.sparqlTimeoutMs());
        // The reasoner's part needs the reference; the graph it yields is never changed.
        InferredGraph graph = SparqlGraphs.current(c.reference());
        boolean consistent = c.reference().isConsistent();
        Rendering rendering = c.render();
        boolean federated = safeguards.sparqlFederated();
        return c.afterRelease(() -> evaluate(query, graph, limitMs, federated, rendering, consistent, formatted));
    }

    /**
     * The query's own limit when it asks for one within the node's (sparql_timeout_ms, which is
     * also the default); 0 = none.
     */
    private static long timeLimit(long requestedMs, long nodeMs) {
        if (requestedMs > 0 && (nodeMs <= 0 || requestedMs < nodeMs)) {
            return requestedMs;
        }
        return nodeMs;
    }

    private static Response evaluate(Query query, InferredGraph graph, long limitMs, boolean federated,
                                     Rendering rendering, boolean consistent, boolean formatted) {
        Rows rows = new Rows(formatted);
        boolean timedOut = false;
        try (QueryExecution execution = QueryExecutionFactory.create(query,
                ModelFactory.createModelForGraph(graph.graph()))) {
            // Behind the check above: a SERVICE the check missed fails before connecting.
            execution.getContext().set(Service.serviceAllowed, federated);
            graph.joinOrder().plan(execution.getContext());
            if (limitMs > 0) {
                execution.setTimeout(limitMs);
            }
            if (query.isAskType()) {
                rows.add(List.of("ASK"), new String[] {String.valueOf(execution.execAsk())});
            } else {
                ResultSet results = execution.execSelect();
                List<String> variables = results.getResultVars();
                Var[] vars = variables.stream().map(Var::alloc).toArray(Var[]::new);
                String[] values = new String[vars.length];
                while (results.hasNext()) {
                    // Bindings of graph nodes: a QuerySolution would wrap each value in a model resource first.
                    Binding solution = results.nextBinding();
                    for (int i = 0; i < vars.length; i++) {
                        Node node = solution.get(vars[i]);
                        values[i] = node == null ? "" : render(rendering, node);
                    }
                    rows.add(variables, values);
                }
            }
        } catch (QueryCancelledException e) {
            timedOut = true;
        }
        return rows.response(consistent, timedOut);
    }

    /**
     * The rows of an answer as the contract writes them: one string per row (one variable: its
     * value alone; several: {@code name=value} pairs joined by "; "), or, FORMATTED, key/value
     * items with an empty item between rows. Refuses an answer past the size limit.
     */
    private static final class Rows {
        private final boolean formatted;
        private final List<String> lines = new ArrayList<>();
        private final List<QueryItem> items = new ArrayList<>();
        private long bytes;
        private int count;

        Rows(boolean formatted) {
            this.formatted = formatted;
        }

        void add(List<String> variables, String[] values) {
            StringBuilder line = formatted || variables.size() == 1 ? null : new StringBuilder();
            if (formatted && count > 0) {
                items.add(new QueryItem("", ""));
            }
            for (int i = 0; i < values.length; i++) {
                String variable = variables.get(i);
                bytes += variable.length() + SizeLimits.utf8Bytes(values[i]);
                if (formatted) {
                    items.add(new QueryItem(variable, values[i]));
                } else if (line != null) {
                    line.append(i == 0 ? "" : "; ").append(variable).append('=').append(values[i]);
                }
            }
            if (bytes > SizeLimits.ANSWER_BYTES) {
                throw SizeLimits.tooLarge("the answer exceeds " + SizeLimits.size(SizeLimits.ANSWER_BYTES)
                        + " after " + count + " rows; narrow the query or add a LIMIT");
            }
            if (!formatted) {
                lines.add(line == null ? values[0] : line.toString());
            }
            count++;
        }

        Response response(boolean consistent, boolean timedOut) {
            if (formatted) {
                return Response.okSparql(consistent, items, timedOut);
            }
            return Response.ok(consistent, List.of()).withQueriedObjects(lines, timedOut);
        }
    }

    private static String joinSplitForm(String prefix, String select, String where) {
        String body = where.trim();
        if (body.regionMatches(true, 0, "WHERE", 0, 5)) {
            return prefix + "\n" + select + "\n" + body;
        }
        return prefix + "\n" + select + "\nWHERE {\n" + (body.startsWith("{") ? body.substring(1, body.lastIndexOf('}'))
                : body) + "\n}";
    }

    private static long timeout(String text) {
        try {
            long value = Long.parseLong(text.trim());
            if (value >= 0) {
                return value;
            }
        } catch (NumberFormatException e) {
            // answered below
        }
        throw new ArmorException(ExitCode.BAD_DATA_TYPE, "SPARQL timeout must be a whole number of ms >= 0, got '"
                + text + "'");
    }

    /**
     * A query parsed with a reference's prefixes, kept for the next time the same text comes from
     * a reference with the same prefixes: robots ask the same questions again and again, and
     * parsing is about a tenth of a small query's time. Shared by concurrent executions, which
     * only read it once its result variables are set.
     */
    private record ParsedQuery(Map<String, String> prefixes, String defaultNamespace, String text) {}

    private static final int PARSED_QUERIES_KEPT = 256;
    private static final Map<ParsedQuery, Query> PARSED = Collections.synchronizedMap(
            new LinkedHashMap<>(PARSED_QUERIES_KEPT, 0.75f, true) {
                @Override
                protected boolean removeEldestEntry(Map.Entry<ParsedQuery, Query> eldest) {
                    return size() > PARSED_QUERIES_KEPT;
                }
            });

    private static Query parse(Reference reference, String text) {
        ParsedQuery key = new ParsedQuery(reference.names().prefixes(), reference.names().defaultNamespace(), text);
        Query parsed = PARSED.get(key);
        if (parsed == null) {
            parsed = parseAnew(reference, text);
            parsed.setResultVars();
            PARSED.put(key, parsed);
        }
        return parsed;
    }

    private static Query parseAnew(Reference reference, String text) {
        PrefixMapping prefixes = PrefixMapping.Factory.create();
        reference.names().prefixes().forEach(prefixes::setNsPrefix);
        prefixes.setNsPrefix("", reference.names().defaultNamespace());
        Query query = new Query();
        query.setPrefixMapping(prefixes);
        try {
            return QueryFactory.parse(query, text, null, org.apache.jena.query.Syntax.syntaxSPARQL_11);
        } catch (QueryParseException e) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "malformed SPARQL: " + e.getMessage()
                    .replaceAll("\\s+", " ").trim(), e);
        }
    }

    private static String render(Rendering rendering, Node node) {
        if (node.isURI()) {
            return rendering.iri(node.getURI());
        }
        if (node.isLiteral()) {
            return Rendering.literal(node.getLiteralLexicalForm(), node.getLiteralLanguage(),
                    node.getLiteralDatatypeURI());
        }
        return "_:" + node.getBlankNodeLabel();
    }
}
