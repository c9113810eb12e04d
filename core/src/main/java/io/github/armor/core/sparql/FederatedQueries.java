// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import org.apache.jena.query.Query;
import org.apache.jena.sparql.algebra.Algebra;
import org.apache.jena.sparql.algebra.Op;
import org.apache.jena.sparql.algebra.OpVisitorBase;
import org.apache.jena.sparql.algebra.op.OpGroup;
import org.apache.jena.sparql.algebra.op.OpOrder;
import org.apache.jena.sparql.algebra.op.OpService;
import org.apache.jena.sparql.algebra.walker.Walker;
import org.apache.jena.sparql.expr.ExprFunctionOp;
import org.apache.jena.sparql.expr.ExprVisitorBase;

/**
 * Whether a SPARQL query has a SERVICE clause anywhere: in its pattern, a subquery, an OPTIONAL
 * or MINUS, or a pattern inside an expression (EXISTS in a FILTER, a projection, ORDER BY,
 * GROUP BY, HAVING or an aggregate).
 */
final class FederatedQueries {
    private FederatedQueries() {}

    static boolean uses(Query query) {
        return uses(Algebra.compile(query));
    }

    private static boolean uses(Op op) {
        boolean[] found = {false};
        ExprVisitorBase patternsInExpressions = new ExprVisitorBase() {
            @Override
            public void visit(ExprFunctionOp function) {
                if (function.getGraphPattern() != null && uses(function.getGraphPattern())) {
                    found[0] = true;
                }
            }
        };
        OpVisitorBase services = new OpVisitorBase() {
            @Override
            public void visit(OpService service) {
                found[0] = true;
            }

            // The walker leaves these expressions out.
            @Override
            public void visit(OpOrder order) {
                order.getConditions().forEach(c -> Walker.walk(c.getExpression(), patternsInExpressions));
            }

            @Override
            public void visit(OpGroup group) {
                group.getAggregators().stream().map(a -> a.getAggregator().getExprList())
                        .filter(java.util.Objects::nonNull)
                        .forEach(list -> list.forEach(e -> Walker.walk(e, patternsInExpressions)));
            }
        };
        Walker.walk(op, services, patternsInExpressions);
        return found[0];
    }
}
