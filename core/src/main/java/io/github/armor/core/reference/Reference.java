// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.AcknowledgedChange;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reasoning.ModularReasoner;
import io.github.armor.core.reasoning.PublishedStates;
import io.github.armor.core.reasoning.RealisationScope;
import io.github.armor.core.reasoning.ReasoningPlan;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Function;
import java.util.function.Supplier;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDocumentFormat;
import org.semanticweb.owlapi.model.OWLInverseObjectPropertiesAxiom;
import org.semanticweb.owlapi.model.OWLNaryAxiom;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.RemoveAxiom;
import org.semanticweb.owlapi.reasoner.InconsistentOntologyException;
import org.semanticweb.owlapi.reasoner.InferenceType;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.ReasonerInterruptedException;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;
import org.semanticweb.owlapi.reasoner.TimeOutException;

/**
 * One named ontology with its reasoner, as ARMOR calls it a reference.
 *
 * <p>Threading: OWL API ontologies and reasoners are not safe for concurrent use, so every
 * directive on a reference runs under {@link #lock}; directives on different references run in
 * parallel. Callers take the lock through {@link #locked} with a bounded wait.
 *
 * <p>Buffered manipulation queues changes until {@link #applyPending()}; a buffered reasoner sees
 * applied changes only at {@link #reason()}. {@link #isConsistent()} is a cached value, refreshed
 * whenever the reasoner is brought up to date, so reading it never costs a reasoning pass.
 */
public final class Reference {
    /**
     * How a reference was made: everything needed to make it again from a saved copy.
     *
     * @param source           the file or URL it was loaded from; null for CREATE
     * @param ontologyIri      the ontology IRI argument as given (empty: the document's own)
     * @param reasoner         canonical reasoner name
     */
    public record Settings(String source, String ontologyIri, String reasoner, boolean bufferedManipulation,
                           boolean bufferedReasoner) {}

    private final String name;
    private final Settings settings;
    private final String source;
    private final OWLOntologyManager manager;
    private final OWLOntology ontology;
    private final EntityResolver resolver;
    private final String reasonerName;
    private final boolean bufferedManipulation;
    private final boolean bufferedReasoner;
    private final long reasonerTimeoutMs;
    private final ReasonerCoverage coverage;

    private final ReentrantLock lock = new ReentrantLock(true);
    private volatile boolean viewInside;
    // The reasoner's kept types as readers that do not wait see them: offered when a writer lets go.
    private final PublishedStates published = new PublishedStates();

    private final List<OWLOntologyChange> pending = new ArrayList<>();
    // Null after a time limit took it away: made afresh when next needed (see reasoner()).
    private OWLReasoner reasoner;
    private boolean removedSinceSync;
    private boolean consistent = true;
    private String mountedBy = "";
    private ArmorException loadTimeout;
    private Transaction transaction;
    // When the reasoner was last brought up to date and how long it took (the web view shows them).
    private volatile long lastReasoningEpochMs;
    private volatile long lastReasoningNanos;
    // Changes the reasoner has not been brought up to date with since the last timed reasoning.
    private boolean unreasonedChanges;
    // Read by event and subscription threads without the lock; written only under it.
    private volatile long revision;
    private final ChangeHistory changeHistory = new ChangeHistory();
    // In memory only: derived state (the SPARQL graph) is rebuilt when it moves; read under the lock.
    private long modificationCount;

    /**
     * A reference over an ontology. Plain names take the ontology IRI of the settings (or the
     * document's own) followed by '#', as ARMOR does; prefixes are those the document declares.
     */
    public static Reference open(String name, OWLOntology ontology, Settings settings, long reasonerTimeoutMs) {
        String ontologyIri = !settings.ontologyIri().isEmpty() ? settings.ontologyIri()
                : ontology.getOntologyID().getOntologyIRI().map(Object::toString).orElse("urn:armor:" + name);
        String namespace = ontologyIri.endsWith("#") || ontologyIri.endsWith("/") ? ontologyIri : ontologyIri + "#";
        OWLDocumentFormat format = ontology.getOWLOntologyManager().getOntologyFormat(ontology);
        EntityResolver names = new EntityResolver(ontology, namespace, EntityResolver.prefixesOf(
                format != null && format.isPrefixOWLDocumentFormat()
                        ? format.asPrefixOWLDocumentFormat().getPrefixName2PrefixMap() : Map.of()));
        return new Reference(name, settings, ontology, names, reasonerTimeoutMs);
    }

    private Reference(String name, Settings settings, OWLOntology ontology, EntityResolver resolver,
                      long reasonerTimeoutMs) {
        this.name = name;
        this.settings = settings;
        this.source = settings.source();
        this.manager = ontology.getOWLOntologyManager();
        this.ontology = ontology;
        this.resolver = resolver;
        this.reasonerName = settings.reasoner();
        this.bufferedManipulation = settings.bufferedManipulation();
        this.bufferedReasoner = settings.bufferedReasoner();
        this.reasonerTimeoutMs = reasonerTimeoutMs;
        this.coverage = ReasonerCoverage.watch(reasonerName, ontology);
        try {
            ReasonerCalls.withBudget(reasonerTimeoutMs, () -> {
                timedReasoning(this::refreshConsistency);
                return null;
            });
            published.offer(reasoner, revision);
        } catch (ArmorException e) {
            if (e.exitCode() != ExitCode.TIMEOUT) {
                coverage.close();
                throw e;
            }
            // A reasoner that runs away at LOAD is stopped; the reference stays, its reasoner made afresh when asked.
            loadTimeout = e;
        } catch (RuntimeException e) {
            coverage.close();
            throw e;
        }
    }

    /** The time limit the first reasoning ran into at LOAD, once (then empty). */
    public Optional<ArmorException> takeLoadTimeout() {
        Optional<ArmorException> taken = Optional.ofNullable(loadTimeout);
        loadTimeout = null;
        return taken;
    }

    /**
     * Runs {@code work} holding this reference, waiting at most {@code waitMs} for other
     * directives; its reasoner calls share one reasoner time limit.
     */
    public <T> T locked(long waitMs, Function<Reference, T> work) {
        acquire(waitMs);
        try {
            return ReasonerCalls.withBudget(reasonerTimeoutMs, () -> work.apply(this));
        } finally {
            release();
        }
    }

    /**
     * {@link #locked} for a read-only view of the web page: while a view holds this reference,
     * {@link #heldByDirective} stays false, so a page does not report its own read as a directive.
     */
    public <T> T lockedForView(long waitMs, Function<Reference, T> work) {
        return locked(waitMs, r -> {
            boolean outermost = !viewInside;
            viewInside = true;
            try {
                return work.apply(r);
            } finally {
                if (outermost) {
                    viewInside = false;
                }
            }
        });
    }

    /**
     * Takes this reference for the calling thread (re-entrant), waiting at most {@code waitMs};
     * an atomic list holds every reference it touches this way until it ends.
     *
     * @throws ArmorException TIMEOUT when another directive kept it longer
     */
    public void acquire(long waitMs) {
        boolean acquired;
        try {
            acquired = lock.tryLock(waitMs, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new ArmorException(ExitCode.TIMEOUT, "interrupted while waiting for reference '" + name + "'");
        }
        if (!acquired) {
            throw new ArmorException(ExitCode.TIMEOUT, "reference '" + name + "' stayed busy for " + waitMs
                    + " ms (another directive is using it)");
        }
    }

    public void release() {
        if (lock.getHoldCount() == 1) {
            published.offer(reasoner, revision);
        }
        lock.unlock();
    }

    /** Whether other threads wait for this reference (a read-only view then lets them go first). */
    public boolean othersWaiting() {
        return lock.hasQueuedThreads();
    }

    /** Whether another thread holds this reference (a writer reasoning, or a directive under way). */
    public boolean isBusy() {
        return lock.isLocked() && !lock.isHeldByCurrentThread();
    }

    /** Whether a directive (not a view of the web page) holds this reference: what a page shows as busy. */
    public boolean heldByDirective() {
        return isBusy() && !viewInside;
    }

    /**
     * The last reasoned state a writer left, for a reader that must not wait while the reference
     * is busy; empty when this reference's reasoner keeps none (buffered reasoner, ELK, whole-ontology reasoning).
     */
    public Optional<PublishedStates.Published> publishedState() {
        return published.current();
    }

    public String name() {
        return name;
    }

    public String source() {
        return source;
    }

    public Settings settings() {
        return settings;
    }

    /** Whether buffered manipulations wait for APPLY (a checkpoint holds applied changes only). */
    public boolean hasPending() {
        return !pending.isEmpty();
    }

    public OWLOntology ontology() {
        return ontology;
    }

    public OWLOntologyManager manager() {
        return manager;
    }

    public OWLDataFactory factory() {
        return manager.getOWLDataFactory();
    }

    public EntityResolver names() {
        return resolver;
    }

    public String reasonerName() {
        return reasonerName;
    }

    /** What of the ontology the reasoner does not use (its answers may then be incomplete). */
    public ReasonerCoverage coverage() {
        return coverage;
    }

    public boolean isConsistent() {
        return consistent;
    }

    /** How this reference's ontology is reasoned on: in modules, or whole and why. Safe from any thread. */
    public ReasoningPlan reasoningPlan() {
        OWLReasoner current = reasoner;
        if (current instanceof ModularReasoner modular) {
            return modular.plan();
        }
        if (bufferedReasoner) {
            return ReasoningPlan.whole("buffered reasoner (brought up to date at REASON)");
        }
        return current == null ? ReasoningPlan.NOT_YET : ReasoningPlan.whole(reasonerName
                + " is not one of the reasoners ARMOR reasons in modules with (HERMIT, PELLET, JFACT)");
    }

    /**
     * What LOAD says about the reference beyond success: its profile, what the reasoner will not
     * use, how many classes and what classifying them cost, and how it is reasoned on.
     */
    public LoadStatement loadStatement() {
        ReasoningPlan plan = reasoningPlan();
        return new LoadStatement()
                .with("profile", coverage.profileName().isEmpty() ? "" : "profile: " + coverage.profileName())
                .with("coverage", coverage.unusedReport())
                .with("classes", classification().describe())
                .with("reasoning", plan != ReasoningPlan.NOT_YET && !bufferedReasoner ? "reasoning " + plan.describe()
                        : "");
    }

    /** The schema's kept class hierarchy, when the reasoner keeps one (in modules). Safe from any thread. */
    public Optional<io.github.armor.core.reasoning.ClassifiedSchema> classifiedSchema() {
        return reasoner instanceof ModularReasoner modular ? Optional.ofNullable(modular.classifiedSchema())
                : Optional.empty();
    }

    /** What CREATE says: an empty ontology's only news are what the reasoner will not use, and whole-ontology reasoning. */
    public LoadStatement createStatement() {
        ReasoningPlan plan = reasoningPlan();
        String unused = coverage.unusedReport();
        return new LoadStatement().with("profile", unused.isEmpty() ? "" : "profile: " + coverage.profileName())
                .with("coverage", unused)
                .with("reasoning", plan.whole() && !bufferedReasoner && ModularReasoner.handles(reasonerName)
                        ? "reasoning " + plan.describe() : "");
    }

    /** How many classes the ontology has and what its kept hierarchy cost. Safe from any thread. */
    public Classification classification() {
        OWLReasoner current = reasoner;
        int classes = (int) ontology.classesInSignature(org.semanticweb.owlapi.model.parameters.Imports.INCLUDED)
                .filter(owlClass -> !owlClass.isBuiltIn()).count();
        return current instanceof ModularReasoner modular ? Classification.of(classes, modular)
                : Classification.notKept(classes);
    }

    /**
     * How many times the ontology or the reasoner's view of it has changed (enacted changes,
     * APPLY, rollbacks, reasoner flushes and rebuilds) since the reference was opened. Whatever
     * is derived from both may be kept while this stays the same.
     */
    public long modificationCount() {
        return modificationCount;
    }

    public String mountedBy() {
        return mountedBy;
    }

    public void setMountedBy(String client) {
        mountedBy = client == null ? "" : client;
    }

    /**
     * How many acknowledged changes the reference has had: 0 when it is loaded or created, one
     * more for each journaled directive or atomic list that changed it. It survives restarts
     * (the journal keeps it), so change events and subscription answers can be ordered by it.
     */
    public long revision() {
        return revision;
    }

    /** Its latest acknowledged changes (GET REF CHANGES). */
    public ChangeHistory changeHistory() {
        return changeHistory;
    }

    /** An acknowledged change: the revision it made, kept in the change history. */
    public void acknowledge(AcknowledgedChange change) {
        this.revision = change.revision();
        changeHistory.add(change);
    }

    /** Sets the revision to the journal's at a restore. */
    public void setRevision(long revision) {
        this.revision = revision;
    }

    /** Queues or applies ontology changes according to the buffering mode. */
    public void change(List<? extends OWLOntologyChange> changes) {
        if (changes.isEmpty()) {
            return;
        }
        for (OWLOntologyChange change : changes) {
            // SameIndividual(:a :a) parses to one operand, which no OWL syntax can write down.
            if (change.isAddAxiom() && change.getAxiom() instanceof OWLNaryAxiom<?> nary
                    && nary.getOperandsAsList().size() < 2) {
                throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "an axiom of this kind needs two different"
                        + " operands at least: " + nary);
            }
        }
        if (bufferedManipulation) {
            pending.addAll(changes);
            return;
        }
        enact(changes);
    }

    /** APPLY: the queued changes reach the ontology (and a non-buffered reasoner). */
    public void applyPending() {
        if (transaction != null && transaction.pendingBefore == null) {
            transaction.pendingBefore = List.copyOf(pending);
        }
        List<OWLOntologyChange> queued = List.copyOf(pending);
        pending.clear();
        enact(queued);
    }

    /** REASON: apply the queue, bring the reasoner up to date, recompute consistency and inferences. */
    public void reason() {
        noteReasonedInTransaction();
        applyPending();
        timedReasoning(() -> {
            bringReasonerUpToDate();
            refreshConsistency();
            // Over an upper ontology a plain reasoner answers each question when asked: realising
            // every individual against SOMA's classes takes longer than any robot waits.
            if (consistent && (reasoner instanceof ModularReasoner
                    || !RealisationScope.overUpperOntology(ontology))) {
                precompute(InferenceType.CLASS_HIERARCHY);
                precompute(InferenceType.CLASS_ASSERTIONS);
            }
        });
    }

    /**
     * The reasoner for a query, with consistency checked first: reasoners answer nothing meaningful
     * (or throw) on an inconsistent ontology.
     */
    public OWLReasoner reasonerForQuery() {
        if (!consistent) {
            throw new ArmorException(ExitCode.INCONSISTENT, "reference '" + name
                    + "' is inconsistent; QUERY CONSISTENCY explains why");
        }
        return reasoner();
    }

    /**
     * Runs a reasoner call within the reasoner time limit, turning the reasoner's own failures
     * into ARMOR codes. A reasoner that overruns is interrupted and replaced by a fresh one, so
     * the reference stays usable (its next query reasons from scratch); whatever it answered
     * after the limit is discarded, and one that ignores the interruption is left behind
     * ({@link ReasonerCalls}).
     */
    public <T> T guardReasoner(Supplier<T> call) {
        try {
            return withinTimeLimit(call);
        } catch (InconsistentOntologyException e) {
            consistent = false;
            throw new ArmorException(ExitCode.INCONSISTENT, "reference '" + name + "' is inconsistent", e);
        } catch (TimeOutException | ReasonerInterruptedException | ReasonerCalls.Overran e) {
            throw overran(e);
        } catch (UnsupportedOperationException e) {
            throw new ArmorException(ExitCode.NOT_SUPPORTED, reasonerName + " does not support this: "
                    + e.getMessage() + "; a complete OWL 2 DL reasoner (PELLET, HERMIT) answers it", e);
        } catch (ArmorException e) {
            throw e;
        } catch (RuntimeException e) {
            throw new ArmorException(ExitCode.REASONER_FAILED, reasonerName + " failed on reference '" + name
                    + "': " + e, e);
        }
    }

    /** Releases the reasoner; the reference must not be used afterwards. */
    public void dispose() {
        coverage.close();
        if (reasoner != null) {
            reasoner.dispose();
        }
    }

    /** Starts recording changes so that an atomic directive list can undo them. */
    public void beginTransaction() {
        if (transaction == null) {
            transaction = new Transaction(pending.size());
        }
    }

    public void commitTransaction() {
        transaction = null;
    }

    /** Undoes everything since {@link #beginTransaction()}: enacted changes and the queue. */
    public void rollbackTransaction() {
        Transaction undo = transaction;
        transaction = null;
        if (undo == null) {
            return;
        }
        List<OWLOntologyChange> reversed = new ArrayList<>();
        for (int i = undo.enacted.size() - 1; i >= 0; i--) {
            reversed.add(undo.enacted.get(i).reverseChange());
        }
        manager.applyChanges(reversed);
        modificationCount++;
        unreasonedChanges |= !reversed.isEmpty();
        removedSinceSync |= reversed.stream().anyMatch(OWLOntologyChange::isRemoveAxiom);
        if (undo.pendingBefore != null) {
            pending.clear();
            pending.addAll(undo.pendingBefore);
        } else {
            pending.subList(undo.pendingSizeBefore, pending.size()).clear();
        }
        if (!reversed.isEmpty() && (!bufferedReasoner || undo.reasoned)) {
            synchroniseReasoner();
        }
    }

    private void enact(List<? extends OWLOntologyChange> requested) {
        if (requested.isEmpty()) {
            return;
        }
        List<OWLOntologyChange> changes = requested.stream().map(Reference::asStored).toList();
        List<OWLOntologyChange> enacted = new ArrayList<>(manager.applyChangesAndGetDetails(changes).getEnactedChanges());
        modificationCount++;
        unreasonedChanges |= !enacted.isEmpty();
        removedSinceSync |= enacted.stream().anyMatch(OWLOntologyChange::isRemoveAxiom);
        if (transaction != null) {
            transaction.enacted.addAll(enacted);
        }
        if (!bufferedReasoner && !enacted.isEmpty()) {
            synchroniseReasoner();
        }
    }

    /**
     * A removal of the axiom as the ontology stores it. InverseObjectProperties(p q) equals
     * InverseObjectProperties(q p) but is written in the order it was added: undoing the removal
     * of the other order would put back an axiom written differently (a SAVE, a digest and the
     * journal would see a change that a rolled-back list must not make).
     */
    private static OWLOntologyChange asStored(OWLOntologyChange change) {
        if (change.isRemoveAxiom() && change.getAxiom() instanceof OWLInverseObjectPropertiesAxiom inverse) {
            return change.getOntology().inverseObjectPropertyAxioms(inverse.getFirstProperty())
                    .filter(inverse::equals).findFirst()
                    .map(stored -> (OWLOntologyChange) new RemoveAxiom(change.getOntology(), stored))
                    .orElse(change);
        }
        return change;
    }

    /**
     * Brings the reasoner up to date with the ontology (applied changes; the buffer stays). After
     * a restore this makes even a buffered reasoner see everything that was replayed.
     */
    public void synchroniseReasoner() {
        noteReasonedInTransaction();
        Runnable work = () -> {
            bringReasonerUpToDate();
            refreshConsistency();
        };
        if (unreasonedChanges) {
            timedReasoning(work);
        } else {
            // Nothing new (a restore without changes to replay): the time shown stays that of
            // the reasoning that did the work, not of a no-op flush ("reasoned in 0.0 ms").
            work.run();
        }
    }

    /** When the reasoner was last brought up to date (ms since the epoch; 0: never). */
    public long lastReasoningEpochMs() {
        return lastReasoningEpochMs;
    }

    /** How long bringing the reasoner up to date took that time, in nanoseconds. */
    public long lastReasoningNanos() {
        return lastReasoningNanos;
    }

    private void timedReasoning(Runnable work) {
        unreasonedChanges = false;
        long start = System.nanoTime();
        try {
            work.run();
        } finally {
            lastReasoningNanos = System.nanoTime() - start;
            lastReasoningEpochMs = System.currentTimeMillis();
        }
    }

    /**
     * Flushes the reasoner, or replaces it where incremental updates are known to go wrong:
     * Openllet and JFact keep inferences of removed axioms, and HermiT refuses assertions
     * whose property was not in the ontology when it was created. ELK updates itself correctly,
     * and so does the modular reasoner (it reasons on the modules a change touched afresh).
     */
    private void bringReasonerUpToDate() {
        modificationCount++;
        boolean handlesRemovals = reasonerName.equals("ELK")
                || reasoner instanceof ModularReasoner modular && modular.handlesRemovals();
        if (removedSinceSync && !handlesRemovals) {
            rebuildReasoner();
            return;
        }
        OWLReasoner current = reasoner();
        try {
            guardReasoner(() -> {
                current.flush();
                return null;
            });
        } catch (ArmorException e) {
            if (e.exitCode() != ExitCode.REASONER_FAILED) {
                throw e;
            }
            rebuildReasoner();
        }
    }

    private void rebuildReasoner() {
        try {
            if (reasoner != null) {
                reasoner.dispose();
            }
        } catch (RuntimeException e) {
            // a reasoner that failed may not dispose cleanly; it is replaced either way
        }
        reasoner = null;
        reasoner();
    }

    /** The reasoner, made afresh (over the ontology as it is) if a time limit took the last one away. */
    private OWLReasoner reasoner() {
        if (reasoner == null) {
            reasoner = createReasoner();
            modificationCount++;
            removedSinceSync = false;
        }
        return reasoner;
    }

    private <T> T withinTimeLimit(Supplier<T> call) {
        return ReasonerCalls.run(reasoner(), ReasonerCalls.deadline(reasonerTimeoutMs), call);
    }

    private ArmorException overran(RuntimeException cause) {
        boolean abandoned = cause instanceof ReasonerCalls.Overran overran && overran.abandoned();
        if (!(cause instanceof ReasonerCalls.Overran overran) || overran.started()) {
            // Interrupted, it may answer wrongly or not at all from now on: the next use makes another.
            if (!abandoned) {
                ReasonerCalls.disposeInBackground(reasoner); // an abandoned one is disposed by its call
            }
            reasoner = null;
        }
        return new ArmorException(ExitCode.TIMEOUT, reasonerName + " exceeded the reasoner time limit of "
                + reasonerTimeoutMs + " ms on reference '" + name + "' and was interrupted" + (abandoned
                ? " (it ignored the interruption and runs on in the background until it ends)" : "")
                + "; nothing it computed is answered; the reference is usable and its reasoner starts afresh", cause);
    }

    private void noteReasonedInTransaction() {
        if (transaction != null) {
            transaction.reasoned = true;
        }
    }

    private void refreshConsistency() {
        try {
            consistent = withinTimeLimit(reasoner()::isConsistent);
        } catch (TimeOutException | ReasonerInterruptedException | ReasonerCalls.Overran e) {
            throw overran(e);
        } catch (ArmorException e) {
            throw e;
        } catch (RuntimeException e) {
            // An unsupported construct makes some reasoners fail on isConsistent; other
            // directives on the reference must stay usable, so only the answer says so.
            throw new ArmorException(ExitCode.REASONER_FAILED, reasonerName + " could not check consistency of '"
                    + name + "': " + e + ReasonerRegistry.acceptingAlternative(reasonerName, ontology), e);
        }
    }

    private void precompute(InferenceType type) {
        OWLReasoner current = reasoner();
        guardReasoner(() -> {
            if (current.getPrecomputableInferenceTypes().contains(type)) {
                current.precomputeInferences(type);
            }
            return null;
        });
    }

    /**
     * A reasoner over the ontology, made within the time limit. The limit is not handed to the
     * reasoner's configuration: reasoners count such limits their own way (some return what they
     * have when it passes); {@link ReasonerCalls} enforces it and interrupts them.
     */
    private OWLReasoner createReasoner() {
        try {
            return ReasonerCalls.run(null, ReasonerCalls.deadline(reasonerTimeoutMs), () -> {
                SimpleConfiguration configuration = new SimpleConfiguration();
                // A reasoner brought up to date after every change reasons only where a change reaches.
                if (!bufferedReasoner && ModularReasoner.handles(reasonerName)) {
                    return new ModularReasoner(reasonerName, ReasonerRegistry.factory(reasonerName), ontology,
                            configuration);
                }
                return ReasonerRegistry.factory(reasonerName).createReasoner(ontology, configuration);
            });
        } catch (ReasonerCalls.Overran e) {
            throw new ArmorException(ExitCode.TIMEOUT, reasonerName + " could not start on reference '" + name
                    + "' within the reasoner time limit of " + reasonerTimeoutMs + " ms", e);
        } catch (ArmorException e) {
            throw e;
        } catch (RuntimeException | LinkageError e) {
            throw new ArmorException(ExitCode.REASONER_FAILED, reasonerName + " could not start on reference '"
                    + name + "': " + e + ReasonerRegistry.acceptingAlternative(reasonerName, ontology), e);
        }
    }

    /** What to undo: changes enacted since it began, and the queue as it was (copied only if APPLY empties it). */
    private static final class Transaction {
        final int pendingSizeBefore;
        List<OWLOntologyChange> pendingBefore;
        final List<OWLOntologyChange> enacted = new ArrayList<>();
        // The reasoner was brought up to date meanwhile (a REASON in the list): it and the
        // consistency mark saw changes the rollback undoes.
        boolean reasoned;

        Transaction(int pendingSizeBefore) {
            this.pendingSizeBefore = pendingSizeBefore;
        }
    }
}
