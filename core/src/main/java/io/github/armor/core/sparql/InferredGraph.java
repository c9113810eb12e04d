// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.sparql;

import io.github.armor.core.answers.Inferences;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reference.Reference;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.Supplier;
import java.util.stream.Stream;
import org.apache.jena.graph.Graph;
import org.apache.jena.graph.Node;
import org.apache.jena.graph.NodeFactory;
import org.apache.jena.graph.Triple;
import org.apache.jena.sparql.graph.GraphFactory;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.util.InferredAxiomGenerator;
import org.semanticweb.owlapi.util.InferredClassAssertionAxiomGenerator;
import org.semanticweb.owlapi.util.InferredDataPropertyCharacteristicAxiomGenerator;
import org.semanticweb.owlapi.util.InferredEquivalentClassAxiomGenerator;
import org.semanticweb.owlapi.util.InferredPropertyAssertionGenerator;
import org.semanticweb.owlapi.util.InferredSubClassAxiomGenerator;

/**
 * The RDF graph that SPARQL queries of a reference run on, for one state of the reference (its
 * modification count): the ontology's triples as the OWL API renders it, the inferred class
 * hierarchy, and every individual's inferred named types and property values; the same triples
 * as the ontology saved with its inferences (SAVE INFERENCE).
 *
 * <p>Never changed once made, so any number of queries read it at once: a fresh graph is an
 * {@link IndexedGraph}, a derived one a {@link LayeredGraph} over it. The next state's graph is
 * derived from this one when only assertions about named individuals changed: every class's
 * instances are asked again (one question per class) and compared with this graph's, and the
 * property values of the individuals the changes name are asked again (of every individual
 * where {@link PropertyValueScope} says values can travel). Anything else builds it afresh.
 */
final class InferredGraph {
    private final long version;
    private final Graph graph;
    private final JoinOrder joinOrder;
    private final Basis basis;

    /**
     * How the graph was made, for deriving the next one: the ontology's classes and properties
     * (an assertion that adds or drops one forces a fresh build), its individuals and the
     * inferred instances of each class (IRIs), and which questions the reasoner answered. Null
     * when the next graph is built afresh.
     */
    private record Basis(List<OWLClass> classes, Set<Node> classNodes, Set<OWLEntity> schema,
                         Set<Node> propertyNodes, PropertyValueScope scope, Set<String> individuals,
                         Map<OWLClass, Set<String>> instances, boolean typesAnswered, boolean valuesAnswered) {}

    private InferredGraph(long version, Graph graph, JoinOrder joinOrder, Basis basis) {
        this.version = version;
        this.graph = graph;
        this.joinOrder = joinOrder;
        this.basis = basis;
    }

    long version() {
        return version;
    }

    /** The triples; never changed, read by queries outside the reference's lock. */
    Graph graph() {
        return graph;
    }

    /** The order in which queries on this graph join their patterns. */
    JoinOrder joinOrder() {
        return joinOrder;
    }

    /** Whether the next state's graph may be derived from this one (else it is built afresh). */
    boolean derivable() {
        return basis != null;
    }

    /** The graph of the reference as it is now; under the reference's lock. */
    static InferredGraph build(Reference reference, long version) {
        OWLReasoner reasoner = reference.reasonerForQuery();
        OWLOntology ontology = reference.ontology();
        Graph graph = GraphFactory.createGraphMem();
        RdfTerms.render(withInferredSchema(reference), graph);
        if (!reasoner.getPendingChanges().isEmpty()) {
            // A buffered reasoner that has not seen the latest changes: it is asked as SAVE INFERENCE
            // asks it, about every individual of the ontology, and the graph is not derived from.
            for (InferredAxiomGenerator<? extends OWLAxiom> generator : List.of(
                    new InferredClassAssertionAxiomGenerator(), new InferredPropertyAssertionGenerator())) {
                Set<? extends OWLAxiom> axioms = answered(reference,
                        () -> generator.createAxioms(reference.factory(), reasoner));
                if (axioms != null) {
                    axioms.stream().map(RdfTerms::assertion).filter(Objects::nonNull).forEach(graph::add);
                }
            }
            return fresh(version, graph, null);
        }
        List<OWLClass> classes = classes(ontology, reference.factory());
        List<OWLNamedIndividual> individuals = ontology.individualsInSignature(Imports.INCLUDED).toList();
        Set<String> names = new HashSet<>();
        individuals.forEach(i -> names.add(i.getIRI().toString()));
        Map<OWLClass, Set<String>> instances = answered(reference,
                () -> ReasonerAnswers.instances(reasoner, classes, names));
        if (instances != null) {
            Node thing = RdfTerms.entity(reference.factory().getOWLThing());
            // Every individual is a Thing, also one the reasoner has not met (HermiT omits
            // individuals that are only declared from the instances of owl:Thing).
            names.forEach(name -> graph.add(Triple.create(NodeFactory.createURI(name), RdfTerms.TYPE, thing)));
            instances.forEach((owlClass, members) -> {
                Node type = RdfTerms.entity(owlClass);
                members.forEach(name -> graph.add(Triple.create(NodeFactory.createURI(name), RdfTerms.TYPE, type)));
            });
        }
        PropertyValueScope scope = PropertyValueScope.of(ontology);
        List<Triple> values = answered(reference, () -> {
            List<Triple> found = new ArrayList<>();
            ReasonerAnswers.values(reasoner, ontology, scope, individuals, found::add);
            return found;
        });
        if (values != null) {
            values.forEach(graph::add);
        }
        Basis basis = derivable(ontology)
                ? basis(ontology, classes, scope, names, instances, values != null) : null;
        return fresh(version, graph, basis);
    }

    private static InferredGraph fresh(long version, Graph triples, Basis basis) {
        IndexedGraph graph = IndexedGraph.copyOf(triples);
        return new InferredGraph(version, graph, JoinOrder.of(graph), basis);
    }

    /**
     * The graph of the reference as it is now, derived from this one after {@code changes} (every
     * ontology change since this graph was made); null when it must be built afresh. Under the
     * reference's lock.
     */
    InferredGraph updated(Reference reference, List<OWLOntologyChange> changes, long newVersion) {
        if (basis == null) {
            return null;
        }
        OWLReasoner reasoner = reference.reasonerForQuery();
        if (!reasoner.getPendingChanges().isEmpty()) {
            return null;
        }
        OWLOntology ontology = reference.ontology();
        Set<OWLNamedIndividual> mentioned = new LinkedHashSet<>();
        boolean spreads = false;
        for (OWLOntologyChange change : changes) {
            if (!change.isAxiomChange() || RdfTerms.assertion(change.getAxiom()) == null) {
                return null;
            }
            OWLAxiom axiom = change.getAxiom();
            for (OWLEntity entity : (Iterable<OWLEntity>) axiom.signature()::iterator) {
                if (entity.isOWLNamedIndividual()) {
                    mentioned.add(entity.asOWLNamedIndividual());
                } else if (!entity.isBuiltIn() && (!basis.schema().contains(entity)
                        || !ontology.containsEntityInSignature(entity, Imports.INCLUDED))) {
                    return null;
                }
            }
            if (axiom instanceof OWLObjectPropertyAssertionAxiom assertion && basis.valuesAnswered()) {
                spreads |= answered(reference, () -> basis.scope().spreads(reasoner,
                        assertion.getProperty().asOWLObjectProperty())) != Boolean.FALSE;
            }
        }
        List<Triple> additions = new ArrayList<>();
        List<Triple> removals = new ArrayList<>();
        Set<String> individuals = new HashSet<>(basis.individuals());
        Set<String> touched = new LinkedHashSet<>();
        for (OWLNamedIndividual individual : mentioned) {
            String name = individual.getIRI().toString();
            touched.add(name);
            if (ontology.containsEntityInSignature(individual, Imports.INCLUDED)) {
                individuals.add(name);
            } else {
                individuals.remove(name);
            }
        }
        Map<OWLClass, Set<String>> instances = basis.instances();
        if (basis.typesAnswered()) {
            instances = answered(reference, () -> ReasonerAnswers.instances(reasoner, basis.classes(), individuals));
            if (instances == null) {
                return null;
            }
            for (Map.Entry<OWLClass, Set<String>> members : instances.entrySet()) {
                Set<String> before = basis.instances().getOrDefault(members.getKey(), Set.of());
                if (!before.equals(members.getValue())) {
                    before.stream().filter(name -> !members.getValue().contains(name)).forEach(touched::add);
                    members.getValue().stream().filter(name -> !before.contains(name)).forEach(touched::add);
                }
            }
        }
        OWLDataFactory factory = reference.factory();
        for (String name : touched) {
            Node individual = NodeFactory.createURI(name);
            Set<Triple> wanted = new HashSet<>();
            if (basis.typesAnswered()) {
                for (OWLClass owlClass : basis.classes()) {
                    if (owlClass.isOWLThing() ? individuals.contains(name) : instances.get(owlClass).contains(name)) {
                        wanted.add(Triple.create(individual, RdfTerms.TYPE, RdfTerms.entity(owlClass)));
                    }
                }
            }
            asserted(ontology, factory.getOWLNamedIndividual(IRI.create(name)), AssertionKind.TYPE).forEach(wanted::add);
            reconcile(graph.find(individual, RdfTerms.TYPE, Node.ANY)
                    .filterKeep(t -> basis.classNodes().contains(t.getObject())).toSet(), wanted, additions, removals);
        }
        Collection<OWLNamedIndividual> valuesOf = spreads
                ? union(ontology.individualsInSignature(Imports.INCLUDED).toList(), mentioned) : mentioned;
        Map<Node, Set<Triple>> inferredValues = new HashMap<>();
        if (basis.valuesAnswered()) {
            List<OWLNamedIndividual> known = valuesOf.stream()
                    .filter(i -> ontology.containsEntityInSignature(i, Imports.INCLUDED)).toList();
            Boolean answeredValues = answered(reference, () -> {
                ReasonerAnswers.values(reasoner, ontology, basis.scope(), known, t -> inferredValues
                        .computeIfAbsent(t.getSubject(), s -> new HashSet<>()).add(t));
                return true;
            });
            if (answeredValues == null) {
                return null;
            }
        }
        for (OWLNamedIndividual individual : valuesOf) {
            Node subject = RdfTerms.entity(individual);
            Set<Triple> wanted = new HashSet<>(inferredValues.getOrDefault(subject, Set.of()));
            asserted(ontology, individual, AssertionKind.VALUE).forEach(wanted::add);
            reconcile(graph.find(subject, Node.ANY, Node.ANY)
                    .filterKeep(t -> basis.propertyNodes().contains(t.getPredicate())).toSet(), wanted, additions, removals);
        }
        for (OWLNamedIndividual individual : mentioned) {
            Triple declared = Triple.create(RdfTerms.entity(individual), RdfTerms.TYPE, RdfTerms.NAMED_INDIVIDUAL);
            boolean wanted = ontology.containsEntityInSignature(individual, Imports.INCLUDED);
            if (wanted != graph.contains(declared)) {
                (wanted ? additions : removals).add(declared);
            }
        }
        Basis next = new Basis(basis.classes(), basis.classNodes(), basis.schema(), basis.propertyNodes(),
                basis.scope(), individuals, instances, basis.typesAnswered(), basis.valuesAnswered());
        return new InferredGraph(newVersion, LayeredGraph.apply(graph, additions, removals), joinOrder, next);
    }

    private enum AssertionKind { TYPE, VALUE }

    /** The triples of the individual's asserted named types, or of its asserted property values. */
    private static Stream<Triple> asserted(OWLOntology ontology, OWLNamedIndividual individual, AssertionKind kind) {
        return ontology.importsClosure().flatMap(o -> kind == AssertionKind.TYPE ? o.classAssertionAxioms(individual)
                        : Stream.concat(o.objectPropertyAssertionAxioms(individual), o.dataPropertyAssertionAxioms(individual)))
                .map(RdfTerms::assertion).filter(Objects::nonNull);
    }

    private static void reconcile(Set<Triple> present, Set<Triple> wanted, List<Triple> additions,
                                  List<Triple> removals) {
        wanted.stream().filter(t -> !present.contains(t)).forEach(additions::add);
        present.stream().filter(t -> !wanted.contains(t)).forEach(removals::add);
    }

    private static <T> Set<T> union(Collection<T> first, Collection<T> second) {
        Set<T> all = new LinkedHashSet<>(first);
        all.addAll(second);
        return all;
    }

    /**
     * Whether later graphs can be derived from this one: each individual's assertions must render
     * as the plain triples {@link RdfTerms#assertion} gives (no anonymous individuals, no
     * assertions through inverse properties), and no property may also be an annotation property.
     */
    private static boolean derivable(OWLOntology ontology) {
        if (ontology.importsClosure().anyMatch(o -> o.anonymousIndividuals().findAny().isPresent())) {
            return false;
        }
        if (ontology.importsClosure().flatMap(o -> o.axioms(org.semanticweb.owlapi.model.AxiomType
                .OBJECT_PROPERTY_ASSERTION)).anyMatch(a -> a.getProperty().isAnonymous())) {
            return false;
        }
        Set<IRI> annotationProperties = new HashSet<>();
        ontology.annotationPropertiesInSignature(Imports.INCLUDED).forEach(p -> annotationProperties.add(p.getIRI()));
        return Stream.concat(ontology.objectPropertiesInSignature(Imports.INCLUDED),
                ontology.dataPropertiesInSignature(Imports.INCLUDED)).noneMatch(p -> annotationProperties.contains(p.getIRI()));
    }

    private static Basis basis(OWLOntology ontology, List<OWLClass> classes, PropertyValueScope scope,
                               Set<String> individuals, Map<OWLClass, Set<String>> instances,
                               boolean valuesAnswered) {
        Set<Node> classNodes = new HashSet<>();
        classes.forEach(c -> classNodes.add(RdfTerms.entity(c)));
        Set<OWLEntity> schema = new HashSet<>(classes);
        Set<Node> propertyNodes = new HashSet<>();
        ontology.signature(Imports.INCLUDED).filter(e -> !e.isOWLNamedIndividual()).forEach(e -> {
            schema.add(e);
            if (e.isOWLObjectProperty() || e.isOWLDataProperty()) {
                propertyNodes.add(RdfTerms.entity(e));
            }
        });
        return new Basis(classes, classNodes, schema, propertyNodes, scope, individuals,
                instances == null ? Map.of() : instances, instances != null, valuesAnswered);
    }

    /** The ontology's classes and owl:Thing: the types every individual is asked about. */
    private static List<OWLClass> classes(OWLOntology ontology, OWLDataFactory factory) {
        Set<OWLClass> classes = new LinkedHashSet<>();
        classes.add(factory.getOWLThing());
        ontology.classesInSignature(Imports.INCLUDED).filter(c -> !c.isOWLNothing()).forEach(classes::add);
        return List.copyOf(classes);
    }

    /**
     * A copy of the ontology (imports merged) with the inferred class hierarchy and data property
     * characteristics added, as SAVE INFERENCE adds them.
     */
    private static OWLOntology withInferredSchema(Reference reference) {
        OWLOntology copy = Inferences.copyWithImports(reference);
        OWLOntologyManager manager = copy.getOWLOntologyManager();
        OWLReasoner reasoner = reference.reasonerForQuery();
        for (InferredAxiomGenerator<? extends OWLAxiom> generator : List.of(new InferredSubClassAxiomGenerator(),
                new InferredEquivalentClassAxiomGenerator(), new InferredDataPropertyCharacteristicAxiomGenerator())) {
            Set<? extends OWLAxiom> axioms = answered(reference,
                    () -> generator.createAxioms(manager.getOWLDataFactory(), reasoner));
            if (axioms != null) {
                manager.addAxioms(copy, axioms.stream().map(OWLAxiom.class::cast));
            }
        }
        return copy;
    }

    /** The reasoner's answer within its time limit; null when this reasoner cannot answer such questions. */
    private static <T> T answered(Reference reference, Supplier<T> question) {
        try {
            return reference.guardReasoner(question);
        } catch (ArmorException e) {
            if (e.exitCode() == ExitCode.NOT_SUPPORTED) {
                return null;
            }
            throw e;
        }
    }
}
