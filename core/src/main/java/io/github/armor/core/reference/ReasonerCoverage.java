// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassAssertionAxiom;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLDatatype;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.model.OWLOntologyChangeListener;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.SWRLBuiltInAtom;
import org.semanticweb.owlapi.model.SWRLRule;
import org.semanticweb.owlapi.profiles.OWL2DLProfile;
import org.semanticweb.owlapi.profiles.OWL2ELProfile;
import org.semanticweb.owlapi.profiles.OWLProfile;
import org.semanticweb.owlapi.profiles.OWLProfileViolation;
import org.semanticweb.owlapi.profiles.violations.OntologyIRINotAbsolute;
import org.semanticweb.owlapi.profiles.violations.OntologyVersionIRINotAbsolute;
import org.semanticweb.owlapi.profiles.violations.UndeclaredEntityViolation;
import org.semanticweb.owlapi.profiles.violations.UseOfIllegalAxiom;
import org.semanticweb.owlapi.profiles.violations.UseOfIllegalClassExpression;
import org.semanticweb.owlapi.profiles.violations.UseOfIllegalDataRange;
import org.semanticweb.owlapi.profiles.violations.UseOfNonAbsoluteIRI;
import org.semanticweb.owlapi.profiles.violations.UseOfObjectPropertyInverse;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Which axioms of a reference's ontology its reasoner will not use, found by the OWL API's profile
 * checkers: ELK reasons in OWL 2 EL and skips what lies outside it (universal restrictions,
 * cardinalities, negation, unions, inverses, SWRL rules, datatypes outside EL...); JFact has no
 * SWRL; every reasoner here works in OWL 2 DL and may skip or misread what lies outside it.
 * HermiT refuses SWRL built-ins outright (210 at LOAD), so they never reach this list.
 *
 * <p>Checked over the imports closure when the reference opens, then kept up to date as axioms
 * are added and removed: each added axiom is checked alone (so a violation that only the whole
 * ontology shows, such as a property made non-simple by a later axiom, is found at the next LOAD).
 * Axioms in every profile (declarations, annotations, named class and object property
 * assertions) are not checked again. Plugin reasoners (named by class) are not described.
 */
public final class ReasonerCoverage implements OWLOntologyChangeListener {
    private static final Logger LOG = LoggerFactory.getLogger(ReasonerCoverage.class);
    private static final int KINDS_SHOWN = 6;
    private static final Map<String, String> EXPRESSIONS = Map.ofEntries(
            Map.entry("ObjectAllValuesFrom", "universal restriction (only)"),
            Map.entry("DataAllValuesFrom", "universal restriction (only)"),
            Map.entry("ObjectMinCardinality", "cardinality"), Map.entry("ObjectMaxCardinality", "cardinality"),
            Map.entry("ObjectExactCardinality", "cardinality"), Map.entry("DataMinCardinality", "cardinality"),
            Map.entry("DataMaxCardinality", "cardinality"), Map.entry("DataExactCardinality", "cardinality"),
            Map.entry("ObjectComplementOf", "negation (not)"), Map.entry("ObjectUnionOf", "union (or)"),
            Map.entry("ObjectOneOf", "enumeration (oneOf)"), Map.entry("ObjectHasSelf", "self restriction"));

    private final String reasoner;
    private final OWLOntology ontology;
    private final OWLProfile profile;
    private final boolean rulesUnused;
    private final String profileName;
    private final Map<OWLAxiom, Set<String>> unused = new HashMap<>();
    private final Map<String, Integer> kindCounts = new HashMap<>();
    // A data property assertion on named entities is in a profile or not by its literal's datatype alone.
    private final Map<OWLDatatype, Set<String>> kindsOfDataAssertions = new HashMap<>();
    private final OWLOntologyManager scratch = OWLManager.createOWLOntologyManager();
    private volatile String summary = "";

    private ReasonerCoverage(String reasoner, OWLOntology ontology, OWLProfile profile, boolean rulesUnused) {
        this.reasoner = reasoner;
        this.ontology = ontology;
        this.profile = profile;
        this.rulesUnused = rulesUnused;
        if (profile == null) {
            profileName = "";
            return;
        }
        List<OWLProfileViolation> violations = profile.checkOntology(ontology).getViolations();
        record(violations);
        if (rulesUnused) {
            ontology.axioms(AxiomType.SWRL_RULE, org.semanticweb.owlapi.model.parameters.Imports.INCLUDED)
                    .forEach(rule -> markUnused(rule, "SWRL rule"));
        }
        boolean within = violations.stream().noneMatch(ReasonerCoverage::aboutReasoning);
        profileName = (within ? "" : "outside ") + profile.getName();
        summary = describe();
    }

    /**
     * The coverage of {@code reasonerName} over {@code ontology}, kept up to date by listening to
     * its manager until {@link #close()}.
     */
    public static ReasonerCoverage watch(String reasonerName, OWLOntology ontology) {
        ReasonerCoverage coverage = switch (reasonerName) {
            case "ELK" -> new ReasonerCoverage(reasonerName, ontology, new OWL2ELProfile(), false);
            case "JFACT" -> new ReasonerCoverage(reasonerName, ontology, new OWL2DLProfile(), true);
            case "HERMIT", "PELLET", "OPENLLET" -> new ReasonerCoverage(reasonerName, ontology,
                    new OWL2DLProfile(), false);
            default -> new ReasonerCoverage(reasonerName, ontology, null, false);
        };
        if (coverage.profile != null) {
            ontology.getOWLOntologyManager().addOntologyChangeListener(coverage);
            LOG.info("ontology {}: {}{}", ontology.getOntologyID().getOntologyIRI().map(Object::toString)
                    .orElse("(anonymous)"), coverage.profileName, coverage.summary.isEmpty() ? ""
                    : "; " + coverage.summary);
        }
        return coverage;
    }

    /** Stops following the ontology's changes. */
    public void close() {
        if (profile != null) {
            ontology.getOWLOntologyManager().removeOntologyChangeListener(this);
        }
    }

    /** The profile checked for the reasoner: "OWL 2 EL" for ELK, "OWL 2 DL" otherwise, "outside ..." if not. */
    public String profileName() {
        return profileName;
    }

    /** How many of the ontology's axioms the reasoner does not use. */
    public synchronized int unusedAxioms() {
        return unused.size();
    }

    /**
     * Empty when the reasoner uses every axiom, else what it does not use, such as {@code ELK does
     * not use 3 axioms: 2 universal restriction (only), 1 SWRL rule}. Safe to read from any thread.
     */
    public String summary() {
        return summary;
    }

    /** What a LOAD says after the profile on success (empty when nothing is left unused). */
    public String unusedReport() {
        String now = summary;
        return now.isEmpty() ? "" : now + "; answers may be incomplete";
    }

    @Override
    public void ontologiesChanged(List<? extends OWLOntologyChange> changes) {
        Set<OWLOntology> closure = ontology.importsClosure().collect(Collectors.toSet());
        List<OWLAxiom> added = new ArrayList<>();
        boolean changed = false;
        synchronized (this) {
            for (OWLOntologyChange change : changes) {
                if (!change.isAxiomChange() || !closure.contains(change.getOntology())) {
                    continue;
                }
                OWLAxiom axiom = change.getAxiom();
                if (change.isRemoveAxiom()) {
                    changed |= markUsed(axiom);
                } else if (axiom instanceof OWLDataPropertyAssertionAxiom assertion && named(assertion)) {
                    Set<String> kinds = kindsOfDataAssertions.computeIfAbsent(assertion.getObject().getDatatype(),
                            datatype -> kindsAlone(assertion));
                    for (String kind : kinds) {
                        changed |= markUnused(axiom, kind);
                    }
                } else if (!inEveryProfile(axiom)) {
                    added.add(axiom);
                }
            }
            if (!added.isEmpty()) {
                changed |= check(added);
            }
            if (changed) {
                summary = describe();
            }
        }
    }

    private boolean check(Collection<OWLAxiom> axioms) {
        boolean changed = record(violationsAlone(axioms));
        if (rulesUnused) {
            for (OWLAxiom rule : axioms) {
                if (rule.isOfType(AxiomType.SWRL_RULE)) {
                    changed |= markUnused(rule, "SWRL rule");
                }
            }
        }
        return changed;
    }

    /** The profile's violations among {@code axioms}, checked as an ontology of their own. */
    private List<OWLProfileViolation> violationsAlone(Collection<OWLAxiom> axioms) {
        try {
            OWLOntology alone = scratch.createOntology(axioms.stream());
            try {
                return profile.checkOntology(alone).getViolations();
            } finally {
                scratch.removeOntology(alone);
            }
        } catch (OWLOntologyCreationException e) {
            LOG.debug("could not check added axioms against {}", profile.getName(), e);
            return List.of();
        }
    }

    private Set<String> kindsAlone(OWLAxiom axiom) {
        return violationsAlone(List.of(axiom)).stream().filter(ReasonerCoverage::aboutReasoning)
                .map(ReasonerCoverage::kind).collect(Collectors.toCollection(LinkedHashSet::new));
    }

    private boolean record(List<OWLProfileViolation> violations) {
        boolean changed = false;
        for (OWLProfileViolation violation : violations) {
            if (aboutReasoning(violation)) {
                changed |= markUnused(violation.getAxiom(), kind(violation));
            }
        }
        return changed;
    }

    private boolean markUnused(OWLAxiom axiom, String kind) {
        if (!unused.computeIfAbsent(axiom, a -> new LinkedHashSet<>()).add(kind)) {
            return false;
        }
        kindCounts.merge(kind, 1, Integer::sum);
        return true;
    }

    private boolean markUsed(OWLAxiom axiom) {
        Set<String> kinds = unused.remove(axiom);
        if (kinds == null) {
            return false;
        }
        kinds.forEach(kind -> kindCounts.computeIfPresent(kind, (k, count) -> count > 1 ? count - 1 : null));
        return true;
    }

    private static boolean named(OWLDataPropertyAssertionAxiom assertion) {
        return !assertion.getProperty().isAnonymous() && !assertion.getSubject().isAnonymous();
    }

    /** Whether a violation is about what a reasoner can use, not about declarations or IRI forms. */
    private static boolean aboutReasoning(OWLProfileViolation violation) {
        return !(violation instanceof UndeclaredEntityViolation
                || violation instanceof OntologyIRINotAbsolute || violation instanceof OntologyVersionIRINotAbsolute
                || violation instanceof UseOfNonAbsoluteIRI) && aboutAnAxiom(violation);
    }

    /** The OWL API's getAxiom throws, rather than answer null, for a violation about the ontology itself. */
    private static boolean aboutAnAxiom(OWLProfileViolation violation) {
        try {
            return violation.getAxiom() != null;
        } catch (IllegalStateException e) {
            return false;
        }
    }

    /** Axioms within OWL 2 EL and DL whatever their content, so never checked one by one. */
    private static boolean inEveryProfile(OWLAxiom axiom) {
        if (axiom.isOfType(AxiomType.DECLARATION) || axiom.isAnnotationAxiom()) {
            return true;
        }
        if (axiom instanceof OWLClassAssertionAxiom assertion) {
            return !assertion.getClassExpression().isAnonymous() && !assertion.getIndividual().isAnonymous();
        }
        if (axiom instanceof OWLObjectPropertyAssertionAxiom assertion) {
            return !assertion.getProperty().isAnonymous() && !assertion.getSubject().isAnonymous()
                    && !assertion.getObject().isAnonymous();
        }
        return false;
    }

    /** A short name for what a violation is about: the construct, as a user would look for it. */
    private static String kind(OWLProfileViolation violation) {
        if (violation instanceof UseOfIllegalClassExpression) {
            String type = ((OWLClassExpression) violation.getExpression()).getClassExpressionType().getName();
            return EXPRESSIONS.getOrDefault(type, type);
        }
        if (violation instanceof UseOfObjectPropertyInverse) {
            return "inverse property";
        }
        if (violation instanceof UseOfIllegalDataRange) {
            Object range = violation.getExpression();
            return "datatype " + (range instanceof OWLDatatype datatype ? "xsd:" + datatype.getIRI().getShortForm()
                    : range);
        }
        if (violation instanceof UseOfIllegalAxiom) {
            OWLAxiom axiom = violation.getAxiom();
            if (axiom instanceof SWRLRule rule) {
                return rule.body().anyMatch(SWRLBuiltInAtom.class::isInstance) ? "SWRL rule with built-ins"
                        : "SWRL rule";
            }
            return axiom.getAxiomType().getName() + " axiom";
        }
        String name = violation.getClass().getSimpleName().replaceFirst("^UseOf", "");
        return name.replaceAll("([a-z])([A-Z])", "$1 $2").toLowerCase(java.util.Locale.ROOT);
    }

    private String describe() {
        if (unused.isEmpty()) {
            return "";
        }
        List<Map.Entry<String, Integer>> sorted = kindCounts.entrySet().stream()
                .sorted(Map.Entry.<String, Integer>comparingByValue(Comparator.reverseOrder())
                        .thenComparing(Map.Entry.comparingByKey())).toList();
        String kinds = sorted.stream().limit(KINDS_SHOWN).map(e -> e.getValue() + " " + e.getKey())
                .collect(Collectors.joining(", ")) + (sorted.size() > KINDS_SHOWN ? ", ..." : "");
        int count = unused.size();
        return reasoner + " does not use " + count + (count == 1 ? " axiom" : " axioms")
                + (profile instanceof OWL2ELProfile ? " outside OWL 2 EL" : "") + ": " + kinds;
    }
}
