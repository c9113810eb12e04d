// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.semanticweb.owlapi.change.AddAxiomData;
import org.semanticweb.owlapi.change.AxiomChangeData;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLObjectHasValue;
import org.semanticweb.owlapi.model.OWLObjectOneOf;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.util.OWLObjectTransformer;
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
        OWLDataFactory factory = manager.getOWLDataFactory();
        OWLObjectTransformer<OWLClassExpression> empty = new OWLObjectTransformer<>(
                object -> object instanceof OWLObjectOneOf || object instanceof OWLObjectHasValue,
                expression -> expression instanceof OWLObjectHasValue hasValue
                        ? factory.getOWLObjectSomeValuesFrom(hasValue.getProperty(), factory.getOWLNothing())
                        : factory.getOWLNothing(),
                factory, OWLClassExpression.class);
        Map<OWLAxiom, OWLAxiom> original = new HashMap<>();
        Set<OWLAxiom> rewritten = new HashSet<>();
        for (OWLAxiom axiom : schema) {
            OWLAxiom read = axiom;
            if (axiom.individualsInSignature().findAny().isPresent()) {
                for (AxiomChangeData change : empty.change(axiom)) {
                    if (change instanceof AddAxiomData add) {
                        read = add.getAxiom();
                    }
                }
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

    /** Whether an assertion with this symbol keeps the answer (else the check must run again). */
    boolean covers(OWLEntity symbol) {
        return symbol.isOWLNamedIndividual() || symbol.isBuiltIn() || reached.contains(symbol);
    }
}
