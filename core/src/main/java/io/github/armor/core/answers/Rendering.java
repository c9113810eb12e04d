// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.answers;

import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.vocab.Namespaces;

/** How entities and literals are written into {@code queried_objects} (contract section 4). */
public final class Rendering {
    private static final int SHORT_FORMS_KEPT = 100_000;

    private final boolean fullIri;
    private final Map<String, String> shortForms = new ConcurrentHashMap<>();

    public Rendering(boolean fullIri) {
        this.fullIri = fullIri;
    }

    public String entity(OWLEntity entity) {
        return iri(entity.getIRI());
    }

    public String iri(IRI iri) {
        return fullIri ? "<" + iri + ">" : iri.getShortForm();
    }

    /**
     * An IRI given as text (SPARQL rows): the same form, without making an OWL API IRI for every
     * value. Short forms are remembered, as rows name the same IRIs again and again.
     */
    public String iri(String iri) {
        if (fullIri) {
            return "<" + iri + ">";
        }
        String shortForm = shortForms.get(iri);
        if (shortForm == null) {
            if (shortForms.size() >= SHORT_FORMS_KEPT) {
                shortForms.clear();
            }
            shortForm = IRI.create(iri).getShortForm();
            shortForms.put(iri, shortForm);
        }
        return shortForm;
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
