// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import java.util.Collection;
import java.util.List;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.vocab.Namespaces;

/** How entities and literals are written into {@code queried_objects} (contract section 4). */
public final class Rendering {
    private final boolean fullIri;

    public Rendering(boolean fullIri) {
        this.fullIri = fullIri;
    }

    public String entity(OWLEntity entity) {
        return iri(entity.getIRI());
    }

    public String iri(IRI iri) {
        return fullIri ? "<" + iri + ">" : iri.getShortForm();
    }

    /** {@code "lexical"^^xsd:type}, or {@code "text"@lang} for a language-tagged string. */
    public static String literal(OWLLiteral literal) {
        return literal(literal.getLiteral(), literal.hasLang() ? literal.getLang() : "",
                literal.getDatatype().getIRI().toString());
    }

    /** The same form from its parts, for literals that do not come from the OWL API (SPARQL rows). */
    public static String literal(String lexical, String language, String datatypeIri) {
        String quoted = "\"" + lexical + "\"";
        if (!language.isEmpty()) {
            return quoted + "@" + language;
        }
        for (Namespaces known : List.of(Namespaces.XSD, Namespaces.RDF, Namespaces.RDFS, Namespaces.OWL)) {
            if (datatypeIri.startsWith(known.getPrefixIRI())) {
                return quoted + "^^" + known.getPrefixName() + ":" + datatypeIri.substring(known.getPrefixIRI().length());
            }
        }
        return quoted + "^^<" + datatypeIri + ">";
    }

    /** Entities rendered, owl:Thing and owl:Nothing left out, sorted, without repeats. */
    public List<String> entities(Stream<? extends OWLEntity> entities) {
        return entities.filter(e -> !e.isTopEntity() && !e.isBottomEntity())
                .map(this::entity).distinct().sorted().toList();
    }

    public static List<String> literals(Collection<OWLLiteral> literals) {
        return literals.stream().map(Rendering::literal).distinct().sorted().toList();
    }
}
