// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.explanation;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.semanticweb.owl.explanation.impl.blackbox.EntailmentChecker;
import org.semanticweb.owl.explanation.impl.blackbox.EntailmentCheckerFactory;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import uk.ac.manchester.cs.owlapi.modularity.ModuleType;
import uk.ac.manchester.cs.owlapi.modularity.SyntacticLocalityModuleExtractor;

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
 */
final class RememberingEntailmentChecker implements EntailmentChecker<OWLAxiom> {
    private final EntailmentChecker<OWLAxiom> reasoner;
    private final OWLOntologyManager manager;
    private final Set<OWLEntity> signature;
    private final Memory memory;
    private Set<OWLAxiom> lastAxioms = Set.of();
    private Set<OWLAxiom> lastEntailing = Set.of();
    private int reasonerCalls;

    /** What the reasoner answered about one fact: the sets (modules) that entail it and those that do not. */
    private record Memory(List<Set<OWLAxiom>> entailing, List<Set<OWLAxiom>> notEntailing) {}

    private RememberingEntailmentChecker(EntailmentChecker<OWLAxiom> reasoner, OWLOntologyManager manager,
                                         Memory memory) {
        this.reasoner = reasoner;
        this.manager = manager;
        this.memory = memory;
        this.signature = reasoner.getEntailmentSignature();
    }

    /**
     * Checkers for {@code reasoners}' entailments that remember the reasoner's answers; the
     * library makes one for each justification it looks for, and those of one fact share what
     * they learnt. Modules are made with {@code manager}.
     */
    static EntailmentCheckerFactory<OWLAxiom> factory(EntailmentCheckerFactory<OWLAxiom> reasoners,
                                                      OWLOntologyManager manager) {
        Map<OWLAxiom, Memory> memories = new HashMap<>();
        return fact -> new RememberingEntailmentChecker(reasoners.createEntailementChecker(fact), manager,
                memories.computeIfAbsent(fact, f -> new Memory(new ArrayList<>(), new ArrayList<>())));
    }

    @Override
    public boolean isEntailed(Set<OWLAxiom> axioms) {
        lastAxioms = Set.copyOf(axioms);
        lastEntailing = Set.of();
        if (axioms.contains(reasoner.getEntailment())) {
            lastEntailing = Set.of(reasoner.getEntailment());
            return true;
        }
        Set<OWLAxiom> module = module(axioms);
        for (Set<OWLAxiom> known : memory.entailing()) {
            if (module.containsAll(known)) {
                lastEntailing = known;
                return true;
            }
        }
        for (Set<OWLAxiom> known : memory.notEntailing()) {
            if (known.containsAll(module)) {
                return false;
            }
        }
        reasonerCalls++;
        boolean entailed = reasoner.isEntailed(module);
        (entailed ? memory.entailing() : memory.notEntailing()).add(module);
        if (entailed) {
            lastEntailing = module;
        }
        return entailed;
    }

    /** A subset of {@code axioms} that entails the fact (the module, or a smaller set known to), if they do. */
    @Override
    public Set<OWLAxiom> getEntailingAxioms(Set<OWLAxiom> axioms) {
        if (!lastAxioms.equals(axioms)) {
            isEntailed(axioms);
        }
        return lastEntailing;
    }

    private Set<OWLAxiom> module(Set<OWLAxiom> axioms) {
        if (axioms.isEmpty()) {
            return Set.of();
        }
        return new SyntacticLocalityModuleExtractor(manager, axioms.stream(), ModuleType.STAR).extract(signature)
                .stream().filter(OWLAxiom::isLogicalAxiom).collect(Collectors.toUnmodifiableSet());
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
        return reasoner.getEntailment();
    }

    @Override
    public Set<OWLEntity> getEntailmentSignature() {
        return signature;
    }

    @Override
    public Set<OWLEntity> getSeedSignature() {
        return reasoner.getSeedSignature();
    }

    @Override
    public Set<OWLAxiom> getModule(Set<OWLAxiom> axioms) {
        return reasoner.getModule(axioms);
    }

    @Override
    public String getModularisationTypeDescription() {
        return reasoner.getModularisationTypeDescription();
    }

    @Override
    public boolean isUseModularisation() {
        return reasoner.isUseModularisation();
    }
}
