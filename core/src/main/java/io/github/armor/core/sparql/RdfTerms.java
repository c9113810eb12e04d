// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import java.util.HashMap;
import java.util.Map;
import org.apache.jena.datatypes.TypeMapper;
import org.apache.jena.graph.Graph;
import org.apache.jena.graph.Node;
import org.apache.jena.graph.NodeFactory;
import org.apache.jena.graph.Triple;
import org.apache.jena.vocabulary.RDF;
import org.eclipse.rdf4j.model.BNode;
import org.eclipse.rdf4j.model.Literal;
import org.eclipse.rdf4j.model.Statement;
import org.eclipse.rdf4j.model.Value;
import org.eclipse.rdf4j.rio.helpers.AbstractRDFHandler;
import org.semanticweb.owlapi.formats.NTriplesDocumentFormat;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassAssertionAxiom;
import org.semanticweb.owlapi.model.OWLDataPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLDeclarationAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.rio.RioRenderer;
import org.semanticweb.owlapi.vocab.OWLRDFVocabulary;

/**
 * OWL API objects as Jena RDF terms, written exactly as the OWL API's own RDF renderers write
 * them, so that a graph built piece by piece equals the one its N-Triples file would give.
 */
final class RdfTerms {
    static final Node TYPE = RDF.Nodes.type;
    static final Node NAMED_INDIVIDUAL = NodeFactory.createURI(OWLRDFVocabulary.OWL_NAMED_INDIVIDUAL.getIRI().toString());

    private RdfTerms() {}

    static Node iri(IRI iri) {
        return NodeFactory.createURI(iri.toString());
    }

    static Node entity(OWLEntity entity) {
        return iri(entity.getIRI());
    }

    static Node literal(OWLLiteral literal) {
        return literal(literal.getLiteral(), literal.getLang(), literal.getDatatype().getIRI().toString());
    }

    static Node literal(String lexical, String language, String datatypeIri) {
        if (!language.isEmpty()) {
            return NodeFactory.createLiteral(lexical, language);
        }
        return NodeFactory.createLiteral(lexical, TypeMapper.getInstance().getSafeTypeByName(datatypeIri));
    }

    /** Adds to {@code graph} every triple of the ontology's RDF rendering (the OWL API's, as for N-Triples). */
    static void render(OWLOntology ontology, Graph graph) {
        Map<String, Node> blankNodes = new HashMap<>();
        new RioRenderer(ontology, new AbstractRDFHandler() {
            @Override
            public void handleStatement(Statement statement) {
                graph.add(Triple.create(node(statement.getSubject(), blankNodes),
                        node(statement.getPredicate(), blankNodes), node(statement.getObject(), blankNodes)));
            }
        }, new NTriplesDocumentFormat()).render();
    }

    private static Node node(Value value, Map<String, Node> blankNodes) {
        if (value instanceof org.eclipse.rdf4j.model.IRI iri) {
            return NodeFactory.createURI(iri.stringValue());
        }
        if (value instanceof BNode blank) {
            return blankNodes.computeIfAbsent(blank.getID(), id -> NodeFactory.createBlankNode());
        }
        Literal literal = (Literal) value;
        return literal(literal.getLabel(), literal.getLanguage().orElse(""), literal.getDatatype().stringValue());
    }

    /**
     * The single triple an unannotated assertion about named things renders as: an individual's
     * declaration, its class (a named one), an object property value between named individuals
     * (through a named property), a data property value. Null for every other axiom.
     */
    static Triple assertion(OWLAxiom axiom) {
        if (axiom.isAnnotated()) {
            return null;
        }
        if (axiom instanceof OWLDeclarationAxiom declaration) {
            OWLEntity entity = declaration.getEntity();
            return entity.isOWLNamedIndividual() ? Triple.create(entity(entity), TYPE, NAMED_INDIVIDUAL) : null;
        }
        if (axiom instanceof OWLClassAssertionAxiom assertion) {
            return assertion.getIndividual().isNamed() && !assertion.getClassExpression().isAnonymous()
                    ? Triple.create(iri(assertion.getIndividual().asOWLNamedIndividual().getIRI()), TYPE,
                    entity(assertion.getClassExpression().asOWLClass())) : null;
        }
        if (axiom instanceof OWLObjectPropertyAssertionAxiom assertion) {
            return assertion.getSubject().isNamed() && assertion.getObject().isNamed()
                    && assertion.getProperty().isNamed()
                    ? Triple.create(iri(assertion.getSubject().asOWLNamedIndividual().getIRI()),
                    entity(assertion.getProperty().asOWLObjectProperty()),
                    iri(assertion.getObject().asOWLNamedIndividual().getIRI())) : null;
        }
        if (axiom instanceof OWLDataPropertyAssertionAxiom assertion) {
            return assertion.getSubject().isNamed() && assertion.getProperty().isNamed()
                    ? Triple.create(iri(assertion.getSubject().asOWLNamedIndividual().getIRI()),
                    entity(assertion.getProperty().asOWLDataProperty()), literal(assertion.getObject())) : null;
        }
        return null;
    }
}
