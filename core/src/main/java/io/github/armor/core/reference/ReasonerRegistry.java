// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import openllet.owlapi.OpenlletReasonerFactory;
import org.semanticweb.elk.owlapi.ElkReasonerFactory;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.SimpleConfiguration;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import uk.ac.manchester.cs.jfact.JFactFactory;

/** Turns a reasoner name from a directive into an {@link OWLReasonerFactory}. */
public final class ReasonerRegistry {
    private static final Map<String, Supplier<OWLReasonerFactory>> KNOWN = Map.of(
            "HERMIT", org.semanticweb.HermiT.ReasonerFactory::new,
            "PELLET", OpenlletReasonerFactory::getInstance,
            "OPENLLET", OpenlletReasonerFactory::getInstance,
            "JFACT", JFactFactory::new,
            "ELK", ElkReasonerFactory::new);

    // ROS 1 ARMOR's own names (armor_api documents them): FaCT++ is what JFact ports to Java, and
    // Snorocket was ARMOR's OWL 2 EL classifier, whose place ELK takes here.
    private static final Map<String, String> ARMOR_NAMES = Map.of("FACT", "JFACT", "SNOROCKET", "ELK");

    // Complete OWL 2 DL reasoners, the most capable first (Openllet also applies SWRL built-ins).
    // ELK is never proposed: it accepts almost anything by ignoring what is not EL.
    private static final List<String> ALTERNATIVES = List.of("PELLET", "HERMIT", "JFACT");
    private static final long TRIAL_MS = 10_000;
    // Where factory class names are looked up: the core's class path, plus the jars of plugin_dirs once set.
    private static volatile ClassLoader classLoader = ReasonerRegistry.class.getClassLoader();

    private ReasonerRegistry() {}

    /** Looks reasoner factory classes up in {@code loader} (the plugin directory's) from now on. */
    public static void useClassLoader(ClassLoader loader) {
        classLoader = loader;
    }

    /**
     * What to add to a refusal by {@code refused}: the first other complete reasoner that starts
     * on the ontology and checks its consistency within a few seconds, tried for real, so the
     * name given is one that accepts it. Runs only when a reasoner refused, never on success.
     */
    public static String acceptingAlternative(String refused, OWLOntology ontology) {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(TRIAL_MS);
        for (String candidate : ALTERNATIVES) {
            long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
            if (candidate.equalsIgnoreCase(refused) || left <= 0) {
                continue;
            }
            if (accepts(candidate, ontology, left)) {
                return "; " + candidate + " accepts this ontology (name it as the reasoner argument of LOAD, or set"
                        + " the node's default_reasoner)";
            }
        }
        return "; no other reasoner here accepted it within " + TRIAL_MS / 1000 + " s either";
    }

    private static boolean accepts(String candidate, OWLOntology ontology, long timeLimitMs) {
        // Its own limit, not the directive's: the trial runs because a reasoner already refused.
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeLimitMs);
        Optional<OWLReasoner> reasoner = Optional.empty();
        try {
            reasoner = Optional.of(ReasonerCalls.run(null, deadline,
                    () -> factory(candidate).createReasoner(ontology, new SimpleConfiguration())));
            OWLReasoner started = reasoner.get();
            ReasonerCalls.run(started, deadline, started::isConsistent);
            return true;
        } catch (ReasonerCalls.Overran e) {
            if (e.abandoned()) {
                reasoner = Optional.empty(); // the abandoned call disposes it
            }
            return false;
        } catch (RuntimeException | LinkageError e) {
            return false;
        } finally {
            reasoner.ifPresent(r -> {
                try {
                    r.dispose();
                } catch (RuntimeException e) {
                    // a trial reasoner that fails to dispose is dropped all the same
                }
            });
        }
    }

    /**
     * The canonical name of a reasoner: one of the known names upper-cased, or the class name as given.
     *
     * @throws ArmorException REASONER_FAILED when the name is neither known nor a loadable factory class
     */
    public static String canonicalName(String name, String defaultName) {
        String chosen = name == null || name.isBlank() ? defaultName : name.trim();
        String upper = chosen.toUpperCase(Locale.ROOT);
        upper = ARMOR_NAMES.getOrDefault(upper, upper);
        if (KNOWN.containsKey(upper)) {
            return upper;
        }
        factory(chosen);
        return chosen;
    }

    /** A fresh factory for a canonical name. */
    public static OWLReasonerFactory factory(String canonicalName) {
        Supplier<OWLReasonerFactory> known = KNOWN.get(canonicalName.toUpperCase(Locale.ROOT));
        if (known != null) {
            return known.get();
        }
        try {
            Class<?> type = Class.forName(canonicalName, true, classLoader);
            if (!OWLReasonerFactory.class.isAssignableFrom(type)) {
                throw new ArmorException(ExitCode.REASONER_FAILED,
                        "reasoner '" + canonicalName + "' is a class but not an OWLReasonerFactory");
            }
            return (OWLReasonerFactory) type.getDeclaredConstructor().newInstance();
        } catch (ClassNotFoundException e) {
            throw new ArmorException(ExitCode.REASONER_FAILED, "unknown reasoner '" + canonicalName
                    + "': expected HERMIT, PELLET, JFACT, ELK or an OWLReasonerFactory class name (on the core's"
                    + " class path or in a jar of plugin_dirs)");
        } catch (ReflectiveOperationException | LinkageError e) {
            throw new ArmorException(ExitCode.REASONER_FAILED,
                    "reasoner factory '" + canonicalName + "' could not be created: " + e, e);
        }
    }
}
