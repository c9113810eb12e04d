// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.answers;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reference.EntityResolver;
import java.math.BigDecimal;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLDatatype;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.vocab.OWL2Datatype;

/** Builds typed literals from a directive's (type, value) pair, refusing values the type cannot hold. */
public final class Literals {
    private static final Map<String, OWL2Datatype> ARMOR_TYPES = Map.of(
            "STRING", OWL2Datatype.XSD_STRING,
            "INT", OWL2Datatype.XSD_INTEGER,
            "INTEGER", OWL2Datatype.XSD_INTEGER,
            "FLOAT", OWL2Datatype.XSD_FLOAT,
            "LONG", OWL2Datatype.XSD_LONG,
            "DOUBLE", OWL2Datatype.XSD_DOUBLE,
            "BOOL", OWL2Datatype.XSD_BOOLEAN,
            "BOOLEAN", OWL2Datatype.XSD_BOOLEAN);

    private static final Set<OWL2Datatype> NUMBERS = Set.of(OWL2Datatype.XSD_INTEGER, OWL2Datatype.XSD_LONG,
            OWL2Datatype.XSD_INT, OWL2Datatype.XSD_SHORT, OWL2Datatype.XSD_BYTE, OWL2Datatype.XSD_DECIMAL,
            OWL2Datatype.XSD_FLOAT, OWL2Datatype.XSD_DOUBLE, OWL2Datatype.XSD_NON_NEGATIVE_INTEGER,
            OWL2Datatype.XSD_NON_POSITIVE_INTEGER, OWL2Datatype.XSD_POSITIVE_INTEGER,
            OWL2Datatype.XSD_NEGATIVE_INTEGER, OWL2Datatype.XSD_UNSIGNED_LONG, OWL2Datatype.XSD_UNSIGNED_INT,
            OWL2Datatype.XSD_UNSIGNED_SHORT, OWL2Datatype.XSD_UNSIGNED_BYTE, OWL2Datatype.OWL_REAL,
            OWL2Datatype.OWL_RATIONAL);
    private static final Set<OWL2Datatype> TEXT = Set.of(OWL2Datatype.XSD_STRING, OWL2Datatype.RDF_PLAIN_LITERAL,
            OWL2Datatype.RDF_LANG_STRING);

    private Literals() {}

    /**
     * The stored value of {@code property} for {@code individual} that a REMOVE or REPLACE of
     * {@code given} means. A directive names a value by its type word and text, and the same value
     * is often stored with another datatype (100 as xsd:long, written by another client as INT;
     * "kitchen"@en, which no type word can name): the exact literal when it is stored, else the one
     * stored value equal to it (numbers by numeric value across the numeric datatypes, booleans by
     * truth value, strings by text whatever their language tag), else {@code given} itself (its
     * removal changes nothing, as in ARMOR).
     *
     * @throws ArmorException WRONG_ARGUMENTS when several stored values are equal to it
     */
    public static OWLLiteral stored(OWLOntology ontology, OWLDataProperty property, OWLNamedIndividual individual,
                                    OWLLiteral given) {
        List<OWLLiteral> values = values(ontology, property, individual);
        if (values.contains(given)) {
            return given;
        }
        List<OWLLiteral> equal = values.stream().filter(v -> sameValue(v, given)).toList();
        if (equal.size() > 1) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "value " + Rendering.literal(given) + " matches "
                    + equal.size() + " stored values of " + property.getIRI().getShortForm() + " for "
                    + individual.getIRI().getShortForm() + " (" + equal.stream().map(Rendering::literal)
                    .collect(Collectors.joining(", ")) + "); name the one meant with its own type, e.g. xsd:"
                    + equal.get(0).getDatatype().getIRI().getShortForm() + "; nothing changed");
        }
        return equal.isEmpty() ? given : equal.get(0);
    }

    /** The asserted values of a data property for an individual, in a stable order. */
    public static List<OWLLiteral> values(OWLOntology ontology, OWLDataProperty property,
                                          OWLNamedIndividual individual) {
        return ontology.dataPropertyAssertionAxioms(individual)
                .filter(a -> a.getProperty().equals(property)).map(a -> a.getObject()).sorted().toList();
    }

    /** Whether two literals denote the same value in ARMOR's sense (see {@link #stored}). */
    static boolean sameValue(OWLLiteral a, OWLLiteral b) {
        OWL2Datatype typeA = builtIn(a);
        OWL2Datatype typeB = builtIn(b);
        if (TEXT.contains(typeA) && TEXT.contains(typeB)) {
            return a.getLiteral().equals(b.getLiteral());
        }
        if (typeA == OWL2Datatype.XSD_BOOLEAN && typeB == OWL2Datatype.XSD_BOOLEAN) {
            return truth(a.getLiteral()) == truth(b.getLiteral());
        }
        if (NUMBERS.contains(typeA) && NUMBERS.contains(typeB)) {
            try {
                return new BigDecimal(a.getLiteral().trim()).compareTo(new BigDecimal(b.getLiteral().trim())) == 0;
            } catch (NumberFormatException e) {
                // INF, -INF, NaN: equal only as written
                return a.getLiteral().trim().equals(b.getLiteral().trim());
            }
        }
        return false;
    }

    private static OWL2Datatype builtIn(OWLLiteral literal) {
        if (literal.hasLang()) {
            return OWL2Datatype.RDF_LANG_STRING;
        }
        return literal.getDatatype().isBuiltIn() ? literal.getDatatype().getBuiltInDatatype() : null;
    }

    private static boolean truth(String lexical) {
        String value = lexical.trim();
        return value.equals("true") || value.equals("1");
    }

    public static OWLLiteral literal(OWLDataFactory factory, EntityResolver names, String type, String value) {
        OWLDatatype datatype = datatype(factory, names, type);
        if (datatype.isBuiltIn()) {
            OWL2Datatype builtIn = datatype.getBuiltInDatatype();
            if (builtIn == OWL2Datatype.XSD_BOOLEAN) {
                // Python clients write str(True): "True" is the same word, stored as xsd:boolean spells it.
                if (!value.equalsIgnoreCase("true") && !value.equalsIgnoreCase("false")) {
                    throw new ArmorException(ExitCode.BAD_DATA_TYPE,
                            "'" + value + "' is not a boolean: write true or false");
                }
                return factory.getOWLLiteral(value.toLowerCase(Locale.ROOT), datatype);
            }
            if (!builtIn.isInLexicalSpace(value)) {
                throw new ArmorException(ExitCode.BAD_DATA_TYPE,
                        "'" + value + "' is not a valid " + builtIn.getPrefixedName() + " value");
            }
        }
        return factory.getOWLLiteral(value, datatype);
    }

    /** ARMOR's type names (STRING, INT, FLOAT, LONG, DOUBLE, BOOL...) or any {@code xsd:} datatype. */
    public static OWLDatatype datatype(OWLDataFactory factory, EntityResolver names, String type) {
        String trimmed = type.trim();
        OWL2Datatype armor = ARMOR_TYPES.get(trimmed.toUpperCase(Locale.ROOT));
        if (armor != null) {
            return factory.getOWLDatatype(armor);
        }
        if (trimmed.regionMatches(true, 0, "xsd:", 0, 4)) {
            IRI iri = IRI.create("http://www.w3.org/2001/XMLSchema#" + trimmed.substring(4));
            if (OWL2Datatype.isBuiltIn(iri)) {
                return factory.getOWLDatatype(iri);
            }
        } else if (trimmed.startsWith("<") || trimmed.startsWith("http")) {
            try {
                IRI iri = names.iri(org.semanticweb.owlapi.model.EntityType.DATATYPE, trimmed);
                if (OWL2Datatype.isBuiltIn(iri)) {
                    return factory.getOWLDatatype(iri);
                }
            } catch (ArmorException e) {
                // fall through to the unknown-type answer below
            }
        }
        throw new ArmorException(ExitCode.BAD_DATA_TYPE, "unknown data type '" + type
                + "': expected STRING, INT, INTEGER, FLOAT, LONG, DOUBLE, BOOL, BOOLEAN or an xsd: datatype");
    }
}
