// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.explanation;

import io.github.armor.core.reference.ReasonerCalls;
import io.github.armor.core.reference.ReasonerRegistry;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Deque;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Function;
import java.util.function.Supplier;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.semanticweb.owl.explanation.api.Explanation;
import org.semanticweb.owl.explanation.api.ExplanationException;
import org.semanticweb.owl.explanation.api.ExplanationGenerator;
import org.semanticweb.owl.explanation.api.ExplanationGeneratorFactory;
import org.semanticweb.owl.explanation.api.ExplanationGeneratorInterruptedException;
import org.semanticweb.owl.explanation.api.NotEntailedException;
import org.semanticweb.owl.explanation.api.ExplanationProgressMonitor;
import org.semanticweb.HermiT.ReasonerFactory;
import org.semanticweb.owl.explanation.impl.blackbox.Configuration;
import org.semanticweb.owl.explanation.impl.blackbox.DivideAndConquerContractionStrategy;
import org.semanticweb.owl.explanation.impl.blackbox.EntailmentCheckerFactory;
import org.semanticweb.owl.explanation.impl.blackbox.InitialEntailmentCheckStrategy;
import org.semanticweb.owl.explanation.impl.blackbox.StructuralTypePriorityExpansionStrategy;
import org.semanticweb.owl.explanation.impl.blackbox.checker.BlackBoxExplanationGeneratorFactory;
import org.semanticweb.owl.explanation.impl.blackbox.checker.InconsistentOntologyExplanationGeneratorFactory;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLIndividualAxiom;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.OWLPrimitive;
import org.semanticweb.owlapi.model.OWLSubClassOfAxiom;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import uk.ac.manchester.cs.owlapi.modularity.ModuleType;
import uk.ac.manchester.cs.owlapi.modularity.SyntacticLocalityModuleExtractor;

/**
 * Finds justifications (minimal sets of the ontology's axioms that entail a fact) with the OWL
 * API's explanation library (owlexplanation: black-box expansion and contraction, then a hitting
 * set tree for more than one), searched first on a small part of the ontology:
 * <ul>
 *   <li>for a fact about individuals, the schema plus the assertions of the individuals the
 *   fact names, then also of their neighbours (linked by property assertions, sameAs,
 *   differentFrom), then up to 3 links away, then the whole connected part, each cut down to the
 *   syntactic locality (STAR) module of the fact's signature, until one yields a justification;</li>
 *   <li>for a subsumption, the STAR module of the two classes.</li>
 * </ul>
 * (Before these, {@link #ofToldPath} tries the told links that lead to the fact.)
 * A justification is a subset of the axioms searched that the reasoner finds entailing the fact
 * and minimal, so whatever part was searched it is one of the whole ontology's. Only when that
 * part yields none (a link this cut does not follow) is the whole ontology searched.
 *
 * <p>The search shares the directive's reasoner time limit: past it, it stops and what was found
 * is answered marked partial (never a set that was not checked).
 */
final class Justifications {
    /** The justifications found (each sorted for a stable answer) and what the search ran on. */
    record Found(List<Set<OWLAxiom>> sets, boolean partial, int searchedAxioms, int ontologyAxioms, String reasoner) {}

    // ELK answers only OWL 2 EL entailments and silently drops the rest: the checks that make a
    // justification minimal need a complete reasoner, so an ELK reference is explained by HermiT.
    private static final String FALLBACK_REASONER = "HERMIT";
    private static final int UNBOUNDED = Integer.MAX_VALUE;
    // Links from the fact's individuals whose assertions are searched, in turn.
    private static final int[] RADII = {1, 2, 4, UNBOUNDED};

    private Justifications() {}

    /** The reasoner the explanations of a reference with this reasoner are computed with. */
    static String explainingReasoner(String referenceReasoner) {
        return "ELK".equals(referenceReasoner) ? FALLBACK_REASONER : referenceReasoner;
    }

    /**
     * Up to {@code limit} justifications of {@code fact} in {@code ontology}, by {@code deadlineNanos}.
     * {@code individuals} are the individuals the fact is about (none for a subsumption).
     */
    static Found of(OWLOntology ontology, OWLAxiom fact, Set<OWLNamedIndividual> individuals, int limit,
                    String reasonerName, long deadlineNanos) {
        Search search = new Search(reasonerName, limit, deadlineNanos,
                ontology.getLogicalAxiomCount(Imports.INCLUDED));
        Set<OWLAxiom> schema = schemaAxioms(ontology);
        // Near the fact first: most facts follow from the assertions of their individuals and of
        // their neighbours; a robot's map is one connected ABox, whose module is nearly all of it.
        Found found = null;
        int searched = -1;
        for (int radius : individuals.isEmpty() ? new int[] {UNBOUNDED} : RADII) {
            Set<OWLAxiom> module = module(search.manager, fact, schema,
                    connectedAssertions(ontology, individuals, radius));
            if (module.size() == searched) {
                continue; // the part did not grow: nothing new to search
            }
            searched = module.size();
            found = search.run(fact, module, false);
            if (!found.sets().isEmpty() || found.partial()) {
                return found;
            }
        }
        if (searched < search.ontologySize) {
            found = search.run(fact, logicalAxioms(ontology), false);
        }
        return found;
    }

    /**
     * Up to {@code limit} justifications of a fact among the told links that lead to it: for a
     * subsumption between named classes, the told hierarchy between them
     * ({@link #toldHierarchyBetween}); for {@code subject p object} with p transitive, the chain
     * of p's assertions between them ({@link #transitiveChainBetween}). Null when there is no such
     * path or none of it entails the fact. Over a large upper ontology the STAR module of two
     * classes is hundreds of axioms that take the library minutes, a part-of tree is one connected
     * ABox whose module grows with the tree, and the reference's reasoner may classify or realise
     * everything to say the fact holds; a justification found on the path proves it holds.
     */
    static Found ofToldPath(OWLOntology ontology, OWLAxiom fact, int limit, String reasonerName, long deadlineNanos) {
        Set<OWLAxiom> told = fact instanceof OWLSubClassOfAxiom subsumption
                ? toldHierarchyBetween(ontology, subsumption)
                : fact instanceof OWLObjectPropertyAssertionAxiom assertion
                ? transitiveChainBetween(ontology, assertion) : Set.of();
        if (told.isEmpty()) {
            return null;
        }
        Found found = new Search(reasonerName, limit, deadlineNanos, ontology.getLogicalAxiomCount(Imports.INCLUDED))
                .run(fact, told, false);
        return found.sets().isEmpty() ? null : found;
    }

    /** Up to {@code limit} sets of axioms that make {@code ontology} inconsistent. */
    static Found ofInconsistency(OWLOntology ontology, int limit, String reasonerName, long deadlineNanos) {
        Set<OWLAxiom> all = logicalAxioms(ontology);
        OWLDataFactory factory = ontology.getOWLOntologyManager().getOWLDataFactory();
        OWLAxiom contradiction = factory.getOWLSubClassOfAxiom(factory.getOWLThing(), factory.getOWLNothing());
        return new Search(reasonerName, limit, deadlineNanos, all.size()).run(contradiction, all, true);
    }

    private static Set<OWLAxiom> logicalAxioms(OWLOntology ontology) {
        return ontology.logicalAxioms(Imports.INCLUDED).map(a -> (OWLAxiom) a.getAxiomWithoutAnnotations())
                .collect(Collectors.toCollection(LinkedHashSet::new));
    }

    /**
     * The SubClassOf and EquivalentClasses axioms between named classes that lie on some path of
     * such links from the fact's subclass to its superclass: empty when either is not named or
     * no such path exists.
     */
    private static Set<OWLAxiom> toldHierarchyBetween(OWLOntology ontology, OWLSubClassOfAxiom fact) {
        if (fact.getSubClass().isAnonymous() || fact.getSuperClass().isAnonymous()) {
            return Set.of();
        }
        return axiomsOnPaths(fact.getSubClass().asOWLClass(), fact.getSuperClass().asOWLClass(),
                current -> ontology.importsClosure().flatMap(part -> Stream.concat(
                        part.subClassAxiomsForSubClass(current).filter(a -> !a.getSuperClass().isAnonymous())
                                .map(a -> Map.entry(a.getSuperClass().asOWLClass(), (OWLAxiom) a)),
                        part.equivalentClassesAxioms(current).flatMap(a -> a.namedClasses()
                                .filter(c -> !c.equals(current)).map(c -> Map.entry(c, (OWLAxiom) a))))));
    }

    /**
     * For {@code subject p object} with p transitive: the assertions of p on some path from the
     * subject to the object, with p's TransitiveObjectProperty axiom; empty otherwise. A part-of
     * tree is one connected ABox whose module around the two individuals grows with the tree
     * (3,647 axioms for a room of the building at 100,000 individuals).
     */
    private static Set<OWLAxiom> transitiveChainBetween(OWLOntology ontology, OWLObjectPropertyAssertionAxiom fact) {
        if (fact.getProperty().isAnonymous() || fact.getSubject().isAnonymous() || fact.getObject().isAnonymous()) {
            return Set.of();
        }
        OWLObjectProperty property = fact.getProperty().asOWLObjectProperty();
        List<OWLAxiom> transitive = ontology.importsClosure().flatMap(part -> part.transitiveObjectPropertyAxioms(
                property)).map(a -> (OWLAxiom) a.getAxiomWithoutAnnotations()).toList();
        if (transitive.isEmpty()) {
            return Set.of();
        }
        Set<OWLAxiom> chain = axiomsOnPaths(fact.getSubject(), fact.getObject(),
                current -> ontology.importsClosure().flatMap(part -> part.objectPropertyAssertionAxioms(current))
                        .filter(a -> a.getProperty().equals(property) && a.getObject().isNamed())
                        .map(a -> Map.entry(a.getObject(), (OWLAxiom) a)));
        if (!chain.isEmpty()) {
            chain.add(transitive.get(0));
        }
        return chain;
    }

    /**
     * The axioms of the links, from {@code links} (each to the next node and the axiom that
     * makes it), on some path from {@code start} to {@code goal}; empty when none reaches it.
     */
    private static <N> Set<OWLAxiom> axiomsOnPaths(N start, N goal, Function<N, Stream<Map.Entry<N, OWLAxiom>>> links) {
        Map<N, List<Map.Entry<N, OWLAxiom>>> from = new HashMap<>();
        Set<N> reached = new LinkedHashSet<>(List.of(start));
        Deque<N> queue = new ArrayDeque<>(reached);
        while (!queue.isEmpty()) {
            N current = queue.poll();
            links.apply(current).forEach(link -> {
                from.computeIfAbsent(current, n -> new ArrayList<>()).add(link);
                if (reached.add(link.getKey())) {
                    queue.add(link.getKey());
                }
            });
        }
        if (start.equals(goal) || !reached.contains(goal)) {
            return new LinkedHashSet<>();
        }
        // Back from the goal along the links found: the nodes that lead to it.
        Map<N, List<Map.Entry<N, OWLAxiom>>> into = new HashMap<>();
        from.forEach((node, out) -> out.forEach(link -> into.computeIfAbsent(link.getKey(),
                n -> new ArrayList<>()).add(Map.entry(node, link.getValue()))));
        Set<OWLAxiom> onPaths = new LinkedHashSet<>();
        Set<N> leading = new LinkedHashSet<>(List.of(goal));
        Deque<N> back = new ArrayDeque<>(leading);
        while (!back.isEmpty()) {
            for (Map.Entry<N, OWLAxiom> link : into.getOrDefault(back.poll(), List.of())) {
                onPaths.add(link.getValue().getAxiomWithoutAnnotations());
                if (leading.add(link.getKey())) {
                    back.add(link.getKey());
                }
            }
        }
        return onPaths;
    }

    /**
     * The logical axioms that are not assertions (classes, properties, rules), read through the
     * ontology's index of each axiom type: a scan of every axiom cost more than the search itself
     * on a large ABox.
     */
    private static Set<OWLAxiom> schemaAxioms(OWLOntology ontology) {
        Set<OWLAxiom> schema = new LinkedHashSet<>();
        AxiomType.AXIOM_TYPES.stream().filter(type -> type.isLogical() && !AxiomType.ABoxAxiomTypes.contains(type))
                .forEach(type -> ontology.axioms(type, Imports.INCLUDED)
                        .forEach(axiom -> schema.add(axiom.getAxiomWithoutAnnotations())));
        return schema;
    }

    /**
     * The part of the ontology searched first: the schema and some assertions, cut down to the
     * STAR module of the fact's signature in them.
     */
    private static Set<OWLAxiom> module(OWLOntologyManager manager, OWLAxiom fact, Set<OWLAxiom> schema,
                                        Set<OWLAxiom> assertions) {
        Set<OWLAxiom> candidates = new LinkedHashSet<>(schema);
        candidates.addAll(assertions);
        Set<OWLEntity> signature = fact.signature().collect(Collectors.toSet());
        SyntacticLocalityModuleExtractor extractor = new SyntacticLocalityModuleExtractor(manager,
                candidates.stream(), ModuleType.STAR);
        return extractor.extract(signature).stream().filter(OWLAxiom::isLogicalAxiom)
                .collect(Collectors.toCollection(LinkedHashSet::new));
    }

    /**
     * The assertions about the individuals at most {@code radius - 1} links from {@code start}
     * (links: assertions between individuals), so {@code radius} links reach their neighbours.
     */
    private static Set<OWLAxiom> connectedAssertions(OWLOntology ontology, Set<OWLNamedIndividual> start,
                                                     int radius) {
        Set<OWLAxiom> assertions = new LinkedHashSet<>();
        Map<OWLIndividual, Integer> distance = new HashMap<>();
        start.forEach(i -> distance.put(i, 0));
        Deque<OWLIndividual> queue = new ArrayDeque<>(start);
        while (!queue.isEmpty()) {
            OWLIndividual individual = queue.poll();
            int next = distance.get(individual) + 1;
            if (next > radius) {
                continue;
            }
            ontology.referencingAxioms((OWLPrimitive) individual, Imports.INCLUDED)
                    .filter(a -> a.isOfType(AxiomType.ABoxAxiomTypes))
                    .forEach(axiom -> {
                        if (!assertions.add(axiom.getAxiomWithoutAnnotations())) {
                            return;
                        }
                        if (axiom instanceof OWLIndividualAxiom || axiom.isOfType(AxiomType.OBJECT_PROPERTY_ASSERTION,
                                AxiomType.NEGATIVE_OBJECT_PROPERTY_ASSERTION)) {
                            axiom.individualsInSignature().filter(i -> distance.putIfAbsent(i, next) == null)
                                    .forEach(queue::add);
                        }
                    });
        }
        return assertions;
    }

    /**
     * One EXPLAIN's searches: they share the deadline and one ontology manager, which the
     * library would otherwise make anew for every entailment check and module.
     */
    private static final class Search {
        final OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        final int ontologySize;
        private final OWLReasonerFactory factory;
        private final int limit;
        private final long deadlineNanos;
        private final String reasoner;

        /** A search for a reference reasoned on by {@code referenceReasoner}, with {@link #explainingReasoner}'s. */
        Search(String referenceReasoner, int limit, long deadlineNanos, int ontologySize) {
            this.reasoner = explainingReasoner(referenceReasoner);
            this.factory = ReasonerRegistry.factory(reasoner);
            this.limit = limit;
            this.deadlineNanos = deadlineNanos;
            this.ontologySize = ontologySize;
        }

        Found run(OWLAxiom fact, Set<OWLAxiom> axioms, boolean inconsistency) {
            List<Explanation<OWLAxiom>> found = new CopyOnWriteArrayList<>();
            ExplanationProgressMonitor<OWLAxiom> monitor = new ExplanationProgressMonitor<>() {
                @Override
                public void foundExplanation(ExplanationGenerator<OWLAxiom> generator,
                                             Explanation<OWLAxiom> explanation, Set<Explanation<OWLAxiom>> all) {
                    found.add(explanation);
                }

                @Override
                public boolean isCancelled() {
                    return System.nanoTime() > deadlineNanos || Thread.currentThread().isInterrupted();
                }
            };
            Supplier<OWLOntologyManager> managers = () -> manager;
            long leftMs = Math.max(1, (deadlineNanos - System.nanoTime()) / 1_000_000);
            ExplanationGeneratorFactory<OWLAxiom> generators;
            if (inconsistency) {
                generators = new InconsistentOntologyExplanationGeneratorFactory(factory,
                        manager.getOWLDataFactory(), managers, leftMs);
            } else {
                EntailmentCheckerFactory<OWLAxiom> checks = RememberingEntailmentChecker.factory(
                        factory.getClass() == ReasonerFactory.class ? new UntimedHermiT() : factory, manager);
                // PERFORM: a part of the ontology that does not entail the fact answers none (and
                // the whole is searched) instead of a wrong set. The library's shorter
                // constructors leave this strategy unset (owlexplanation 5.0.0).
                generators = new BlackBoxExplanationGeneratorFactory<>(new Configuration<>(checks,
                        new StructuralTypePriorityExpansionStrategy<>(InitialEntailmentCheckStrategy.PERFORM, managers),
                        new DivideAndConquerContractionStrategy<>(), monitor, managers));
            }
            boolean partial = false;
            Set<Explanation<OWLAxiom>> complete = Set.of();
            try {
                complete = ReasonerCalls.run(null, deadlineNanos, () -> {
                    try {
                        return generators.createExplanationGenerator(axioms, monitor).getExplanations(fact, limit);
                    } catch (ExplanationGeneratorInterruptedException e) {
                        throw new SearchStopped(e);
                    } catch (NotEntailedException e) {
                        return Set.<Explanation<OWLAxiom>>of();
                    } catch (ExplanationException e) {
                        throw new IllegalStateException("the explanation library failed: " + e.getMessage(), e);
                    }
                });
            } catch (ReasonerCalls.Overran | SearchStopped e) {
                partial = true;
            }
            if (!partial && monitor.isCancelled()) {
                partial = complete.size() < limit;
            }
            Set<Set<OWLAxiom>> sets = new LinkedHashSet<>();
            for (Explanation<OWLAxiom> explanation : partial ? found : complete) {
                if (!explanation.isEmpty() && sets.size() < limit) {
                    sets.add(Set.copyOf(explanation.getAxioms()));
                }
            }
            List<Set<OWLAxiom>> ordered = new ArrayList<>(sets);
            ordered.sort(Comparator.<Set<OWLAxiom>>comparingInt(Set::size).thenComparing(s -> s.stream()
                    .map(Object::toString).sorted().collect(Collectors.joining("\n"))));
            return new Found(ordered, partial, axioms.size(), ontologySize, reasoner);
        }
    }

    /** The explanation library gave up (interrupted at the deadline): what was found so far stands. */
    private static final class SearchStopped extends RuntimeException {
        SearchStopped(Throwable cause) {
            super(cause);
        }
    }
}
