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
        String quoted = "\"" + literal.getLiteral() + "\"";
        if (literal.hasLang()) {
            return quoted + "@" + literal.getLang();
        }
        IRI datatype = literal.getDatatype().getIRI();
        for (Namespaces known : List.of(Namespaces.XSD, Namespaces.RDF, Namespaces.RDFS, Namespaces.OWL)) {
            if (datatype.getNamespace().equals(known.getPrefixIRI())) {
                return quoted + "^^" + known.getPrefixName() + ":" + datatype.getRemainder().orElse("");
            }
        }
        return quoted + "^^<" + datatype + ">";
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
