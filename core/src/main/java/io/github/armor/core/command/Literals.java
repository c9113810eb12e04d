// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reference.EntityResolver;
import java.util.Locale;
import java.util.Map;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDatatype;
import org.semanticweb.owlapi.model.OWLLiteral;
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

    private Literals() {}

    public static OWLLiteral literal(OWLDataFactory factory, EntityResolver names, String type, String value) {
        OWLDatatype datatype = datatype(factory, names, type);
        if (datatype.isBuiltIn()) {
            OWL2Datatype builtIn = datatype.getBuiltInDatatype();
            if (builtIn == OWL2Datatype.XSD_BOOLEAN && !value.equals("true") && !value.equals("false")) {
                throw new ArmorException(ExitCode.BAD_DATA_TYPE,
                        "'" + value + "' is not a boolean: write true or false");
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
