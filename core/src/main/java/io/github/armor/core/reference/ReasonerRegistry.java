// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import openllet.owlapi.OpenlletReasonerFactory;
import org.semanticweb.elk.owlapi.ElkReasonerFactory;
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

    private ReasonerRegistry() {}

    /**
     * The canonical name of a reasoner: one of the known names upper-cased, or the class name as given.
     *
     * @throws ArmorException REASONER_FAILED when the name is neither known nor a loadable factory class
     */
    public static String canonicalName(String name, String defaultName) {
        String chosen = name == null || name.isBlank() ? defaultName : name.trim();
        String upper = chosen.toUpperCase(Locale.ROOT);
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
            Class<?> type = Class.forName(canonicalName);
            if (!OWLReasonerFactory.class.isAssignableFrom(type)) {
                throw new ArmorException(ExitCode.REASONER_FAILED,
                        "reasoner '" + canonicalName + "' is a class but not an OWLReasonerFactory");
            }
            return (OWLReasonerFactory) type.getDeclaredConstructor().newInstance();
        } catch (ClassNotFoundException e) {
            throw new ArmorException(ExitCode.REASONER_FAILED, "unknown reasoner '" + canonicalName
                    + "': expected HERMIT, PELLET, JFACT, ELK or an OWLReasonerFactory class name");
        } catch (ReflectiveOperationException | LinkageError e) {
            throw new ArmorException(ExitCode.REASONER_FAILED,
                    "reasoner factory '" + canonicalName + "' could not be created: " + e, e);
        }
    }
}
