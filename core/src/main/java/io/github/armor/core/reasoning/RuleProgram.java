// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.Builtins.DataValue;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLDataPropertyExpression;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLObjectPropertyExpression;
import org.semanticweb.owlapi.model.OWLSubDataPropertyOfAxiom;
import org.semanticweb.owlapi.model.OWLSubObjectPropertyOfAxiom;
import org.semanticweb.owlapi.model.SWRLArgument;
import org.semanticweb.owlapi.model.SWRLAtom;
import org.semanticweb.owlapi.model.SWRLBuiltInAtom;
import org.semanticweb.owlapi.model.SWRLClassAtom;
import org.semanticweb.owlapi.model.SWRLDataPropertyAtom;
import org.semanticweb.owlapi.model.SWRLDifferentIndividualsAtom;
import org.semanticweb.owlapi.model.SWRLIndividualArgument;
import org.semanticweb.owlapi.model.SWRLLiteralArgument;
import org.semanticweb.owlapi.model.SWRLObjectPropertyAtom;
import org.semanticweb.owlapi.model.SWRLRule;
import org.semanticweb.owlapi.model.SWRLSameIndividualAtom;
import org.semanticweb.owlapi.model.SWRLVariable;

/**
 * An ontology's SWRL rules, read for evaluation beside the modules ({@link RuleEngine}), or why
 * they cannot be, in which case the whole ontology is reasoned on by a reasoner that implements
 * rules (Openllet does, built-ins included; HermiT does without built-ins).
 *
 * <h2>Why evaluating rules on entailed facts gives Openllet's answers</h2>
 * Openllet reads DL-safe rules as first-order clauses over named individuals: a conclusion is
 * entailed when it holds in every model. The rules are evaluated here instead on the facts the
 * ontology entails, until nothing new follows: the types the modules give (without the rules'
 * conclusions, see below), the asserted property edges and data values with those the rules
 * concluded, carried up the property hierarchy (sub-properties, equivalences, inverses, symmetry),
 * and the asserted DifferentIndividuals. Every conclusion found is entailed (each rule is sound
 * for named individuals, and so is each fact it read). The converse holds when the ontology has
 * a model in which the facts the rules read hold only where entailed: then the rules hold in that
 * model (a body that matches in it matches on entailed facts, whose conclusion was added), so it
 * is a model of everything in which nothing more holds. Such a model exists when:
 * <ul>
 * <li>the schema is Horn and can make no two named individuals equal ({@link HornSchema}): it then
 *     has a canonical model, in which anonymous elements hang below named ones in trees;</li>
 * <li>no edge of a property a rule reads can come from anything but assertions and conclusions
 *     through the hierarchy: nothing transitive, reflexive, chained, hasValue or self below it
 *     (a path through the trees, or to a named individual, would make edges between named
 *     individuals), and no value of a data property a rule reads is made by a class expression
 *     (hasValue, some values, cardinalities);</li>
 * <li>a DifferentIndividuals atom is matched only on individuals asserted different or the same
 *     name: a pair that is neither can be equal in some models and not in others, which is a
 *     choice; the engine then reports it and the whole ontology is reasoned on;</li>
 * <li>conclusions do not feed one another in a cycle (counting derivations, which is how the
 *     engine retracts, would keep a fact that only supports itself), and the types a rule reads
 *     are the same with and without the conclusions (the modules check that after each change:
 *     a conclusion URGENT ⊑ Room about a room that is a Room anyway changes nothing a rule reads;
 *     one that makes a rule's class true is a chain of rules through classes, reasoned on whole).
 *     With that, the types without conclusions are the types with them, and evaluating on the
 *     former cannot let a conclusion support itself.</li>
 * </ul>
 * Only the built-ins of {@link Builtins} are evaluated, and every variable must be bound by an
 * atom of the body (DL safety) or computed by an arithmetic built-in, whose results are read
 * only by other built-ins (a value written by a rule must be one the ontology holds).
 */
final class RuleProgram {
    /** A term of an atom: a variable (by number) or a constant (a named individual or a data value). */
    record Term(int variable, Object constant) {
        static Term variable(int number) {
            return new Term(number, null);
        }

        static Term constant(Object value) {
            return new Term(-1, value);
        }

        boolean isVariable() {
            return variable >= 0;
        }
    }

    enum Kind { CLASS, EDGE, VALUE, BUILTIN, DIFFERENT, SAME }

    /** One atom: a class, object or data property with its terms, a built-in, or (in)equality. */
    record Atom(Kind kind, Object predicate, Term[] terms) {
        Term term(int index) {
            return terms[index];
        }
    }

    /**
     * A rule: its atoms, and for each body atom that a fact can match, the order in which the
     * other atoms are joined once it is bound.
     */
    record Rule(SWRLRule source, int variables, List<Atom> body, List<Atom> head, int[][] plans) {}

    final List<Rule> rules;
    final Set<OWLClass> bodyClasses;
    /** For each asserted or concluded property, the read or concluded properties its edges are edges of. */
    private final Map<OWLObjectProperty, List<Image>> edgeImages = new HashMap<>();
    private final Map<OWLDataProperty, Set<OWLDataProperty>> valueImages = new HashMap<>();
    private final PropertyHierarchy hierarchy;
    final Set<OWLObjectProperty> edgeProperties;
    final Set<OWLDataProperty> valueProperties;
    private final Set<OWLEntity> schemaSignature;
    final boolean readsDifference;

    /** Where an edge of a property lands: a property kept here, in the same direction or reversed. */
    record Image(OWLObjectProperty property, boolean reversed) {}

    private RuleProgram(List<Rule> rules, PropertyHierarchy hierarchy, Set<OWLObjectProperty> edgeProperties,
                        Set<OWLDataProperty> valueProperties, Set<OWLEntity> schemaSignature) {
        this.rules = rules;
        this.hierarchy = hierarchy;
        this.edgeProperties = edgeProperties;
        this.valueProperties = valueProperties;
        this.schemaSignature = schemaSignature;
        Set<OWLClass> classes = new HashSet<>();
        boolean difference = false;
        for (Rule rule : rules) {
            for (Atom atom : rule.body) {
                if (atom.kind == Kind.CLASS) {
                    classes.add((OWLClass) atom.predicate);
                }
                difference |= atom.kind == Kind.DIFFERENT;
            }
        }
        this.bodyClasses = Set.copyOf(classes);
        this.readsDifference = difference;
    }

    /** The program, or why the rules must be left to a reasoner on the whole ontology. */
    record Compiled(RuleProgram program, String obstacle) {}

    /**
     * @param schema      the logical axioms that are not assertions nor rules
     * @param rules       the SWRL rules
     * @param aboxShapes  the ABox axioms that bear on Horn-ness and equality: sameness, class
     *                    assertions on class expressions
     * @param links       the ABox's links under that schema
     */
    static Compiled compile(List<OWLAxiom> schema, List<SWRLRule> rules, List<OWLAxiom> aboxShapes, AboxLinks links) {
        List<OWLAxiom> all = new ArrayList<>(schema);
        all.addAll(aboxShapes);
        Optional<String> notHorn = HornSchema.obstacle(all);
        if (notHorn.isPresent()) {
            return new Compiled(null, "SWRL rules with " + notHorn.get());
        }
        PropertyHierarchy hierarchy = new PropertyHierarchy(all);
        List<Rule> read = new ArrayList<>();
        Set<OWLObjectProperty> edges = new LinkedHashSet<>();
        Set<OWLDataProperty> values = new LinkedHashSet<>();
        for (SWRLRule rule : rules) {
            RuleReader reader = new RuleReader();
            Rule compiled;
            try {
                compiled = reader.read(rule);
            } catch (IllegalArgumentException e) {
                return new Compiled(null, "a SWRL rule ARMOR does not evaluate (" + e.getMessage() + "): " + rule);
            }
            for (Atom atom : compiled.body) {
                if (atom.kind == Kind.EDGE) {
                    edges.add((OWLObjectProperty) atom.predicate);
                } else if (atom.kind == Kind.VALUE) {
                    values.add((OWLDataProperty) atom.predicate);
                }
            }
            read.add(compiled);
        }
        Set<OWLObjectProperty> bodyEdges = Set.copyOf(edges);
        Set<OWLDataProperty> bodyValues = Set.copyOf(values);
        for (Rule rule : read) {
            for (Atom atom : rule.head) {
                if (atom.kind == Kind.EDGE) {
                    OWLObjectProperty property = (OWLObjectProperty) atom.predicate;
                    if (links.links(property)) {
                        return new Compiled(null, "a SWRL rule concludes " + property.getIRI().getShortForm()
                                + ", which class expressions observe");
                    }
                    edges.add(property);
                } else if (atom.kind == Kind.VALUE) {
                    values.add((OWLDataProperty) atom.predicate);
                }
            }
        }
        String unsafe = hierarchy.madeOtherwise(edges, values);
        if (unsafe != null) {
            return new Compiled(null, "SWRL rules over " + unsafe);
        }
        Set<OWLEntity> signature = new HashSet<>();
        schema.forEach(axiom -> axiom.signature().forEach(signature::add));
        RuleProgram program = new RuleProgram(List.copyOf(read), hierarchy, Set.copyOf(edges), Set.copyOf(values),
                signature);
        String cycle = program.cycle(bodyEdges, bodyValues);
        return cycle == null ? new Compiled(program, null)
                : new Compiled(null, "SWRL rules whose conclusions feed one another (" + cycle + ")");
    }

    /** The kept properties an edge of this property is an edge of. */
    List<Image> imagesOf(OWLObjectProperty property) {
        return edgeImages.computeIfAbsent(property, p -> hierarchy.edgeImages(p, edgeProperties));
    }

    /** The kept data properties a value of this property is a value of. */
    Set<OWLDataProperty> imagesOf(OWLDataProperty property) {
        return valueImages.computeIfAbsent(property, p -> hierarchy.valueImages(p, valueProperties));
    }

    /** Whether no rule body reads the kept data property twice (a replaced value can then be joined in one step). */
    boolean readOnce(OWLDataProperty property) {
        for (Rule rule : rules) {
            if (rule.body.stream().filter(atom -> atom.kind == Kind.VALUE && atom.predicate.equals(property)).count() > 1) {
                return false;
            }
        }
        return true;
    }

    /** Whether a conclusion on this predicate bears on what the modules reason (the schema mentions it). */
    boolean seenBySchema(Object predicate) {
        return predicate instanceof OWLClass || schemaSignature.contains((OWLEntity) predicate);
    }

    /** A rule whose conclusions some rule reads, in a cycle, or null. */
    private String cycle(Set<OWLObjectProperty> bodyEdges, Set<OWLDataProperty> bodyValues) {
        Map<Rule, List<Rule>> feeds = new HashMap<>();
        for (Rule from : rules) {
            for (Rule to : rules) {
                if (feeds(from, to)) {
                    feeds.computeIfAbsent(from, k -> new ArrayList<>()).add(to);
                }
            }
        }
        Set<Rule> done = new HashSet<>();
        for (Rule start : rules) {
            if (onCycle(start, feeds, new HashSet<>(), done)) {
                return start.source.toString();
            }
        }
        return null;
    }

    private boolean feeds(Rule from, Rule to) {
        for (Atom head : from.head) {
            for (Atom body : to.body) {
                if (head.kind == Kind.EDGE && body.kind == Kind.EDGE && imagesOf((OWLObjectProperty) head.predicate)
                        .stream().anyMatch(image -> image.property.equals(body.predicate))) {
                    return true;
                }
                if (head.kind == Kind.VALUE && body.kind == Kind.VALUE
                        && imagesOf((OWLDataProperty) head.predicate).contains(body.predicate)) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean onCycle(Rule rule, Map<Rule, List<Rule>> feeds, Set<Rule> path, Set<Rule> done) {
        if (path.contains(rule)) {
            return true;
        }
        if (!done.add(rule)) {
            return false;
        }
        path.add(rule);
        for (Rule next : feeds.getOrDefault(rule, List.of())) {
            if (onCycle(next, feeds, path, done)) {
                return true;
            }
        }
        path.remove(rule);
        return false;
    }

    /** Reads one SWRL rule: variables numbered, inverse properties turned round, join orders planned. */
    private static final class RuleReader {
        private final Map<IRI, Integer> variables = new HashMap<>();
        private final Set<Integer> boundByBody = new HashSet<>();

        Rule read(SWRLRule rule) {
            List<Atom> body = new ArrayList<>();
            for (SWRLAtom atom : rule.body().toList()) {
                body.add(atom(atom, false));
            }
            for (Atom atom : body) {
                if (atom.kind == Kind.CLASS || atom.kind == Kind.EDGE || atom.kind == Kind.VALUE) {
                    for (Term term : atom.terms) {
                        if (term.isVariable()) {
                            boundByBody.add(term.variable);
                        }
                    }
                }
            }
            List<Atom> head = new ArrayList<>();
            for (SWRLAtom atom : rule.head().toList()) {
                Atom read = atom(atom, true);
                for (Term term : read.terms) {
                    if (term.isVariable() && !boundByBody.contains(term.variable)) {
                        throw new IllegalArgumentException("a conclusion names a variable no property or class of the"
                                + " body binds");
                    }
                }
                head.add(read);
            }
            int[][] plans = new int[body.size()][];
            for (int i = 0; i < body.size(); i++) {
                Kind kind = body.get(i).kind;
                if (kind == Kind.CLASS || kind == Kind.EDGE || kind == Kind.VALUE) {
                    plans[i] = plan(body, i);
                }
            }
            return new Rule(rule, variables.size(), List.copyOf(body), List.copyOf(head), plans);
        }

        private Atom atom(SWRLAtom atom, boolean inHead) {
            if (atom instanceof SWRLClassAtom classAtom) {
                if (classAtom.getPredicate().isAnonymous()) {
                    throw new IllegalArgumentException("a class expression in an atom");
                }
                return new Atom(Kind.CLASS, classAtom.getPredicate().asOWLClass(),
                        new Term[] {term(classAtom.getArgument())});
            }
            if (atom instanceof SWRLObjectPropertyAtom edge) {
                OWLObjectPropertyExpression property = edge.getPredicate();
                Term first = term(edge.getFirstArgument());
                Term second = term(edge.getSecondArgument());
                return property.isAnonymous()
                        ? new Atom(Kind.EDGE, property.getNamedProperty(), new Term[] {second, first})
                        : new Atom(Kind.EDGE, property.asOWLObjectProperty(), new Term[] {first, second});
            }
            if (atom instanceof SWRLDataPropertyAtom value) {
                OWLDataPropertyExpression property = value.getPredicate();
                return new Atom(Kind.VALUE, property.asOWLDataProperty(),
                        new Term[] {term(value.getFirstArgument()), term(value.getSecondArgument())});
            }
            if (inHead) {
                throw new IllegalArgumentException("a conclusion other than a class, object or data property atom");
            }
            if (atom instanceof SWRLBuiltInAtom builtin) {
                if (!Builtins.supports(builtin.getPredicate(), builtin.getArguments().size())) {
                    throw new IllegalArgumentException("built-in " + builtin.getPredicate());
                }
                return new Atom(Kind.BUILTIN, builtin.getPredicate(),
                        builtin.getArguments().stream().map(this::term).toArray(Term[]::new));
            }
            if (atom instanceof SWRLDifferentIndividualsAtom different) {
                return new Atom(Kind.DIFFERENT, null,
                        new Term[] {term(different.getFirstArgument()), term(different.getSecondArgument())});
            }
            if (atom instanceof SWRLSameIndividualAtom same) {
                return new Atom(Kind.SAME, null, new Term[] {term(same.getFirstArgument()),
                        term(same.getSecondArgument())});
            }
            throw new IllegalArgumentException("a data range atom");
        }

        private Term term(SWRLArgument argument) {
            if (argument instanceof SWRLVariable variable) {
                return Term.variable(variables.computeIfAbsent(variable.getIRI(), k -> variables.size()));
            }
            if (argument instanceof SWRLIndividualArgument individual) {
                if (!individual.getIndividual().isNamed()) {
                    throw new IllegalArgumentException("an anonymous individual");
                }
                return Term.constant(individual.getIndividual().asOWLNamedIndividual());
            }
            if (argument instanceof SWRLLiteralArgument literal) {
                return Term.constant(DataValue.of(literal.getLiteral()));
            }
            throw new IllegalArgumentException("an argument of an unknown kind " + argument);
        }

        /**
         * The order in which the other atoms are joined after atom {@code first}: tests whose terms
         * are bound first, then lookups from a bound term, then enumerations.
         */
        private int[] plan(List<Atom> body, int first) {
            Set<Integer> bound = new HashSet<>();
            bind(body.get(first), bound);
            List<Integer> order = new ArrayList<>();
            Set<Integer> left = new LinkedHashSet<>();
            for (int i = 0; i < body.size(); i++) {
                if (i != first) {
                    left.add(i);
                }
            }
            while (!left.isEmpty()) {
                int best = -1;
                int bestCost = Integer.MAX_VALUE;
                for (int index : left) {
                    int cost = cost(body.get(index), bound);
                    if (cost < bestCost) {
                        best = index;
                        bestCost = cost;
                    }
                }
                if (bestCost == Integer.MAX_VALUE) {
                    throw new IllegalArgumentException("a built-in or (in)equality whose variables the body does not bind");
                }
                left.remove(best);
                order.add(best);
                bind(body.get(best), bound);
            }
            return order.stream().mapToInt(Integer::intValue).toArray();
        }

        private static int cost(Atom atom, Set<Integer> bound) {
            long unbound = java.util.Arrays.stream(atom.terms).filter(t -> t.isVariable() && !bound.contains(t.variable))
                    .count();
            return switch (atom.kind) {
                case BUILTIN -> {
                    boolean computes = Builtins.binds((IRI) atom.predicate);
                    boolean restBound = java.util.Arrays.stream(atom.terms).skip(computes ? 1 : 0)
                            .allMatch(t -> !t.isVariable() || bound.contains(t.variable));
                    yield restBound ? 0 : Integer.MAX_VALUE;
                }
                case DIFFERENT, SAME -> unbound == 0 ? 1 : Integer.MAX_VALUE;
                case CLASS -> unbound == 0 ? 1 : 100;
                default -> unbound == 0 ? 1 : unbound == 1 ? 10 : 1000;
            };
        }

        private static void bind(Atom atom, Set<Integer> bound) {
            if (atom.kind == Kind.DIFFERENT || atom.kind == Kind.SAME) {
                return;
            }
            for (Term term : atom.kind == Kind.BUILTIN ? new Term[] {atom.terms[0]} : atom.terms) {
                if (term.isVariable()) {
                    bound.add(term.variable);
                }
            }
        }
    }

    /** The property hierarchy of the schema, and what else can make edges or values. */
    private static final class PropertyHierarchy {
        // Sub-property to super-property, over object property expressions (P, or the inverse of P).
        private final Map<OWLObjectPropertyExpression, Set<OWLObjectPropertyExpression>> objectSupers = new HashMap<>();
        private final Map<OWLDataProperty, Set<OWLDataProperty>> dataSupers = new HashMap<>();
        private final List<OWLAxiom> axioms;

        PropertyHierarchy(List<OWLAxiom> axioms) {
            this.axioms = axioms;
            for (OWLAxiom axiom : axioms) {
                if (axiom instanceof OWLSubObjectPropertyOfAxiom sub) {
                    above(sub.getSubProperty(), sub.getSuperProperty());
                } else if (axiom.isOfType(AxiomType.EQUIVALENT_OBJECT_PROPERTIES)) {
                    List<OWLObjectPropertyExpression> members = ((org.semanticweb.owlapi.model
                            .OWLEquivalentObjectPropertiesAxiom) axiom).properties().toList();
                    members.forEach(a -> members.forEach(b -> above(a, b)));
                } else if (axiom instanceof org.semanticweb.owlapi.model.OWLInverseObjectPropertiesAxiom inverse) {
                    above(inverse.getFirstProperty(), inverse.getSecondProperty().getInverseProperty());
                    above(inverse.getSecondProperty(), inverse.getFirstProperty().getInverseProperty());
                } else if (axiom instanceof org.semanticweb.owlapi.model.OWLSymmetricObjectPropertyAxiom symmetric) {
                    above(symmetric.getProperty(), symmetric.getProperty().getInverseProperty());
                } else if (axiom instanceof OWLSubDataPropertyOfAxiom sub) {
                    dataSupers.computeIfAbsent(sub.getSubProperty().asOWLDataProperty(), k -> new HashSet<>())
                            .add(sub.getSuperProperty().asOWLDataProperty());
                } else if (axiom.isOfType(AxiomType.EQUIVALENT_DATA_PROPERTIES)) {
                    List<OWLDataProperty> members = axiom.dataPropertiesInSignature().toList();
                    members.forEach(a -> members.forEach(b -> {
                        if (!a.equals(b)) {
                            dataSupers.computeIfAbsent(a, k -> new HashSet<>()).add(b);
                        }
                    }));
                }
            }
        }

        private void above(OWLObjectPropertyExpression sub, OWLObjectPropertyExpression sup) {
            objectSupers.computeIfAbsent(sub.getSimplified(), k -> new HashSet<>()).add(sup.getSimplified());
            objectSupers.computeIfAbsent(sub.getInverseProperty().getSimplified(), k -> new HashSet<>())
                    .add(sup.getInverseProperty().getSimplified());
        }

        /** The property and every property expression above it. */
        Set<OWLObjectPropertyExpression> upwards(OWLObjectPropertyExpression property) {
            Set<OWLObjectPropertyExpression> reached = new LinkedHashSet<>(Set.of(property.getSimplified()));
            List<OWLObjectPropertyExpression> frontier = new ArrayList<>(reached);
            while (!frontier.isEmpty()) {
                for (OWLObjectPropertyExpression up : objectSupers.getOrDefault(frontier.remove(frontier.size() - 1),
                        Set.of())) {
                    if (reached.add(up)) {
                        frontier.add(up);
                    }
                }
            }
            return reached;
        }

        Set<OWLDataProperty> upwards(OWLDataProperty property) {
            Set<OWLDataProperty> reached = new LinkedHashSet<>(Set.of(property));
            List<OWLDataProperty> frontier = new ArrayList<>(reached);
            while (!frontier.isEmpty()) {
                for (OWLDataProperty up : dataSupers.getOrDefault(frontier.remove(frontier.size() - 1), Set.of())) {
                    if (reached.add(up)) {
                        frontier.add(up);
                    }
                }
            }
            return reached;
        }

        List<Image> edgeImages(OWLObjectProperty property, Set<OWLObjectProperty> kept) {
            Set<Image> images = new LinkedHashSet<>();
            for (OWLObjectPropertyExpression up : upwards(property)) {
                if (kept.contains(up.getNamedProperty())) {
                    images.add(new Image(up.getNamedProperty(), up.isAnonymous()));
                }
            }
            return List.copyOf(images);
        }

        Set<OWLDataProperty> valueImages(OWLDataProperty property, Set<OWLDataProperty> kept) {
            Set<OWLDataProperty> images = new LinkedHashSet<>(upwards(property));
            images.retainAll(kept);
            return Set.copyOf(images);
        }

        /**
         * What, beside assertions and the hierarchy, can give an edge or a value of these
         * properties (a transitive, reflexive or chained property below one, hasValue or self
         * over one, a class expression that makes values), or null.
         */
        String madeOtherwise(Set<OWLObjectProperty> edges, Set<OWLDataProperty> values) {
            for (OWLAxiom axiom : axioms) {
                List<OWLObjectPropertyExpression> makers = new ArrayList<>();
                List<OWLDataProperty> valueMakers = new ArrayList<>();
                if (axiom.isOfType(AxiomType.TRANSITIVE_OBJECT_PROPERTY, AxiomType.REFLEXIVE_OBJECT_PROPERTY)) {
                    axiom.objectPropertiesInSignature().forEach(makers::add);
                } else if (axiom instanceof org.semanticweb.owlapi.model.OWLSubPropertyChainOfAxiom chain) {
                    makers.add(chain.getSuperProperty());
                }
                axiom.nestedClassExpressions().forEach(expression -> {
                    if (expression instanceof org.semanticweb.owlapi.model.OWLObjectHasValue hasValue) {
                        makers.add(hasValue.getProperty());
                    } else if (expression instanceof org.semanticweb.owlapi.model.OWLObjectHasSelf self) {
                        makers.add(self.getProperty());
                    } else if (expression instanceof org.semanticweb.owlapi.model.OWLDataHasValue
                            || expression instanceof org.semanticweb.owlapi.model.OWLDataSomeValuesFrom
                            || expression instanceof org.semanticweb.owlapi.model.OWLDataCardinalityRestriction) {
                        expression.dataPropertiesInSignature().forEach(valueMakers::add);
                    }
                });
                for (OWLObjectPropertyExpression maker : makers) {
                    for (OWLObjectPropertyExpression up : upwards(maker)) {
                        if (edges.contains(up.getNamedProperty())) {
                            return up.getNamedProperty().getIRI().getShortForm() + ", whose edges " + axiom
                                    + " can make";
                        }
                    }
                }
                for (OWLDataProperty maker : valueMakers) {
                    for (OWLDataProperty up : upwards(maker)) {
                        if (values.contains(up)) {
                            return up.getIRI().getShortForm() + ", whose values " + axiom + " can make";
                        }
                    }
                }
            }
            return null;
        }
    }
}
