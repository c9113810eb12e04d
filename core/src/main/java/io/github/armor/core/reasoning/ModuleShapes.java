// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.AboxModules.Module;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClassAssertionAxiom;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLDataPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLIndividual;
import org.semanticweb.owlapi.model.OWLLiteral;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLNaryIndividualAxiom;
import org.semanticweb.owlapi.model.OWLObjectPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.OWLPropertyAssertionAxiom;
import org.semanticweb.owlapi.model.OWLSubDataPropertyOfAxiom;
import org.semanticweb.owlapi.util.OWLObjectDuplicator;
import org.semanticweb.owlapi.vocab.OWL2Datatype;

/**
 * Modules that are the same up to the names of their individuals: a room with three robots in it
 * has the types every room with three robots has, so it is reasoned on once.
 *
 * <p>A module's shape is its assertions with its individuals renamed to placeholders, in an
 * order found from what each individual's assertions say. Two modules with equal shapes are
 * images of each other under a renaming of individuals, and OWL semantics does not depend on
 * names, so the reasoner's answer for one, renamed, is its answer for the other. The order only
 * decides how often shapes match: a tie broken differently gives a different shape (one more
 * module reasoned on), never a wrong answer. The shape is taken after the module's twins are
 * collapsed ({@link ModuleTwins}): a drawer with five cups has the shape of a drawer with one.
 *
 * <p>Data values are renamed too where the schema cannot tell one from another: a property
 * ({@link #blind}) that no schema axiom mentions but to say it is functional, has a domain, or
 * sits in a hierarchy of such properties. What the schema says of such values is only how many
 * distinct ones an individual has, so a renaming of a module's values that keeps them distinct
 * where they were (one numbering per module, by value: 1 and 1.0 stay equal) and keeps each
 * literal's datatype and validity maps models to models: the robot's clock at 1040 and at 1080
 * is one shape, reasoned on once. Only literals that are valid integers, decimals or strings are
 * renamed (an ill-typed literal makes an ontology inconsistent; a placeholder would not), and a
 * module whose other assertions mention a data property keeps its values.
 */
final class ModuleShapes {
    /** Modules larger than this, once their twins are collapsed, are not compared (rarely repeated, and costly to rename). */
    static final int LARGEST = 64;
    /** Modules larger than this are not even collapsed (one reasoner batch holds them). */
    private static final int COLLAPSED_AT_MOST = ModuleRealiser.BATCH_INDIVIDUALS;
    private static final int KEPT = 4096;
    private static final String PLACEHOLDER = "urn:armor:reasoning#individual";
    // Compiled once: a LOAD checks the literals of every module.
    private static final java.util.regex.Pattern INTEGER = java.util.regex.Pattern.compile("[+-]?[0-9]+");
    private static final java.util.regex.Pattern DECIMAL =
            java.util.regex.Pattern.compile("[+-]?([0-9]+(\\.[0-9]*)?|\\.[0-9]+)");

    /**
     * A module's shape (null when not compared: too large), its kept members in placeholder
     * order, and the module with its twins collapsed, which is what a reasoner is given.
     */
    record Shape(Set<OWLAxiom> key, List<OWLNamedIndividual> order, ModuleTwins.Collapsed collapsed) {}

    /** What reasoning on a shape gave: consistency, and the types by placeholder. */
    private record Outcome(boolean consistent, List<TypeProfile> types) {}

    private final OWLOntologyManager manager;
    private final ModuleTwins twins;
    private final Map<Set<OWLAxiom>, Outcome> known = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Set<OWLAxiom>, Outcome> eldest) {
            return size() > KEPT;
        }
    };

    private long reused;
    private final Set<OWLDataProperty> seen = new HashSet<>();
    private final Map<OWLDataProperty, Set<OWLDataProperty>> related = new HashMap<>();
    private final Map<OWLDataProperty, Boolean> blindness = new java.util.concurrent.ConcurrentHashMap<>();

    /** @param schema what every module is reasoned with (it decides which values are {@link #blind}) */
    ModuleShapes(OWLOntologyManager manager, List<OWLAxiom> schema) {
        this.manager = manager;
        this.twins = new ModuleTwins(manager);
        for (OWLAxiom axiom : schema) {
            if (!axiom.isLogicalAxiom()) {
                continue;
            }
            if (axiom instanceof OWLSubDataPropertyOfAxiom || axiom.isOfType(AxiomType.EQUIVALENT_DATA_PROPERTIES)) {
                List<OWLDataProperty> members = axiom.dataPropertiesInSignature().toList();
                members.forEach(a -> members.forEach(b -> related.computeIfAbsent(a, k -> new HashSet<>()).add(b)));
            } else if (!axiom.isOfType(AxiomType.FUNCTIONAL_DATA_PROPERTY, AxiomType.DATA_PROPERTY_DOMAIN)) {
                axiom.dataPropertiesInSignature().forEach(seen::add);
            }
        }
    }

    /** Whether the schema cannot tell one value of the property from another (nor of any property in its hierarchy). */
    private boolean blind(OWLDataProperty property) {
        return blindness.computeIfAbsent(property, this::blindInSchema);
    }

    private boolean blindInSchema(OWLDataProperty property) {
        Set<OWLDataProperty> reached = new HashSet<>(Set.of(property));
        List<OWLDataProperty> frontier = new ArrayList<>(reached);
        while (!frontier.isEmpty()) {
            OWLDataProperty next = frontier.remove(frontier.size() - 1);
            if (seen.contains(next)) {
                return false;
            }
            for (OWLDataProperty other : related.getOrDefault(next, Set.of())) {
                if (reached.add(other)) {
                    frontier.add(other);
                }
            }
        }
        return true;
    }

    /** The module's assertions with the values of blind properties numbered in order of first appearance. */
    private Set<OWLAxiom> valuesRenamed(Set<OWLAxiom> axioms) {
        for (OWLAxiom axiom : axioms) {
            if (!(axiom instanceof OWLDataPropertyAssertionAxiom) && mentionsDataProperty(axiom)) {
                return axioms;
            }
        }
        OWLDataFactory data = manager.getOWLDataFactory();
        Map<Builtins.DataValue, Integer> numbers = new HashMap<>();
        Set<OWLAxiom> renamed = new LinkedHashSet<>();
        for (OWLAxiom axiom : axioms) {
            if (axiom instanceof OWLDataPropertyAssertionAxiom value && renameable(value.getObject())
                    && blind(value.getProperty().asOWLDataProperty())) {
                int number = numbers.computeIfAbsent(Builtins.DataValue.of(value.getObject()), k -> numbers.size() + 1);
                axiom = data.getOWLDataPropertyAssertionAxiom(value.getProperty(), value.getSubject(),
                        data.getOWLLiteral(String.valueOf(number), value.getObject().getDatatype()));
            }
            renamed.add(axiom);
        }
        return renamed;
    }

    /** Whether an assertion names a data property (read without building the signatures of the common ones). */
    private static boolean mentionsDataProperty(OWLAxiom axiom) {
        if (axiom instanceof OWLClassAssertionAxiom assertion && assertion.getClassExpression().isOWLClass()
                || axiom instanceof OWLObjectPropertyAssertionAxiom || axiom instanceof OWLNaryIndividualAxiom) {
            return false;
        }
        return axiom.dataPropertiesInSignature().findAny().isPresent();
    }

    private static boolean renameable(OWLLiteral literal) {
        if (literal.hasLang()) {
            return false;
        }
        String text = literal.getLiteral();
        return literal.getDatatype().isString()
                || literal.getDatatype().isInteger() && INTEGER.matcher(text).matches()
                || literal.getDatatype().getIRI().equals(OWL2Datatype.XSD_DECIMAL.getIRI())
                && DECIMAL.matcher(text).matches();
    }

    /** The shape of a module with these assertions, or null when it is not collapsed (hub, size, anonymous individuals). */
    Shape shapeOf(Module module, Set<OWLAxiom> asserted) {
        // The hub's individuals are named in the schema: renaming them would change what it says.
        if (module.hub || module.members.size() > COLLAPSED_AT_MOST
                || module.members.stream().anyMatch(OWLIndividual::isAnonymous)) {
            return null;
        }
        ModuleTwins.Collapsed collapsed = twins.collapse(module, asserted);
        List<OWLNamedIndividual> kept = collapsed.kept();
        if (kept.size() > LARGEST) {
            return new Shape(null, kept, collapsed);
        }
        Set<OWLAxiom> axioms = valuesRenamed(collapsed.axioms());
        // Most modules have one individual: there is no order to find.
        List<OWLNamedIndividual> order = kept.size() == 1 ? kept : orderOfMembers(kept, axioms);
        Map<OWLEntity, IRI> renaming = new HashMap<>();
        for (int i = 0; i < order.size(); i++) {
            renaming.put(order.get(i), IRI.create(PLACEHOLDER + i));
        }
        OWLObjectDuplicator renamer = new OWLObjectDuplicator(renaming, manager);
        Set<OWLAxiom> key = new LinkedHashSet<>();
        for (OWLAxiom axiom : axioms) {
            key.add(renamer.duplicateObject(axiom));
        }
        return new Shape(Set.copyOf(key), List.copyOf(order), collapsed);
    }

    /** The members ordered by what their assertions say (ties by IRI). */
    private static List<OWLNamedIndividual> orderOfMembers(List<OWLNamedIndividual> members, Set<OWLAxiom> axioms) {
        Map<OWLIndividual, List<Long>> roles = new HashMap<>();
        for (OWLAxiom axiom : axioms) {
            List<OWLIndividual> about = AboxLinks.individualsOf(axiom).toList();
            long what = describe(axiom);
            for (int position = 0; position < about.size(); position++) {
                roles.computeIfAbsent(about.get(position), k -> new ArrayList<>()).add(what * 8 + position);
            }
        }
        Map<OWLNamedIndividual, String> signature = new HashMap<>();
        members.forEach(member -> {
            List<Long> own = roles.getOrDefault(member, new ArrayList<>());
            own.sort(null);
            signature.put(member, own.toString());
        });
        List<OWLNamedIndividual> order = new ArrayList<>(signature.keySet());
        order.sort(Comparator.comparing((OWLNamedIndividual member) -> signature.get(member))
                .thenComparing(member -> member.getIRI().toString()));
        return order;
    }

    /** The result for a module whose shape (a compared one: its key is set) was reasoned on before, or null. */
    ModuleRealiser.Realised lookup(Module module, Shape shape) {
        Outcome outcome = known.get(shape.key());
        if (outcome == null) {
            return null;
        }
        reused++;
        if (!outcome.consistent()) {
            return new ModuleRealiser.Realised(module, false, Map.of());
        }
        Map<OWLNamedIndividual, TypeProfile> types = new LinkedHashMap<>();
        for (int i = 0; i < shape.order().size(); i++) {
            types.put(shape.order().get(i), outcome.types().get(i));
        }
        return new ModuleRealiser.Realised(module, true, shape.collapsed().spread(types));
    }

    /** How many modules took the result of an earlier one (tests check that this path runs). */
    long reused() {
        return reused;
    }

    /** The result of module {@code from} (shape {@code fromShape}) for module {@code to} of the same shape. */
    ModuleRealiser.Realised transfer(ModuleRealiser.Realised from, Shape fromShape, Module to, Shape toShape) {
        reused++;
        if (!from.consistent()) {
            return new ModuleRealiser.Realised(to, false, Map.of());
        }
        Map<OWLNamedIndividual, TypeProfile> types = new LinkedHashMap<>();
        for (int i = 0; i < toShape.order().size(); i++) {
            types.put(toShape.order().get(i), from.types().get(fromShape.order().get(i)));
        }
        return new ModuleRealiser.Realised(to, true, toShape.collapsed().spread(types));
    }

    void remember(Shape shape, ModuleRealiser.Realised realised) {
        if (shape.key() == null) {
            return;
        }
        List<TypeProfile> types = realised.consistent()
                ? shape.order().stream().map(realised.types()::get).toList() : List.of();
        known.put(shape.key(), new Outcome(realised.consistent(), types));
    }

    /**
     * What an assertion says apart from its individuals, as a number for ordering them (content
     * hash codes: equal assertions up to individuals give equal numbers; a collision only costs
     * a missed match).
     */
    private static long describe(OWLAxiom axiom) {
        long kind = axiom.getAxiomType().getIndex();
        if (axiom instanceof OWLClassAssertionAxiom assertion) {
            return kind << 32 | assertion.getClassExpression().hashCode() & 0xffffffffL;
        }
        if (axiom instanceof OWLPropertyAssertionAxiom<?, ?> assertion) {
            int value = assertion.getObject() instanceof OWLIndividual ? 0 : assertion.getObject().hashCode();
            return kind << 32 | (assertion.getProperty().hashCode() * 31 + value) & 0xffffffffL;
        }
        return kind << 32;
    }
}
