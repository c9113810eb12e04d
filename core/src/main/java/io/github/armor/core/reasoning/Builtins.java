// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.math.BigDecimal;
import java.util.Map;
import java.util.Optional;
import java.util.Objects;
import java.util.Set;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.vocab.OWL2Datatype;

/**
 * The SWRL built-ins ({@code swrlb:}) ARMOR evaluates, over data values compared as OWL 2
 * compares them: integers and decimals by number (1 and 1.0 are one value), floats and doubles
 * apart from them, strings by text and language, anything else by datatype and lexical form.
 * Comparisons take numbers of any numeric type, and strings; arithmetic takes numbers of the
 * decimal family (integers and decimals), whose results are exact. A rule with any other
 * built-in is evaluated by the reasoner on the whole ontology.
 */
final class Builtins {
    static final String SWRLB = "http://www.w3.org/2003/11/swrlb#";
    private static final Set<String> COMPARISONS = Set.of("equal", "notEqual", "lessThan", "lessThanOrEqual",
            "greaterThan", "greaterThanOrEqual");
    /** Arithmetic: the first argument is the result (bound by the built-in when the body does not bind it). */
    private static final Map<String, Integer> ARITHMETIC = Map.of("add", 3, "subtract", 3, "multiply", 3, "mod", 3,
            "abs", 2, "unaryMinus", 2, "unaryPlus", 2);

    private Builtins() {
    }

    /** A data value as OWL 2 compares it, with a literal that has it (null for one a built-in computed). */
    static final class DataValue {
        final OWLLiteral literal;
        private final Object key;

        private DataValue(OWLLiteral literal, Object key) {
            this.literal = literal;
            this.key = key;
        }

        static DataValue of(OWLLiteral literal) {
            IRI datatype = literal.getDatatype().getIRI();
            if (OWL2Datatype.isBuiltIn(datatype)) {
                OWL2Datatype type = OWL2Datatype.getDatatype(datatype);
                try {
                    if (decimalFamily(type)) {
                        return new DataValue(literal, new BigDecimal(literal.getLiteral().trim()).stripTrailingZeros());
                    }
                    if (type == OWL2Datatype.XSD_DOUBLE || type == OWL2Datatype.XSD_FLOAT) {
                        // Float and double value spaces are apart from each other and from decimals.
                        return new DataValue(literal, new Floating(type == OWL2Datatype.XSD_FLOAT,
                                Double.parseDouble(literal.getLiteral().trim())));
                    }
                } catch (NumberFormatException e) {
                    return new DataValue(literal, literal);
                }
                if (type == OWL2Datatype.XSD_STRING || type == OWL2Datatype.RDF_PLAIN_LITERAL) {
                    return new DataValue(literal, new Text(literal.getLiteral(), literal.getLang()));
                }
            }
            return new DataValue(literal, literal);
        }

        static DataValue number(BigDecimal value) {
            return new DataValue(null, value.stripTrailingZeros());
        }

        BigDecimal decimal() {
            return key instanceof BigDecimal number ? number : null;
        }

        Double floating() {
            if (key instanceof BigDecimal number) {
                return number.doubleValue();
            }
            return key instanceof Floating floating ? floating.value : null;
        }

        @Override
        public boolean equals(Object other) {
            return other instanceof DataValue that && key.equals(that.key);
        }

        @Override
        public int hashCode() {
            return key.hashCode();
        }

        @Override
        public String toString() {
            return literal != null ? literal.toString() : key.toString();
        }
    }

    private record Floating(boolean single, double value) {}

    private record Text(String text, String language) {}

    private static boolean decimalFamily(OWL2Datatype type) {
        return switch (type) {
            case XSD_DECIMAL, XSD_INTEGER, XSD_INT, XSD_LONG, XSD_SHORT, XSD_BYTE, XSD_NON_NEGATIVE_INTEGER,
                 XSD_NON_POSITIVE_INTEGER, XSD_POSITIVE_INTEGER, XSD_NEGATIVE_INTEGER, XSD_UNSIGNED_LONG,
                 XSD_UNSIGNED_INT, XSD_UNSIGNED_SHORT, XSD_UNSIGNED_BYTE -> true;
            default -> false;
        };
    }

    /** Whether ARMOR evaluates this built-in with this many arguments. */
    static boolean supports(IRI builtin, int arguments) {
        String name = name(builtin);
        return name != null && (COMPARISONS.contains(name) && arguments == 2
                || ARITHMETIC.getOrDefault(name, -1) == arguments);
    }

    /** Whether the built-in computes its first argument (arithmetic) rather than only testing its arguments. */
    static boolean binds(IRI builtin) {
        String name = name(builtin);
        return name != null && ARITHMETIC.containsKey(name);
    }

    // Built-ins are tested once per match: their names are read once.
    private static final Map<IRI, Optional<String>> NAMES = new java.util.concurrent.ConcurrentHashMap<>();

    private static String name(IRI builtin) {
        return NAMES.computeIfAbsent(builtin, iri -> iri.toString().startsWith(SWRLB)
                ? Optional.of(iri.toString().substring(SWRLB.length())) : Optional.empty()).orElse(null);
    }

    /** A comparison's truth; both arguments are bound. */
    static boolean test(IRI builtin, DataValue left, DataValue right) {
        String name = name(builtin);
        if (name.equals("equal") || name.equals("notEqual")) {
            return left.equals(right) == name.equals("equal");
        }
        Integer order = compare(left, right);
        if (order == null) {
            return false;
        }
        return switch (name) {
            case "lessThan" -> order < 0;
            case "lessThanOrEqual" -> order <= 0;
            case "greaterThan" -> order > 0;
            default -> order >= 0;
        };
    }

    /** The result of an arithmetic built-in on its other arguments, or null when it has none (not numbers). */
    static DataValue compute(IRI builtin, DataValue[] operands) {
        BigDecimal[] numbers = new BigDecimal[operands.length];
        for (int i = 0; i < operands.length; i++) {
            numbers[i] = operands[i].decimal();
            if (numbers[i] == null) {
                return null;
            }
        }
        BigDecimal result = switch (Objects.requireNonNull(name(builtin))) {
            case "add" -> numbers[0].add(numbers[1]);
            case "subtract" -> numbers[0].subtract(numbers[1]);
            case "multiply" -> numbers[0].multiply(numbers[1]);
            case "mod" -> numbers[1].signum() == 0 ? null : numbers[0].remainder(numbers[1]);
            case "abs" -> numbers[0].abs();
            case "unaryMinus" -> numbers[0].negate();
            default -> numbers[0];
        };
        return result == null ? null : DataValue.number(result);
    }

    private static Integer compare(DataValue left, DataValue right) {
        if (left.decimal() != null && right.decimal() != null) {
            return left.decimal().compareTo(right.decimal());
        }
        if (left.floating() != null && right.floating() != null) {
            return Double.compare(left.floating(), right.floating());
        }
        if (left.key instanceof Text a && right.key instanceof Text b && Objects.equals(a.language, b.language)) {
            return a.text.compareTo(b.text);
        }
        return null;
    }
}
