// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.explanation;

import java.lang.reflect.Proxy;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.semanticweb.HermiT.ReasonerFactory;
import org.semanticweb.owl.explanation.impl.blackbox.EntailmentChecker;
import org.semanticweb.owl.explanation.impl.blackbox.EntailmentCheckerFactory;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassAssertionAxiom;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owl.explanation.impl.blackbox.checker.SatisfiabilityEntailmentCheckerFactory;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.reasoner.FreshEntityPolicy;
import org.semanticweb.owlapi.reasoner.IndividualNodeSetPolicy;
import org.semanticweb.owlapi.reasoner.InconsistentOntologyException;
import org.semanticweb.owlapi.reasoner.NullReasonerProgressMonitor;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;

/**
 * Asks the reasoner only what the checks before cannot answer. The explanation library's search
 * checks one set of axioms after another (about twenty for a justification of five axioms out of
 * twelve), and each check makes a new reasoner: that was nearly all of an EXPLAIN's time. Here
 * <ul>
 *   <li>a set is first cut to the STAR module of the fact's signature in it, which entails the
 *   fact exactly when the set does (what syntactic locality guarantees), so sets that differ only
 *   in axioms that cannot matter are one check;</li>
 *   <li>by monotonicity, a set that contains one known to entail the fact entails it, and a set
 *   inside one known not to entail it does not: answered without the reasoner.</li>
 * </ul>
 * Every answer is the one the reasoner would give on the set: only the number of calls changes.
 * HermiT is asked with its own entailment check ({@link #askHermiT}).
 */
final class RememberingEntailmentChecker implements EntailmentChecker<OWLAxiom> {
    // Fresh entities allowed: a set left without an axiom may not name the fact's individual.
    private static final OWLReasonerConfiguration CHECKS = new SimpleConfiguration(new NullReasonerProgressMonitor(),
            FreshEntityPolicy.ALLOW, Long.MAX_VALUE, IndividualNodeSetPolicy.BY_SAME_AS);
    // The library's checker: the signature, the module, and the check (but HermiT's, see askHermiT).
    private final EntailmentChecker<OWLAxiom> library;
    // The library's checker again, on a reasoner that answers what this checker found.
    private final EntailmentChecker<OWLAxiom> replaying;
    private final KnownAnswer knownAnswer = new KnownAnswer();
    // What HermiT checks instead of the fact where that is one tableau (askHermiT), else null.
    private final OWLAxiom negation;
    private final OWLOntologyManager manager;
    private final Set<OWLEntity> signature;
    private final Memory memory;
    private final OWLReasonerFactory reasoners;
    private int reasonerCalls;

    /** What the reasoner answered about one fact: the sets (modules) that entail it and those that do not. */
    private record Memory(List<Set<OWLAxiom>> entailing, List<Set<OWLAxiom>> notEntailing) {}

    private RememberingEntailmentChecker(EntailmentChecker<OWLAxiom> library, OWLReasonerFactory reasoners,
                                         OWLOntologyManager manager, Memory memory) {
        this.library = library;
        this.reasoners = reasoners;
        this.manager = manager;
        this.memory = memory;
        this.signature = library.getEntailmentSignature();
        this.negation = negation(library.getEntailment(), manager.getOWLDataFactory());
        this.replaying = new SatisfiabilityEntailmentCheckerFactory(knownAnswer, () -> manager)
                .createEntailementChecker(library.getEntailment());
    }

    /**
     * Checkers of entailments by {@code reasoners}' reasoners that remember their answers; the
     * library makes one for each justification it looks for, and those of one fact share what
     * they learnt. Modules are made with {@code manager}.
     */
    static EntailmentCheckerFactory<OWLAxiom> factory(OWLReasonerFactory reasoners, OWLOntologyManager manager) {
        EntailmentCheckerFactory<OWLAxiom> library = new SatisfiabilityEntailmentCheckerFactory(reasoners,
                () -> manager);
        Map<OWLAxiom, Memory> memories = new HashMap<>();
        return fact -> new RememberingEntailmentChecker(library.createEntailementChecker(fact), reasoners, manager,
                memories.computeIfAbsent(fact, f -> new Memory(new ArrayList<>(), new ArrayList<>())));
    }

    @Override
    public boolean isEntailed(Set<OWLAxiom> axioms) {
        if (axioms.contains(library.getEntailment())) {
            return true;
        }
        // The set as it is first: monotonicity answers it as well as its module, without making one.
        Boolean known = remembered(axioms);
        if (known != null) {
            return known;
        }
        Set<OWLAxiom> module = module(axioms);
        known = remembered(module);
        if (known != null) {
            return known;
        }
        reasonerCalls++;
        boolean entailed = reasoners instanceof ReasonerFactory ? askHermiT(module) : libraryEntails(module);
        (entailed ? memory.entailing() : memory.notEntailing()).add(module);
        return entailed;
    }

    /** Whether {@code axioms} entail the fact, by the reasoner's earlier answers; null when they do not tell. */
    private Boolean remembered(Set<OWLAxiom> axioms) {
        for (Set<OWLAxiom> known : memory.entailing()) {
            if (axioms.containsAll(known)) {
                return true;
            }
        }
        for (Set<OWLAxiom> known : memory.notEntailing()) {
            if (known.containsAll(axioms)) {
                return false;
            }
        }
        return null;
    }

    /**
     * HermiT on the set alone. For an individual's class or object property value, the set with
     * the fact's negation added must be inconsistent: one tableau. HermiT's own entailment check
     * of an assertion first sets up its instance manager, a tableau over the whole set and the
     * index of known and possible instances, then tests the possible ones: two tableaux and an
     * index, on each of the dozen checks of a search. Other facts go to HermiT's own check; the
     * library's instead turns the fact into a class that must be unsatisfiable, a nominal for an
     * assertion and a second tableau. (Only HermiT: JFact's check fails on a reasoner that has
     * not classified first.)
     */
    private boolean askHermiT(Set<OWLAxiom> module) {
        OWLAxiom fact = library.getEntailment();
        Set<OWLAxiom> axioms = module;
        if (negation != null) {
            axioms = new LinkedHashSet<>(module);
            axioms.add(negation);
        }
        OWLOntology ontology;
        try {
            ontology = manager.createOntology(axioms);
        } catch (OWLOntologyCreationException e) {
            throw new IllegalStateException(e);
        }
        try {
            OWLReasoner checking = reasoners.createReasoner(ontology, CHECKS);
            try {
                if (negation != null) {
                    return !checking.isConsistent();
                }
                if (checking.isEntailmentCheckingSupported(fact.getAxiomType())) {
                    return checking.isEntailed(fact);
                }
            } catch (InconsistentOntologyException e) {
                return true;
            } finally {
                checking.dispose();
            }
        } finally {
            manager.removeOntology(ontology);
        }
        return libraryEntails(module);
    }

    /** An inconsistent set entails every fact; Openllet says so by throwing instead of answering. */
    private boolean libraryEntails(Set<OWLAxiom> module) {
        try {
            return library.isEntailed(module);
        } catch (InconsistentOntologyException e) {
            return true;
        }
    }

    /** The negation of an individual's class or object property value, as an assertion; null for other facts. */
    private static OWLAxiom negation(OWLAxiom fact, OWLDataFactory factory) {
        if (fact instanceof OWLClassAssertionAxiom type) {
            return factory.getOWLClassAssertionAxiom(factory.getOWLObjectComplementOf(type.getClassExpression()),
                    type.getIndividual());
        }
        if (fact instanceof OWLObjectPropertyAssertionAxiom value) {
            return factory.getOWLNegativeObjectPropertyAssertionAxiom(value.getProperty(), value.getSubject(),
                    value.getObject());
        }
        return null;
    }

    /**
     * The library's answer (the whole set checked, as it builds its ontology): the search's next
     * steps start from it, so which justification is found first stays the library's (a module
     * here changed it to a larger one on robotics.owl). The library's checker computes it with a
     * reasoner check of its own, once per justification searched and the dearest of all (the
     * fact as a nominal, two tableaux for HermiT); the search has just asked this checker about
     * the same set, so the library's checker is given that answer instead of a reasoner
     * ({@link KnownAnswer}) and builds its set exactly as it would have.
     */
    @Override
    public Set<OWLAxiom> getEntailingAxioms(Set<OWLAxiom> axioms) {
        knownAnswer.entailed = isEntailed(axioms);
        return replaying.getEntailingAxioms(axioms);
    }

    private Set<OWLAxiom> module(Set<OWLAxiom> axioms) {
        if (axioms.isEmpty()) {
            return Set.of();
        }
        Set<OWLAxiom> module = Modules.star(axioms, signature);
        // In the order the library gave the axioms: its search, and so the justification it finds
        // first, depends on the order, which must not change from one run to the next.
        return axioms.stream().filter(a -> a.isLogicalAxiom() && module.contains(a))
                .collect(Collectors.toCollection(LinkedHashSet::new));
    }

    /** How many checks went to the reasoner. */
    @Override
    public int getCounter() {
        return reasonerCalls;
    }

    @Override
    public void resetCounter() {
        reasonerCalls = 0;
    }

    @Override
    public OWLAxiom getEntailment() {
        return library.getEntailment();
    }

    @Override
    public Set<OWLEntity> getEntailmentSignature() {
        return signature;
    }

    @Override
    public Set<OWLEntity> getSeedSignature() {
        return library.getSeedSignature();
    }

    @Override
    public Set<OWLAxiom> getModule(Set<OWLAxiom> axioms) {
        return library.getModule(axioms);
    }

    @Override
    public String getModularisationTypeDescription() {
        return library.getModularisationTypeDescription();
    }

    @Override
    public boolean isUseModularisation() {
        return library.isUseModularisation();
    }

    /**
     * A "reasoner" that answers the one question the library's satisfiability checker asks (is
     * the fact's negation satisfiable?) with an answer found before: not entailed.
     */
    private static final class KnownAnswer implements OWLReasonerFactory {
        boolean entailed;

        @Override
        public String getReasonerName() {
            return "known answer";
        }

        @Override
        public OWLReasoner createReasoner(OWLOntology ontology, OWLReasonerConfiguration configuration) {
            boolean satisfiable = !entailed;
            return (OWLReasoner) Proxy.newProxyInstance(OWLReasoner.class.getClassLoader(),
                    new Class<?>[] {OWLReasoner.class}, (proxy, method, arguments) -> switch (method.getName()) {
                        case "isSatisfiable" -> satisfiable;
                        case "dispose" -> null;
                        default -> throw new UnsupportedOperationException(method.getName());
                    });
        }

        @Override
        public OWLReasoner createNonBufferingReasoner(OWLOntology ontology, OWLReasonerConfiguration configuration) {
            return createReasoner(ontology, configuration);
        }

        @Override
        public OWLReasoner createReasoner(OWLOntology ontology) {
            return createReasoner(ontology, CHECKS);
        }

        @Override
        public OWLReasoner createNonBufferingReasoner(OWLOntology ontology) {
            return createReasoner(ontology, CHECKS);
        }
    }
}
