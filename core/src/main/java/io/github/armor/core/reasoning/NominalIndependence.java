// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataPropertyDomainAxiom;
import org.semanticweb.owlapi.model.OWLDisjointClassesAxiom;
import org.semanticweb.owlapi.model.OWLDisjointUnionAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLEquivalentClassesAxiom;
import org.semanticweb.owlapi.model.OWLObjectAllValuesFrom;
import org.semanticweb.owlapi.model.OWLObjectComplementOf;
import org.semanticweb.owlapi.model.OWLObjectExactCardinality;
import org.semanticweb.owlapi.model.OWLObjectHasValue;
import org.semanticweb.owlapi.model.OWLObjectIntersectionOf;
import org.semanticweb.owlapi.model.OWLObjectMaxCardinality;
import org.semanticweb.owlapi.model.OWLObjectMinCardinality;
import org.semanticweb.owlapi.model.OWLObjectOneOf;
import org.semanticweb.owlapi.model.OWLObjectPropertyDomainAxiom;
import org.semanticweb.owlapi.model.OWLObjectPropertyRangeAxiom;
import org.semanticweb.owlapi.model.OWLObjectSomeValuesFrom;
import org.semanticweb.owlapi.model.OWLObjectUnionOf;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.OWLSubClassOfAxiom;
import uk.ac.manchester.cs.owlapi.modularity.ModuleType;
import uk.ac.manchester.cs.owlapi.modularity.SyntacticLocalityModuleExtractor;

/**
 * Whether the individuals named in the schema can matter to the modules outside the hub (see
 * {@link AboxLinks}, "Nominals"): every nominal read as ⊥, the ⊥-locality module of the schema
 * for the signature of those modules' assertions must hold no axiom that named an individual.
 * The symbols that module reaches are kept: an ABox change that brings in another symbol asks
 * again.
 */
final class NominalIndependence {
    private final Set<OWLEntity> reached;
    private final OWLAxiom dependent;

    private NominalIndependence(Set<OWLEntity> reached, OWLAxiom dependent) {
        this.reached = reached;
        this.dependent = dependent;
    }

    /**
     * @param schema    the logical axioms that are not assertions
     * @param signature the classes and properties of the assertions of the modules outside the hub
     */
    static NominalIndependence check(OWLOntologyManager manager, List<OWLAxiom> schema, Set<OWLEntity> signature) {
        Emptied emptied = new Emptied(manager.getOWLDataFactory());
        Map<OWLAxiom, OWLAxiom> original = new HashMap<>();
        Set<OWLAxiom> rewritten = new HashSet<>();
        for (OWLAxiom axiom : schema) {
            OWLAxiom read = axiom;
            if (axiom.individualsInSignature().findAny().isPresent()) {
                read = emptied.axiom(axiom);
                original.put(read, axiom);
            }
            rewritten.add(read);
        }
        Set<OWLAxiom> module = new SyntacticLocalityModuleExtractor(manager, rewritten.stream(), ModuleType.BOT)
                .extract(new HashSet<>(signature));
        Set<OWLEntity> reached = new HashSet<>(signature);
        OWLAxiom dependent = null;
        for (OWLAxiom axiom : module) {
            axiom.signature().forEach(reached::add);
            if (dependent == null && original.containsKey(axiom)) {
                dependent = original.get(axiom);
            }
        }
        return new NominalIndependence(Set.copyOf(reached), dependent);
    }

    /** The axiom with a nominal that the ABox's signature reaches, if one does. */
    Optional<OWLAxiom> dependent() {
        return Optional.ofNullable(dependent);
    }

    /** Axioms and class expressions with every nominal read as ⊥: {a, b} is ⊥, P value a is ∃P.⊥. */
    private record Emptied(OWLDataFactory factory) {
        OWLAxiom axiom(OWLAxiom axiom) {
            if (axiom instanceof OWLSubClassOfAxiom sub) {
                return factory.getOWLSubClassOfAxiom(of(sub.getSubClass()), of(sub.getSuperClass()));
            }
            if (axiom instanceof OWLEquivalentClassesAxiom equivalent) {
                return factory.getOWLEquivalentClassesAxiom(equivalent.classExpressions().map(this::of).toList());
            }
            if (axiom instanceof OWLDisjointClassesAxiom disjoint) {
                return factory.getOWLDisjointClassesAxiom(disjoint.classExpressions().map(this::of).toList());
            }
            if (axiom instanceof OWLDisjointUnionAxiom union) {
                return factory.getOWLDisjointUnionAxiom(union.getOWLClass(),
                        union.classExpressions().map(this::of).toList());
            }
            if (axiom instanceof OWLObjectPropertyDomainAxiom domain) {
                return factory.getOWLObjectPropertyDomainAxiom(domain.getProperty(), of(domain.getDomain()));
            }
            if (axiom instanceof OWLObjectPropertyRangeAxiom range) {
                return factory.getOWLObjectPropertyRangeAxiom(range.getProperty(), of(range.getRange()));
            }
            if (axiom instanceof OWLDataPropertyDomainAxiom domain) {
                return factory.getOWLDataPropertyDomainAxiom(domain.getProperty(), of(domain.getDomain()));
            }
            // Any other axiom naming an individual is left as it is: never local, so never independent.
            return axiom;
        }

        OWLClassExpression of(OWLClassExpression expression) {
            if (expression instanceof OWLObjectOneOf) {
                return factory.getOWLNothing();
            }
            if (expression instanceof OWLObjectHasValue hasValue) {
                return factory.getOWLObjectSomeValuesFrom(hasValue.getProperty(), factory.getOWLNothing());
            }
            if (expression instanceof OWLObjectIntersectionOf and) {
                return factory.getOWLObjectIntersectionOf(and.operands().map(this::of));
            }
            if (expression instanceof OWLObjectUnionOf or) {
                return factory.getOWLObjectUnionOf(or.operands().map(this::of));
            }
            if (expression instanceof OWLObjectComplementOf not) {
                return factory.getOWLObjectComplementOf(of(not.getOperand()));
            }
            if (expression instanceof OWLObjectSomeValuesFrom some) {
                return factory.getOWLObjectSomeValuesFrom(some.getProperty(), of(some.getFiller()));
            }
            if (expression instanceof OWLObjectAllValuesFrom all) {
                return factory.getOWLObjectAllValuesFrom(all.getProperty(), of(all.getFiller()));
            }
            if (expression instanceof OWLObjectMinCardinality min) {
                return factory.getOWLObjectMinCardinality(min.getCardinality(), min.getProperty(), of(min.getFiller()));
            }
            if (expression instanceof OWLObjectMaxCardinality max) {
                return factory.getOWLObjectMaxCardinality(max.getCardinality(), max.getProperty(), of(max.getFiller()));
            }
            if (expression instanceof OWLObjectExactCardinality exact) {
                return factory.getOWLObjectExactCardinality(exact.getCardinality(), exact.getProperty(),
                        of(exact.getFiller()));
            }
            return expression;
        }
    }

    /** Whether an assertion with this symbol keeps the answer (else the check must run again). */
    boolean covers(OWLEntity symbol) {
        return symbol.isOWLNamedIndividual() || symbol.isBuiltIn() || reached.contains(symbol);
    }
}
