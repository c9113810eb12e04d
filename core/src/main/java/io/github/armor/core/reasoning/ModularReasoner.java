// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.AboxModules.Module;
import io.github.armor.core.reasoning.AboxModules.Repartition;
import io.github.armor.core.reasoning.ModuleRealiser.Realised;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLDataPropertyExpression;
import org.semanticweb.owlapi.model.OWLDeclarationAxiom;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObjectPropertyExpression;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyChangeListener;
import org.semanticweb.owlapi.model.SWRLRule;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.BufferingMode;
import org.semanticweb.owlapi.reasoner.FreshEntityPolicy;
import org.semanticweb.owlapi.reasoner.IndividualNodeSetPolicy;
import org.semanticweb.owlapi.reasoner.InconsistentOntologyException;
import org.semanticweb.owlapi.reasoner.InferenceType;
import org.semanticweb.owlapi.reasoner.Node;
import org.semanticweb.owlapi.reasoner.NodeSet;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.OWLReasonerConfiguration;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.reasoner.ReasonerInterruptedException;
import org.semanticweb.owlapi.reasoner.TimeOutException;
import org.semanticweb.owlapi.reasoner.impl.OWLNamedIndividualNode;
import org.semanticweb.owlapi.reasoner.impl.OWLNamedIndividualNodeSet;
import org.semanticweb.owlapi.util.Version;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A complete OWL 2 DL reasoner (HermiT, Openllet or JFact underneath) that keeps the types of
 * every individual up to date by reasoning, after an ABox change, only on the modules the change
 * touched ({@link AboxModules}, {@link AboxLinks}), each in a fresh reasoner of the chosen kind.
 * A robot that moves changes two small modules, whatever the size of the map.
 *
 * <p>Answers: consistency, {@link #getTypes} and {@link #getInstances} (not direct) of named classes come from
 * the kept types ({@link InferredState}); they equal the underlying reasoner's on the whole
 * ontology (the randomised equivalence test checks that, change sequence after change sequence).
 * Every other question (direct instances too: reasoners disagree on their
 * meaning for owl:Thing) goes to a reasoner of the same kind on the whole ontology, created on the
 * first such question and brought up to date only when asked again after a change. Instances come
 * one individual per node (ARMOR only ever reads their union).
 *
 * <p>When the ontology cannot be split ({@link AboxLinks#obstacle()}), or the underlying reasoner
 * fails on a module, this reasoner is a plain wrapper of the whole-ontology reasoner and
 * {@link #handlesRemovals()} says so; a schema change is followed by reasoning on every module
 * again.
 *
 * <p>Buffering: changes are seen at {@link #flush()}, as with any buffering reasoner; it is made
 * for a reference that flushes after every change (non-buffered reasoner), and a question asked
 * with changes not flushed yet flushes them first. Thread use: one writer at a time, as any
 * reasoner; {@link #state()} may be read from any thread.
 */
public final class ModularReasoner implements OWLReasoner {
    private static final Logger LOG = LoggerFactory.getLogger(ModularReasoner.class);
    private static final Set<String> UNDERLYING = Set.of("HERMIT", "PELLET", "OPENLLET", "JFACT");

    private enum Mode { NOT_REASONED, MODULAR, WHOLE }

    private final OWLOntology ontology;
    private final OWLReasonerFactory factory;
    private final OWLReasonerConfiguration configuration;
    private final String underlyingName;
    private final List<OWLOntologyChange> pending = new ArrayList<>();
    private final OWLOntologyChangeListener listener = this::changed;

    private Mode mode = Mode.NOT_REASONED;
    private String wholeBecause = "";
    private AboxLinks links;
    // Null without nominals in the schema; else what the ABox's signature reaches of the schema.
    private NominalIndependence nominalIndependence;
    private volatile ReasoningPlan plan = ReasoningPlan.NOT_YET;
    private LastUpdate lastUpdate;
    private AboxModules modules;
    /** Set by dispose: a call abandoned at a time limit that finishes later must not build a reasoner again. */
    private volatile boolean disposed;
    private ModuleRealiser realiser;
    private boolean schemaConsistent;
    // With SWRL rules: the engine, the types without its conclusions (what rules read), and the
    // modules inconsistent once the conclusions are added. Without rules the base state is the state.
    private RuleEngine rules;
    private InferredState baseState;
    private final Set<Module> inconsistentWithConclusions =
            java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
    private volatile InferredState state;
    private Set<OWLOntology> closure;

    private OWLReasoner whole;
    private boolean wholeBehind;
    private boolean wholeMissedRemoval;

    // The schema's class hierarchy, classified once and kept while the schema stays the same.
    private volatile Classifications.Job classification;
    private volatile boolean hierarchyCovers;
    private volatile boolean classifiedHere;
    // The classification the log has told about: once, not at every question that waits for it.
    private Classifications.Job announced;
    private volatile boolean stopWaiting;
    // The classes realised with every change, and those clients asked about (RealisationScope).
    private RealisationScope scope;
    private final Set<OWLClass> asked = new HashSet<>();
    // Over an upper ontology: every type of one module, found when asked.
    private ModuleRealiser everyType;

    /** Whether ARMOR reasons on modules with this reasoner (a complete one, known by name). */
    public static boolean handles(String reasonerName) {
        return UNDERLYING.contains(reasonerName.toUpperCase(Locale.ROOT));
    }

    public ModularReasoner(String reasonerName, OWLReasonerFactory factory, OWLOntology ontology,
                           OWLReasonerConfiguration configuration) {
        this.underlyingName = reasonerName;
        this.factory = factory;
        this.ontology = ontology;
        this.configuration = configuration;
        this.closure = ontology.importsClosure().collect(Collectors.toSet());
        ontology.getOWLOntologyManager().addOntologyChangeListener(listener);
    }

    /**
     * Whether removals are handled here (modules): a reference then keeps this reasoner instead
     * of replacing it after a removal, as it must for reasoners that keep removed inferences.
     */
    public boolean handlesRemovals() {
        return mode != Mode.WHOLE;
    }

    /**
     * What the last flush reasoned on (for tests): everything, or the remade modules' individuals,
     * out of how many, with how many modules after it.
     */
    record LastUpdate(boolean everything, int remade, int individuals, int modules) {}

    LastUpdate lastUpdate() {
        return lastUpdate;
    }

    /** The properties whose assertions tie modules (for tests); empty when not modular. */
    Set<org.semanticweb.owlapi.model.OWLObjectProperty> linkingProperties() {
        AboxLinks now = links;
        return now == null ? Set.of() : now.linking();
    }

    /** How many modules took an earlier module's result since the last schema change (for tests). */
    long reusedShapes() {
        ModuleRealiser current = realiser;
        return current == null ? 0 : current.reusedShapes();
    }

    /** Why the ontology is reasoned on as a whole, or empty when it is reasoned on in modules. */
    public String wholeBecause() {
        return wholeBecause;
    }

    /** How the ontology is reasoned on now (modules or whole, and why); safe to read from any thread. */
    public ReasoningPlan plan() {
        return plan;
    }

    /**
     * The schema's kept class hierarchy (classified once per schema), or null before the first
     * reasoning and when the schema is inconsistent. Safe to read from any thread.
     */
    public ClassifiedSchema classifiedSchema() {
        Classifications.Job job = classification;
        return job == null || !hierarchyCovers ? null : job.now();
    }

    /** Since when the schema's classification runs in the background (System.nanoTime), or -1 when it does not. */
    public long classifyingSince() {
        Classifications.Job job = classification;
        return job != null && job.running() ? job.startedNanos : -1;
    }

    /** Whether the kept hierarchy was classified here, not taken from an earlier classification of the schema. */
    public boolean classifiedHere() {
        return classifiedHere;
    }

    /**
     * The types as of the last flush, for readers on other threads; null until the first
     * reasoning, and whenever the ontology is reasoned on as a whole.
     */
    public InferredState state() {
        return state;
    }

    private void changed(List<? extends OWLOntologyChange> changes) {
        for (OWLOntologyChange change : changes) {
            if (closure.contains(change.getOntology())) {
                pending.add(change);
                wholeMissedRemoval |= change.isRemoveAxiom();
            }
        }
    }

    @Override
    public void flush() {
        List<OWLOntologyChange> changes = List.copyOf(pending);
        pending.clear();
        switch (mode) {
            case WHOLE -> {
                keepHierarchyUpToDate(changes);
                whole.flush();
            }
            case NOT_REASONED -> reasonOnModules();
            case MODULAR -> {
                wholeBehind = true;
                guarded(() -> update(changes));
            }
        }
    }

    /** Every module reasoned on from the ontology as it is: at the first question, and after a schema change. */
    private void reasonOnModules() {
        pending.clear();
        closure = ontology.importsClosure().collect(Collectors.toSet());
        scope = RealisationScope.of(ontology, asked);
        classify();
        AboxLinks found = AboxLinks.of(linkShapingAxioms());
        if (found.obstacle().isPresent()) {
            reasonOnWhole(found.obstacle().get());
            return;
        }
        RuleEngine engine = null;
        List<SWRLRule> swrl = ontology.axioms(AxiomType.SWRL_RULE, Imports.INCLUDED).toList();
        if (!swrl.isEmpty()) {
            if (underlyingName.equalsIgnoreCase("JFACT")) {
                reasonOnWhole("SWRL rules (JFact does not evaluate them; PELLET and HERMIT references do)");
                return;
            }
            RuleProgram.Compiled compiled = RuleProgram.compile(logicalSchemaAxioms().toList(), swrl,
                    Stream.concat(ontology.axioms(AxiomType.SAME_INDIVIDUAL, Imports.INCLUDED),
                            ontology.axioms(AxiomType.CLASS_ASSERTION, Imports.INCLUDED)
                                    .filter(AboxLinks::shapesLinks)).map(OWLAxiom.class::cast).toList(), found);
            if (compiled.obstacle() != null) {
                reasonOnWhole(compiled.obstacle());
                return;
            }
            engine = new RuleEngine(compiled.program(), ontology.getOWLOntologyManager().getOWLDataFactory());
        }
        RuleEngine ruleEngine = engine;
        mode = Mode.MODULAR;
        wholeBehind = true;
        guarded(() -> {
            long start = System.nanoTime();
            rules = ruleEngine;
            inconsistentWithConclusions.clear();
            links = found;
            List<OWLAxiom> schema = schemaAxioms();
            realiser = new ModuleRealiser(factory, configuration, schema,
                    scope.everyClass() ? null : scope.tracked(), !scope.everyClass());
            everyType = scope.everyClass() ? null : new ModuleRealiser(factory, configuration, schema, null, true);
            modules = new AboxModules(ontology, links);
            List<Module> all = modules.partitionAll();
            if (!nominalsIndependent()) {
                return;
            }
            ClassifiedSchema kept = classification.now();
            schemaConsistent = kept != null ? kept.consistent() : realiser.schemaConsistent();
            InferredState.Editor next = InferredState.empty(scope).edit()
                    .classes(ontology.classesInSignature(Imports.INCLUDED).collect(Collectors.toSet()));
            record(all, schemaConsistent ? realiser.realise(all, modules::axiomsOf) : List.of(), next);
            baseState = next.consistent(schemaConsistent && !modules.anyInconsistent()).done();
            state = baseState;
            if (rules != null) {
                InferredState base = baseState;
                rules.load(ontology, owlClass -> base.instances(owlClass));
                if (!withConclusions(base.individualsList(), List.of())) {
                    return;
                }
            }
            lastUpdate = new LastUpdate(true, state.individuals(), state.individuals(), modules.count());
            plan = ReasoningPlan.modules(all.size(), all.stream().mapToInt(m -> m.members.size()).max().orElse(0),
                    all.stream().filter(m -> m.hub).mapToInt(m -> m.members.size()).sum());
            LOG.debug("{} individuals in {} modules reasoned on with {} ({} took the result of a module alike)"
                    + " in {} ms", state.individuals(), all.size(), underlyingName, realiser.reusedShapes(),
                    (System.nanoTime() - start) / 1_000_000);
        });
    }

    /** After ABox changes: the touched modules again; after a schema change: everything again. */
    private void update(List<OWLOntologyChange> changes) {
        Set<OWLIndividual> touched = new LinkedHashSet<>();
        Set<OWLClass> classes = new HashSet<>();
        boolean schemaChanged = false;
        boolean linksMayChange = false;
        List<OWLAxiom> added = new ArrayList<>();
        List<OWLAxiom> removed = new ArrayList<>();
        for (OWLOntologyChange change : changes) {
            if (change.isImportChange()) {
                schemaChanged = true;
            }
            if (!change.isAxiomChange()) {
                continue;
            }
            OWLAxiom axiom = change.getAxiom();
            axiom.classesInSignature().forEach(classes::add);
            if (axiom.isOfType(AxiomType.ABoxAxiomTypes)) {
                hierarchyCovers &= !ClassifiedSchema.escapes(classification.input, axiom);
                AboxLinks.individualsOf(axiom).forEach(touched::add);
                linksMayChange |= AboxLinks.shapesLinks(axiom);
                // With rules: sameness can make the schema unfit for them, and a rule may read difference.
                schemaChanged |= rules != null && (axiom.isOfType(AxiomType.SAME_INDIVIDUAL)
                        || AboxLinks.shapesLinks(axiom)
                        || rules.readsDifference() && axiom.isOfType(AxiomType.DIFFERENT_INDIVIDUALS));
                (change.isAddAxiom() ? added : removed).add(axiom);
            } else if (axiom instanceof OWLDeclarationAxiom declaration) {
                if (declaration.getEntity().isOWLNamedIndividual()) {
                    touched.add(declaration.getEntity().asOWLNamedIndividual());
                }
            } else if (axiom.isLogicalAxiom()) {
                schemaChanged = true;
            }
        }
        if (schemaChanged || linksMayChange && !AboxLinks.of(linkShapingAxioms()).equals(links)) {
            mode = Mode.NOT_REASONED;
            reasonOnModules();
            return;
        }
        if (touched.isEmpty() && classes.isEmpty()) {
            return;
        }
        realiser.prepare();
        Repartition repartition = modules.repartition(touched);
        if (nominalIndependence != null && !coveredByNominalCheck(repartition.made()) && !nominalsIndependent()) {
            return;
        }
        InferredState.Editor next = baseState.edit();
        repartition.gone().stream().filter(OWLIndividual::isNamed)
                .forEach(gone -> next.remove(gone.asOWLNamedIndividual()));
        record(repartition.made(), schemaConsistent
                ? realiser.realise(repartition.made(), modules::axiomsOf) : List.of(), next);
        Set<OWLClass> signature = new HashSet<>(next.classes());
        boolean signatureChanged = false;
        for (OWLClass owlClass : classes) {
            boolean present = ontology.containsEntityInSignature(owlClass, Imports.INCLUDED);
            signatureChanged |= present ? signature.add(owlClass) : signature.remove(owlClass);
        }
        if (signatureChanged) {
            next.classes(signature);
        }
        baseState = next.consistent(schemaConsistent && !modules.anyInconsistent()).done();
        if (rules == null) {
            state = baseState;
        } else if (!withRules(added, removed, repartition)) {
            return;
        }
        lastUpdate = new LastUpdate(false, repartition.made().stream().mapToInt(m -> m.members.size()).sum(),
                state.individuals(), modules.count());
        ReasoningPlan before = plan;
        plan = ReasoningPlan.modules(modules.count(), Math.max(before.largest(), repartition.made().stream()
                .mapToInt(m -> m.members.size()).max().orElse(0)), repartition.made().stream().filter(m -> m.hub)
                .mapToInt(m -> m.members.size()).findAny().orElse(before.hub()));
    }

    /**
     * The rules after an ABox change: the engine takes the asserted edges and values that came
     * and went and the new body-class types of the remade modules' members; the modules whose
     * conclusions changed are reasoned on again with them. False when the ontology went whole.
     */
    private boolean withRules(List<OWLAxiom> added, List<OWLAxiom> removed, Repartition repartition) {
        Map<OWLNamedIndividual, Set<OWLClass>> retyped = new HashMap<>();
        for (Module module : repartition.made()) {
            module.namedMembers().forEach(member -> retyped.put(member, bodyClassesOf(member)));
        }
        repartition.gone().stream().filter(OWLIndividual::isNamed)
                .forEach(gone -> retyped.put(gone.asOWLNamedIndividual(), Set.of()));
        Set<RuleEngine.Fact> changed = rules.update(added, removed, retyped);
        Set<OWLNamedIndividual> affected = new LinkedHashSet<>(retyped.keySet());
        for (RuleEngine.Fact fact : changed) {
            affected.add(fact.subject());
            if (fact.object() instanceof OWLNamedIndividual object) {
                affected.add(object);
            }
        }
        return withConclusions(affected, repartition.dropped());
    }

    private Set<OWLClass> bodyClassesOf(OWLNamedIndividual individual) {
        Set<OWLClass> classes = new HashSet<>();
        baseState.types(individual).ifPresent(profile -> {
            for (OWLClass owlClass : rules.bodyClasses()) {
                if (profile.has(owlClass, false)) {
                    classes.add(owlClass);
                }
            }
        });
        return classes;
    }

    /**
     * The state with the rules' conclusions: the modules of the affected individuals take their
     * types without conclusions, or, when the rules concluded something about a member, are
     * reasoned on with those conclusions. A conclusion must not change a type a rule reads
     * ({@link RuleProgram}, why rules read the types without conclusions); if one does, or the
     * engine met a pair it cannot decide, the whole ontology is reasoned on. False then.
     */
    private boolean withConclusions(Collection<OWLNamedIndividual> affected, List<Module> dropped) {
        if (rules.obstacle() != null) {
            reasonOnWhole(rules.obstacle());
            return false;
        }
        dropped.forEach(inconsistentWithConclusions::remove);
        InferredState.Editor next = state.edit().classes(baseState.edit().classes());
        Set<Module> seen = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
        List<Module> withConclusions = new ArrayList<>();
        for (OWLNamedIndividual individual : affected) {
            Module module = modules.moduleOf(individual);
            if (module == null) {
                next.remove(individual);
                continue;
            }
            if (!seen.add(module)) {
                continue;
            }
            inconsistentWithConclusions.remove(module);
            if (schemaConsistent && module.consistent && module.namedMembers().anyMatch(rules::concludedAbout)) {
                withConclusions.add(module);
            } else {
                module.namedMembers().forEach(member -> next.put(member, baseState.types(member).orElse(null)));
            }
        }
        for (Realised outcome : realiser.realise(withConclusions, module -> {
            Set<OWLAxiom> axioms = new LinkedHashSet<>(modules.axiomsOf(module));
            module.namedMembers().forEach(member -> axioms.addAll(rules.conclusionsAbout(member, module.members)));
            return axioms;
        })) {
            if (!outcome.consistent()) {
                inconsistentWithConclusions.add(outcome.module());
                outcome.module().namedMembers().forEach(member -> next.put(member, null));
                continue;
            }
            for (Map.Entry<OWLNamedIndividual, TypeProfile> entry : outcome.types().entrySet()) {
                Set<OWLClass> before = bodyClassesOf(entry.getKey());
                for (OWLClass owlClass : rules.bodyClasses()) {
                    if (entry.getValue().has(owlClass, false) && !before.contains(owlClass)) {
                        reasonOnWhole("a SWRL rule's conclusion makes " + entry.getKey().getIRI().getShortForm()
                                + " a " + owlClass.getIRI().getShortForm() + ", which a rule reads (rules that"
                                + " chain through classes)");
                        return false;
                    }
                }
                next.put(entry.getKey(), entry.getValue());
            }
        }
        state = next.consistent(baseState.consistent() && inconsistentWithConclusions.isEmpty()).done();
        return true;
    }

    /**
     * With nominals in the schema: whether the modules outside the hub cannot reach them
     * ({@link AboxLinks}, "Nominals"); if they can, the ontology is reasoned on whole.
     */
    private boolean nominalsIndependent() {
        nominalIndependence = null;
        if (links.nominals().isEmpty()) {
            return true;
        }
        if (underlyingName.equalsIgnoreCase("JFACT")) {
            // Seen in the equivalence test: JFact left the schema's individuals out of a module's answers.
            reasonOnWhole("individuals named in the schema (JFact answers them differently in modules)");
            return false;
        }
        // A scratch manager: the extractor makes an ontology in it, which the reference's would keep (and refuse twice).
        NominalIndependence found = NominalIndependence.check(
                org.semanticweb.owlapi.apibinding.OWLManager.createOWLOntologyManager(),
                logicalSchemaAxioms().toList(), modules.signatureOutsideHub());
        if (found.dependent().isPresent()) {
            reasonOnWhole("individuals named in the schema that the ABox can reach (" + found.dependent().get() + ")");
            return false;
        }
        nominalIndependence = found;
        return true;
    }

    /** Whether the assertions of the remade modules outside the hub use only symbols the nominal check covered. */
    private boolean coveredByNominalCheck(List<Module> made) {
        return made.stream().filter(module -> !module.hub).allMatch(module -> modules.axiomsOf(module).stream()
                .allMatch(axiom -> axiom.signature().allMatch(nominalIndependence::covers)));
    }

    /** The realised types into the next state; without realisation (inconsistent schema) types are unknown. */
    private void record(List<Module> made, List<Realised> realised, InferredState.Editor next) {
        if (realised.isEmpty()) {
            made.forEach(module -> module.namedMembers().forEach(member -> next.put(member, null)));
            return;
        }
        for (Realised outcome : realised) {
            if (outcome.consistent()) {
                outcome.types().forEach(next::put);
            } else {
                modules.markInconsistent(outcome.module());
                outcome.module().namedMembers().forEach(member -> next.put(member, null));
            }
        }
    }

    /**
     * Runs module reasoning; a failure of the underlying reasoner on a module (not a time limit
     * or an interruption) sends this ontology to whole-ontology reasoning, where it fails, or
     * not, exactly as before.
     */
    private void guarded(Runnable work) {
        try {
            work.run();
        } catch (TimeOutException | ReasonerInterruptedException e) {
            mode = Mode.NOT_REASONED;
            throw e;
        } catch (RuntimeException e) {
            if (disposed) {
                throw e;
            }
            reasonOnWhole("a module failed: " + e);
        }
    }

    private void reasonOnWhole(String because) {
        if (disposed) {
            throw new ReasonerInterruptedException("the reasoner was disposed while this call ran");
        }
        LOG.info("{}: reasoning on the whole ontology with {}: {}", ontology.getOntologyID().getOntologyIRI()
                .map(Object::toString).orElse("(anonymous ontology)"), underlyingName, because);
        mode = Mode.WHOLE;
        wholeBecause = because;
        plan = ReasoningPlan.whole(because);
        nominalIndependence = null;
        links = null;
        rules = null;
        baseState = null;
        modules = null;
        realiser = null;
        state = null;
        if (whole != null) {
            whole.dispose();
        }
        whole = factory.createReasoner(ontology, configuration);
        wholeBehind = false;
        wholeMissedRemoval = false;
    }

    /**
     * The schema's class hierarchy: the one kept for this schema (classified earlier, or read from
     * the checkpoint's sidecar), else classified by a reasoner of the underlying kind on the
     * schema alone ({@link ClassifiedSchema}): at once for an ontology that stands alone, in the
     * background over an upper ontology ({@link Classifications}), where class questions wait for it.
     */
    private void classify() {
        ClassifiedSchema.Input input = ClassifiedSchema.inputOf(ontology, underlyingName);
        Classifications.Job previous = classification;
        if (previous == null || !previous.input.digest().equals(input.digest())) {
            Classifications.Job job = Classifications.of(input, factory, configuration);
            classifiedHere = job.running();
            classification = job;
            Classifications.release(previous);
        }
        hierarchyCovers = ClassifiedSchema.covers(input, ontology.axioms(Imports.INCLUDED)
                .filter(axiom -> axiom.isOfType(AxiomType.ABoxAxiomTypes)));
        if (scope.everyClass()) {
            awaitClassification();
        }
    }

    /** The classification, waited for while it runs (a time limit stops the wait, not the classification). */
    private ClassifiedSchema awaitClassification() {
        stopWaiting = false;
        ClassifiedSchema done = classification.await(() -> stopWaiting);
        if (done != null && classifiedHere && announced != classification) {
            announced = classification;
            LOG.info("{}: {} classes classified with {} in {} ms", ontology.getOntologyID().getOntologyIRI()
                    .map(Object::toString).orElse("(anonymous ontology)"), done.classCount(), underlyingName,
                    done.classificationNanos() / 1_000_000);
        }
        return done;
    }

    /** On the whole ontology: a schema change classifies again, an assertion may leave the kept hierarchy. */
    private void keepHierarchyUpToDate(List<OWLOntologyChange> changes) {
        boolean schemaChanged = false;
        for (OWLOntologyChange change : changes) {
            if (change.isImportChange() || change.isAxiomChange() && change.getAxiom().isLogicalAxiom()
                    && !change.getAxiom().isOfType(AxiomType.ABoxAxiomTypes)) {
                schemaChanged = true;
            } else if (change.isAxiomChange()) {
                hierarchyCovers &= !ClassifiedSchema.escapes(classification.input, change.getAxiom());
            }
        }
        if (schemaChanged) {
            classify();
        }
    }

    /**
     * The kept hierarchy, when it is the whole ontology's: the schema is consistent, so is the
     * ontology, and the ABox cannot add to the hierarchy ({@link ClassifiedSchema#covers}).
     */
    private ClassifiedSchema hierarchy() {
        if (underlyingName.equalsIgnoreCase("JFACT")) {
            // JFact's kept hierarchy missed an equivalence a schema change made (MAKE EQUIVALENT
            // CLASS: test_contract_manipulations); its own reasoner answers class questions.
            return null;
        }
        InferredState now = current();
        ClassifiedSchema kept = hierarchyCovers ? awaitClassification() : null;
        if (kept == null || !kept.consistent()) {
            return null;
        }
        boolean consistent = now != null ? now.consistent() : whole().isConsistent();
        return consistent ? kept : null;
    }

    /**
     * Every type of the members of an individual's module, over an upper ontology where the
     * modules are realised against some classes only: found now, kept until a change touches the module.
     */
    private TypeProfile everyTypeOf(OWLNamedIndividual individual, TypeProfile known) {
        Module module = modules.of(individual);
        if (module == null || everyType == null) {
            return known;
        }
        everyType.prepare();
        InferredState.Editor next = state.edit();
        record(List.of(module), everyType.realise(List.of(module), modules::axiomsOf), next);
        state = next.done();
        return state.types(individual).orElseThrow(InconsistentOntologyException::new);
    }

    /** Schema axioms and ABox axioms that can make properties link (see {@link AboxLinks#shapesLinks}). */
    private Stream<OWLAxiom> linkShapingAxioms() {
        return Stream.concat(logicalSchemaAxioms(),
                Stream.concat(ontology.axioms(AxiomType.CLASS_ASSERTION, Imports.INCLUDED),
                        ontology.axioms(AxiomType.NEGATIVE_OBJECT_PROPERTY_ASSERTION, Imports.INCLUDED))
                        .filter(AboxLinks::shapesLinks));
    }

    /** The logical axioms that are neither assertions nor rules, through the index by kind (not every assertion). */
    private Stream<OWLAxiom> logicalSchemaAxioms() {
        return AxiomType.AXIOM_TYPES.stream()
                .filter(type -> type.isLogical() && !AxiomType.ABoxAxiomTypes.contains(type)
                        && type != AxiomType.SWRL_RULE)
                .flatMap(type -> ontology.axioms(type, Imports.INCLUDED).map(OWLAxiom.class::cast));
    }

    /**
     * What every module is reasoned with: the logical axioms that are not assertions, and a
     * declaration of every class, property and datatype (so a module's signature is the whole
     * ontology's, individuals apart).
     */
    private List<OWLAxiom> schemaAxioms() {
        OWLDataFactory data = ontology.getOWLOntologyManager().getOWLDataFactory();
        Stream<OWLAxiom> declarations = ontology.signature(Imports.INCLUDED)
                .filter(entity -> !entity.isOWLNamedIndividual() && !entity.isBuiltIn())
                .map(data::getOWLDeclarationAxiom);
        return Stream.concat(logicalSchemaAxioms(), declarations).distinct().toList();
    }

    /** The kept types, brought up to date first (the first question reasons on every module). */
    private InferredState current() {
        if (mode == Mode.NOT_REASONED) {
            reasonOnModules();
        } else if (mode == Mode.MODULAR && !pending.isEmpty()) {
            flush();
        }
        return mode == Mode.MODULAR ? state : null;
    }

    /** The reasoner on the whole ontology, up to date: made or refreshed on demand in modular mode. */
    private OWLReasoner whole() {
        current();
        if (whole == null) {
            whole = factory.createReasoner(ontology, configuration);
            wholeBehind = false;
            wholeMissedRemoval = false;
        } else if (wholeBehind) {
            // Openllet and JFact keep inferences of removed axioms; HermiT refuses some additions; with
            // nominals, JFact and HermiT were seen to keep a class hierarchy that added assertions change.
            AboxLinks now = links;
            boolean rebuilt = wholeMissedRemoval || now != null && !now.nominals().isEmpty();
            if (!rebuilt) {
                try {
                    whole.flush();
                } catch (TimeOutException | ReasonerInterruptedException | InconsistentOntologyException e) {
                    throw e;
                } catch (RuntimeException e) {
                    rebuilt = true;
                }
            }
            if (rebuilt) {
                whole.dispose();
                whole = factory.createReasoner(ontology, configuration);
            }
            wholeBehind = false;
            wholeMissedRemoval = false;
        }
        return whole;
    }

    private InferredState consistentState() {
        InferredState now = current();
        if (now != null && !now.consistent()) {
            throw new InconsistentOntologyException();
        }
        return now;
    }

    @Override
    public boolean isConsistent() {
        InferredState now = current();
        return now != null ? now.consistent() : whole().isConsistent();
    }

    @Override
    public NodeSet<OWLClass> getTypes(OWLNamedIndividual individual, boolean direct) {
        InferredState now = consistentState();
        if (now != null && now.knows(individual)) {
            TypeProfile profile = now.types(individual).orElseThrow(InconsistentOntologyException::new);
            if (!profile.complete()) {
                profile = everyTypeOf(individual, profile);
            }
            // Direct types need the whole ontology's class hierarchy: the hub's assertions can add to it.
            if (!direct || links.nominals().isEmpty()) {
                return profile.nodeSet(direct);
            }
            // Over an upper ontology, a module outside the hub was realised on the schema part its
            // assertions use, which the nominals cannot reach (NominalIndependence): its classes' order is the whole's.
            Module module = modules.of(individual);
            if (!scope.everyClass() && module != null && !module.hub) {
                return profile.nodeSet(true);
            }
            ClassifiedSchema kept = hierarchy();
            if (kept != null) {
                return kept.mostSpecific(profile.nodeSet(false));
            }
        }
        return whole().getTypes(individual, direct);
    }

    /**
     * Realises the modules against all of {@code classes} at once, where they are not yet (over an
     * upper ontology): for a caller about to ask the instances of many classes (SPARQL's inferred
     * graph), which would otherwise realise the modules once per class.
     */
    public void realiseAgainst(java.util.Collection<OWLClass> classes) {
        InferredState now = current();
        if (now == null) {
            return;
        }
        boolean more = false;
        for (OWLClass owlClass : classes) {
            if (!now.knows(owlClass) && now.inSignature(owlClass)) {
                more |= asked.add(owlClass);
            }
        }
        if (more) {
            mode = Mode.NOT_REASONED;
            current();
        }
    }

    @Override
    public NodeSet<OWLNamedIndividual> getInstances(OWLClassExpression expression, boolean direct) {
        InferredState now = consistentState();
        if (now == null || expression.isAnonymous() || direct) {
            return whole().getInstances(expression, direct);
        }
        if (!now.knows(expression.asOWLClass()) && now.inSignature(expression.asOWLClass())) {
            // A class not realised yet (over an upper ontology): from now on it is, with every change.
            asked.add(expression.asOWLClass());
            mode = Mode.NOT_REASONED;
            now = consistentState();
            if (now == null) {
                return whole().getInstances(expression, false);
            }
        }
        OWLNamedIndividualNodeSet instances = new OWLNamedIndividualNodeSet();
        for (OWLNamedIndividual individual : now.instances(expression.asOWLClass())) {
            instances.addNode(new OWLNamedIndividualNode(individual));
        }
        return instances;
    }

    @Override
    public void interrupt() {
        ModuleRealiser current = realiser;
        if (current != null) {
            current.interrupt();
        }
        ModuleRealiser types = everyType;
        if (types != null) {
            types.interrupt();
        }
        stopWaiting = true;
        OWLReasoner wholeNow = whole;
        if (wholeNow != null) {
            wholeNow.interrupt();
        }
    }

    @Override
    public void precomputeInferences(InferenceType... inferenceTypes) {
        if (current() == null) {
            for (InferenceType type : inferenceTypes) {
                // The kept hierarchy is the class hierarchy; over an upper ontology, types are found per question.
                boolean kept = type == InferenceType.CLASS_HIERARCHY && hierarchy() != null
                        || type == InferenceType.CLASS_ASSERTIONS && !scope.everyClass();
                if (!kept) {
                    whole().precomputeInferences(type);
                }
            }
        }
        // Class assertions are what the modules keep; anything else is computed when first asked.
    }

    @Override
    public boolean isPrecomputed(InferenceType inferenceType) {
        return mode == Mode.MODULAR ? inferenceType == InferenceType.CLASS_ASSERTIONS
                : mode == Mode.WHOLE && whole.isPrecomputed(inferenceType);
    }

    @Override
    public Set<InferenceType> getPrecomputableInferenceTypes() {
        return mode == Mode.WHOLE ? whole.getPrecomputableInferenceTypes() : Set.of(InferenceType.CLASS_ASSERTIONS);
    }

    @Override
    public void dispose() {
        disposed = true;
        ontology.getOWLOntologyManager().removeOntologyChangeListener(listener);
        Classifications.release(classification);
        if (whole != null) {
            whole.dispose();
        }
        whole = null;
        state = null;
        modules = null;
        realiser = null;
    }

    @Override
    public String getReasonerName() {
        return "ARMOR modules over " + underlyingName;
    }

    @Override
    public Version getReasonerVersion() {
        return new Version(1, 0, 0, 0);
    }

    @Override
    public BufferingMode getBufferingMode() {
        return BufferingMode.BUFFERING;
    }

    @Override
    public List<OWLOntologyChange> getPendingChanges() {
        return List.copyOf(pending);
    }

    @Override
    public Set<OWLAxiom> getPendingAxiomAdditions() {
        return pending.stream().filter(OWLOntologyChange::isAddAxiom).map(OWLOntologyChange::getAxiom)
                .collect(Collectors.toSet());
    }

    @Override
    public Set<OWLAxiom> getPendingAxiomRemovals() {
        return pending.stream().filter(OWLOntologyChange::isRemoveAxiom).map(OWLOntologyChange::getAxiom)
                .collect(Collectors.toSet());
    }

    @Override
    public OWLOntology getRootOntology() {
        return ontology;
    }

    @Override
    public long getTimeOut() {
        return configuration.getTimeOut();
    }

    @Override
    public FreshEntityPolicy getFreshEntityPolicy() {
        return configuration.getFreshEntityPolicy();
    }

    @Override
    public IndividualNodeSetPolicy getIndividualNodeSetPolicy() {
        return configuration.getIndividualNodeSetPolicy();
    }

    // Everything below is answered by the reasoner on the whole ontology.

    @Override
    public boolean isSatisfiable(OWLClassExpression classExpression) {
        ClassifiedSchema kept = classExpression.isAnonymous() ? null : hierarchy();
        return kept != null ? kept.isSatisfiable(classExpression.asOWLClass()) : whole().isSatisfiable(classExpression);
    }

    @Override
    public Node<OWLClass> getUnsatisfiableClasses() {
        ClassifiedSchema kept = hierarchy();
        return kept != null ? kept.bottomNode() : whole().getUnsatisfiableClasses();
    }

    @Override
    public boolean isEntailed(OWLAxiom axiom) {
        return whole().isEntailed(axiom);
    }

    @Override
    public boolean isEntailed(Set<? extends OWLAxiom> axioms) {
        return whole().isEntailed(axioms);
    }

    @Override
    public boolean isEntailmentCheckingSupported(AxiomType<?> axiomType) {
        return whole().isEntailmentCheckingSupported(axiomType);
    }

    @Override
    public Node<OWLClass> getTopClassNode() {
        ClassifiedSchema kept = hierarchy();
        return kept != null ? kept.topNode() : whole().getTopClassNode();
    }

    @Override
    public Node<OWLClass> getBottomClassNode() {
        ClassifiedSchema kept = hierarchy();
        return kept != null ? kept.bottomNode() : whole().getBottomClassNode();
    }

    @Override
    public NodeSet<OWLClass> getSubClasses(OWLClassExpression ce, boolean direct) {
        ClassifiedSchema kept = ce.isAnonymous() ? null : hierarchy();
        return kept != null ? kept.subClasses(ce.asOWLClass(), direct) : whole().getSubClasses(ce, direct);
    }

    @Override
    public NodeSet<OWLClass> getSuperClasses(OWLClassExpression ce, boolean direct) {
        ClassifiedSchema kept = ce.isAnonymous() ? null : hierarchy();
        return kept != null ? kept.superClasses(ce.asOWLClass(), direct) : whole().getSuperClasses(ce, direct);
    }

    @Override
    public Node<OWLClass> getEquivalentClasses(OWLClassExpression ce) {
        ClassifiedSchema kept = ce.isAnonymous() ? null : hierarchy();
        return kept != null ? kept.equivalentClasses(ce.asOWLClass()) : whole().getEquivalentClasses(ce);
    }

    @Override
    public NodeSet<OWLClass> getDisjointClasses(OWLClassExpression ce) {
        return whole().getDisjointClasses(ce);
    }

    @Override
    public Node<OWLObjectPropertyExpression> getTopObjectPropertyNode() {
        return whole().getTopObjectPropertyNode();
    }

    @Override
    public Node<OWLObjectPropertyExpression> getBottomObjectPropertyNode() {
        return whole().getBottomObjectPropertyNode();
    }

    @Override
    public NodeSet<OWLObjectPropertyExpression> getSubObjectProperties(OWLObjectPropertyExpression pe, boolean direct) {
        return whole().getSubObjectProperties(pe, direct);
    }

    @Override
    public NodeSet<OWLObjectPropertyExpression> getSuperObjectProperties(OWLObjectPropertyExpression pe,
                                                                       boolean direct) {
        return whole().getSuperObjectProperties(pe, direct);
    }

    @Override
    public Node<OWLObjectPropertyExpression> getEquivalentObjectProperties(OWLObjectPropertyExpression pe) {
        return whole().getEquivalentObjectProperties(pe);
    }

    @Override
    public NodeSet<OWLObjectPropertyExpression> getDisjointObjectProperties(OWLObjectPropertyExpression pe) {
        return whole().getDisjointObjectProperties(pe);
    }

    @Override
    public Node<OWLObjectPropertyExpression> getInverseObjectProperties(OWLObjectPropertyExpression pe) {
        return whole().getInverseObjectProperties(pe);
    }

    @Override
    public NodeSet<OWLClass> getObjectPropertyDomains(OWLObjectPropertyExpression pe, boolean direct) {
        return whole().getObjectPropertyDomains(pe, direct);
    }

    @Override
    public NodeSet<OWLClass> getObjectPropertyRanges(OWLObjectPropertyExpression pe, boolean direct) {
        return whole().getObjectPropertyRanges(pe, direct);
    }

    @Override
    public Node<OWLDataProperty> getTopDataPropertyNode() {
        return whole().getTopDataPropertyNode();
    }

    @Override
    public Node<OWLDataProperty> getBottomDataPropertyNode() {
        return whole().getBottomDataPropertyNode();
    }

    @Override
    public NodeSet<OWLDataProperty> getSubDataProperties(OWLDataProperty pe, boolean direct) {
        return whole().getSubDataProperties(pe, direct);
    }

    @Override
    public NodeSet<OWLDataProperty> getSuperDataProperties(OWLDataProperty pe, boolean direct) {
        return whole().getSuperDataProperties(pe, direct);
    }

    @Override
    public Node<OWLDataProperty> getEquivalentDataProperties(OWLDataProperty pe) {
        return whole().getEquivalentDataProperties(pe);
    }

    @Override
    public NodeSet<OWLDataProperty> getDisjointDataProperties(OWLDataPropertyExpression pe) {
        return whole().getDisjointDataProperties(pe);
    }

    @Override
    public NodeSet<OWLClass> getDataPropertyDomains(OWLDataProperty pe, boolean direct) {
        return whole().getDataPropertyDomains(pe, direct);
    }

    @Override
    public NodeSet<OWLNamedIndividual> getObjectPropertyValues(OWLNamedIndividual ind, OWLObjectPropertyExpression pe) {
        // The edges of a property the rules read or conclude are kept by the engine (RuleProgram: they are exactly those).
        InferredState now = consistentState();
        Set<OWLNamedIndividual> kept = now != null && rules != null ? rules.objectValues(ind, pe) : null;
        if (kept != null) {
            OWLNamedIndividualNodeSet values = new OWLNamedIndividualNodeSet();
            kept.forEach(value -> values.addNode(new OWLNamedIndividualNode(value)));
            return values;
        }
        return whole().getObjectPropertyValues(ind, pe);
    }

    @Override
    public Set<OWLLiteral> getDataPropertyValues(OWLNamedIndividual ind, OWLDataProperty pe) {
        return whole().getDataPropertyValues(ind, pe);
    }

    @Override
    public Node<OWLNamedIndividual> getSameIndividuals(OWLNamedIndividual ind) {
        return whole().getSameIndividuals(ind);
    }

    @Override
    public NodeSet<OWLNamedIndividual> getDifferentIndividuals(OWLNamedIndividual ind) {
        return whole().getDifferentIndividuals(ind);
    }
}
