// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.Builtins.DataValue;
import io.github.armor.core.reasoning.RuleProgram.Atom;
import io.github.armor.core.reasoning.RuleProgram.Kind;
import io.github.armor.core.reasoning.RuleProgram.Rule;
import io.github.armor.core.reasoning.RuleProgram.Term;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeSet;
import org.semanticweb.owlapi.model.IRI;

/**
 * Where a replaced value can change the rest of a rule's join, when the rest enumerates the
 * values {@code v} of a data property and the only atoms that read what was replaced are
 * comparisons and arithmetic linear in {@code v}: the robot's clock {@code t} goes from 1000 to
 * 1040, and {@code subtract(age, t, v), greaterThan(age, k)} holds for {@code v < t - k}, before
 * and after; only the rooms whose last visit lies between 900 and 940 can start or stop being
 * URGENT. The other values give the same matches before and after, with the same conclusions
 * (nothing else in the rest reads what was replaced, and a conclusion cannot name a computed
 * value), so their counts would not move: they are not visited at all ({@link OrderedValues}).
 *
 * <p>The arithmetic is exact (decimals, as {@link Builtins} computes it), so a range's ends are
 * exactly where a comparison turns: a value at the boundary is placed as the built-in places it.
 * Anything else (a built-in not linear in {@code v}, a bound operand that is not a decimal, a
 * threshold read after the enumeration) leaves the join as it was.
 */
final class FlipRanges {
    /** Values from {@code low} to {@code high} (null: unbounded), each end included or not. */
    record Range(BigDecimal low, boolean lowIncluded, BigDecimal high, boolean highIncluded) {
        boolean contains(BigDecimal value) {
            int fromLow = low == null ? 1 : value.compareTo(low);
            int toHigh = high == null ? -1 : value.compareTo(high);
            return (fromLow > 0 || fromLow == 0 && lowIncluded) && (toHigh < 0 || toHigh == 0 && highIncluded);
        }
    }

    /** The enumerated value atom (by its index in the body) and the value ranges whose matches differ. */
    record Flips(int atom, int subject, int value, List<Range> ranges) {}

    /** {@code a * v + b}, with {@code v} the enumerated value. */
    private record Linear(BigDecimal a, BigDecimal b) {
        static Linear constant(BigDecimal b) {
            return new Linear(BigDecimal.ZERO, b);
        }

        Linear plus(Linear other) {
            return new Linear(a.add(other.a), b.add(other.b));
        }

        Linear times(BigDecimal factor) {
            return new Linear(a.multiply(factor), b.multiply(factor));
        }
    }

    /** A world's set of values: an interval, or nothing. */
    private static final class Interval {
        Range range = new Range(null, false, null, false);
        boolean empty;

        void narrow(Range other) {
            BigDecimal low = range.low;
            boolean lowIncluded = range.lowIncluded;
            if (other.low != null && (low == null || other.low.compareTo(low) > 0
                    || other.low.compareTo(low) == 0 && !other.lowIncluded)) {
                low = other.low;
                lowIncluded = other.lowIncluded;
            }
            BigDecimal high = range.high;
            boolean highIncluded = range.highIncluded;
            if (other.high != null && (high == null || other.high.compareTo(high) < 0
                    || other.high.compareTo(high) == 0 && !other.highIncluded)) {
                high = other.high;
                highIncluded = other.highIncluded;
            }
            range = new Range(low, lowIncluded, high, highIncluded);
        }

        boolean contains(BigDecimal value) {
            return !empty && range.contains(value);
        }
    }

    private FlipRanges() {
    }

    /**
     * The flips of the rest of a paired join (atoms {@code plan[step..]}, bindings before and
     * after the replacement), or null when the rest is not of that shape.
     */
    static Flips of(Rule rule, int[] plan, int step, Object[] before, Object[] after) {
        int enumerated = -1;
        for (int s = step; s < plan.length && enumerated < 0; s++) {
            Atom atom = rule.body().get(plan[s]);
            if (atom.kind() == Kind.VALUE && unbound(atom.term(0), before) && unbound(atom.term(1), before)
                    && atom.term(0).variable() != atom.term(1).variable()) {
                enumerated = plan[s];
            }
        }
        if (enumerated < 0) {
            return null;
        }
        Set<Integer> differing = new HashSet<>();
        for (int i = 0; i < before.length; i++) {
            if (!Objects.equals(before[i], after[i])) {
                differing.add(i);
            }
        }
        if (differing.isEmpty()) {
            return null;
        }
        for (Atom atom : rule.head()) {
            if (reads(atom, differing)) {
                return null;
            }
        }
        int value = rule.body().get(enumerated).term(1).variable();
        Set<Integer> tracked = new HashSet<>(differing);
        tracked.add(value);
        Interval[] worlds = {new Interval(), new Interval()};
        List<Map<Integer, Linear>> known = List.of(linears(before, value), linears(after, value));
        for (int s = step; s < plan.length; s++) {
            Atom atom = rule.body().get(plan[s]);
            if (atom.kind() != Kind.BUILTIN) {
                if (reads(atom, differing) || readsComputed(atom, tracked, value)) {
                    return null;
                }
                continue;
            }
            if (!reads(atom, tracked)) {
                continue;
            }
            for (int world = 0; world < 2; world++) {
                if (!narrow(atom, known.get(world), worlds[world], tracked)) {
                    return null;
                }
            }
        }
        return new Flips(enumerated, rule.body().get(enumerated).term(0).variable(), value,
                difference(worlds[0], worlds[1]));
    }

    private static boolean unbound(Term term, Object[] binding) {
        return term.isVariable() && binding[term.variable()] == null;
    }

    private static boolean reads(Atom atom, Set<Integer> variables) {
        for (Term term : atom.terms()) {
            if (term.isVariable() && variables.contains(term.variable())) {
                return true;
            }
        }
        return false;
    }

    private static boolean readsComputed(Atom atom, Set<Integer> tracked, int value) {
        for (Term term : atom.terms()) {
            if (term.isVariable() && term.variable() != value && tracked.contains(term.variable())) {
                return true;
            }
        }
        return false;
    }

    /** The bound decimal variables as constants, and the enumerated value as itself. */
    private static Map<Integer, Linear> linears(Object[] binding, int value) {
        Map<Integer, Linear> known = new HashMap<>();
        for (int i = 0; i < binding.length; i++) {
            if (binding[i] instanceof DataValue data && data.decimal() != null) {
                known.put(i, Linear.constant(data.decimal()));
            }
        }
        known.put(value, new Linear(BigDecimal.ONE, BigDecimal.ZERO));
        return known;
    }

    /** One built-in that reads a tracked variable, in one world: false when it is not linear in the value. */
    private static boolean narrow(Atom atom, Map<Integer, Linear> known, Interval world, Set<Integer> tracked) {
        IRI builtin = (IRI) atom.predicate();
        String name = builtin.toString().substring(Builtins.SWRLB.length());
        Term[] terms = atom.terms();
        boolean computes = Builtins.binds(builtin);
        Linear[] operands = new Linear[terms.length];
        for (int i = computes ? 1 : 0; i < terms.length; i++) {
            operands[i] = linear(terms[i], known);
            if (operands[i] == null) {
                return false;
            }
        }
        if (!computes) {
            return compare(name, operands[0], operands[1], world);
        }
        Linear result = switch (name) {
            case "add" -> operands[1].plus(operands[2]);
            case "subtract" -> operands[1].plus(operands[2].times(BigDecimal.ONE.negate()));
            case "multiply" -> operands[1].a.signum() == 0 ? operands[2].times(operands[1].b)
                    : operands[2].a.signum() == 0 ? operands[1].times(operands[2].b) : null;
            case "unaryMinus" -> operands[1].times(BigDecimal.ONE.negate());
            case "unaryPlus" -> operands[1];
            default -> null;
        };
        if (result == null) {
            return false;
        }
        Term target = terms[0];
        if (target.isVariable() && !known.containsKey(target.variable())) {
            known.put(target.variable(), result);
            tracked.add(target.variable());
            return true;
        }
        // The result is given: the built-in tests that it equals what it computes.
        Linear given = linear(target, known);
        return given != null && compare("equal", given, result, world);
    }

    private static Linear linear(Term term, Map<Integer, Linear> known) {
        if (term.isVariable()) {
            return known.get(term.variable());
        }
        return term.constant() instanceof DataValue data && data.decimal() != null
                ? Linear.constant(data.decimal()) : null;
    }

    /** {@code left op right} as a range of the value, narrowing the world's interval. */
    private static boolean compare(String name, Linear left, Linear right, Interval world) {
        if (name.equals("notEqual")) {
            return false; // two ranges; left to the join
        }
        // (left.a - right.a) * v  op  right.b - left.b
        BigDecimal slope = left.a.subtract(right.a);
        BigDecimal bound = right.b.subtract(left.b);
        if (slope.signum() == 0) {
            int order = BigDecimal.ZERO.compareTo(bound);
            boolean holds = switch (name) {
                case "equal" -> order == 0;
                case "lessThan" -> order < 0;
                case "lessThanOrEqual" -> order <= 0;
                case "greaterThan" -> order > 0;
                default -> order >= 0;
            };
            world.empty |= !holds;
            return true;
        }
        BigDecimal at;
        try {
            at = bound.divide(slope);
        } catch (ArithmeticException e) {
            return false; // no exact decimal end (a slope of 3)
        }
        String turned = slope.signum() > 0 ? name : switch (name) {
            case "lessThan" -> "greaterThan";
            case "lessThanOrEqual" -> "greaterThanOrEqual";
            case "greaterThan" -> "lessThan";
            case "greaterThanOrEqual" -> "lessThanOrEqual";
            default -> name;
        };
        Range range = switch (turned) {
            case "equal" -> new Range(at, true, at, true);
            case "lessThan" -> new Range(null, false, at, false);
            case "lessThanOrEqual" -> new Range(null, false, at, true);
            case "greaterThan" -> new Range(at, false, null, false);
            case "greaterThanOrEqual" -> new Range(at, true, null, false);
            default -> null;
        };
        if (range == null) {
            return false;
        }
        world.narrow(range);
        return true;
    }

    /**
     * The values in one world's interval and not the other's, as disjoint ranges: the line is
     * cut at every end of both intervals, and each piece (an end, or the open stretch between
     * two) is kept when the worlds disagree on it.
     */
    private static List<Range> difference(Interval first, Interval second) {
        TreeSet<BigDecimal> ends = new TreeSet<>();
        for (Interval world : new Interval[] {first, second}) {
            if (world.range.low != null) {
                ends.add(world.range.low);
            }
            if (world.range.high != null) {
                ends.add(world.range.high);
            }
        }
        List<Range> pieces = new ArrayList<>();
        BigDecimal previous = null;
        for (BigDecimal end : ends) {
            pieces.add(new Range(previous, false, end, false));
            pieces.add(new Range(end, true, end, true));
            previous = end;
        }
        pieces.add(new Range(previous, false, null, false));
        List<Range> differ = new ArrayList<>();
        for (Range piece : pieces) {
            BigDecimal inside = inside(piece);
            if (inside != null && first.contains(inside) != second.contains(inside)) {
                differ.add(piece);
            }
        }
        return differ;
    }

    /** A value inside a piece, or null for an empty one. */
    private static BigDecimal inside(Range piece) {
        if (piece.low == null && piece.high == null) {
            return BigDecimal.ZERO;
        }
        if (piece.low == null) {
            return piece.high.subtract(BigDecimal.ONE);
        }
        if (piece.high == null) {
            return piece.low.add(BigDecimal.ONE);
        }
        if (piece.low.compareTo(piece.high) == 0) {
            return piece.lowIncluded ? piece.low : null;
        }
        return piece.low.add(piece.high).divide(BigDecimal.valueOf(2));
    }
}
