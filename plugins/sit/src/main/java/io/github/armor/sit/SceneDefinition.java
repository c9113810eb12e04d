// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLObjectIntersectionOf;
import org.semanticweb.owlapi.model.OWLObjectMinCardinality;

/**
 * What a learned scene class is equivalent to: the intersection of {@code p min k T}, one for each
 * property p and type T of the elements the example relates by p, k being how many distinct
 * elements of type T that is. Its cardinality is the sum of the k.
 */
public record SceneDefinition(List<Restriction> restrictions) {
    private static final Comparator<Restriction> ORDER = Comparator
            .comparing((Restriction r) -> r.property().relation())
            .thenComparing(r -> r.property().subject())
            .thenComparing(Restriction::type);

    /** {@code p min k T}: at least k elements of type T that an element of p's subject type relates to by p's relation. */
    public record Restriction(Relation.Property property, Shape type, int min) {
        /** In words, from the side of the elements counted: "at least 2 CONE left of a SPHERE". */
        public String words() {
            Relation relation = property.relation();
            String subject = property.subject().name();
            String alongSameType = relation.fromObject().endsWith(" with") && property.subject() == type
                    ? relation.fromObject().substring(0, relation.fromObject().length() - " with".length()) : null;
            return "at least " + min + " " + type + " "
                    + (alongSameType != null ? alongSameType : relation.fromObject() + " a " + subject);
        }
    }

    /** The definition a scene's assertions give: for each (property, type of the object), its distinct objects. */
    public static SceneDefinition of(Scene scene, List<SpatialRelations.Fact> facts) {
        Map<Restriction, Integer> counts = new TreeMap<>(ORDER);
        for (SceneAssertion assertion : SceneAssertion.of(scene, facts)) {
            Restriction key = new Restriction(assertion.property(), scene.elements().get(assertion.object()).shape(), 0);
            counts.merge(key, 1, Integer::sum);
        }
        List<Restriction> restrictions = new ArrayList<>();
        counts.forEach((key, k) -> restrictions.add(new Restriction(key.property(), key.type(), k)));
        return new SceneDefinition(List.copyOf(restrictions));
    }

    /** card(class): the sum of its k. */
    public int cardinality() {
        return restrictions.stream().mapToInt(Restriction::min).sum();
    }

    /** The whole definition in words, restrictions joined by "; ". */
    public String words() {
        return restrictions.stream().map(Restriction::words).collect(Collectors.joining("; "));
    }

    /**
     * The definition a class expression states, if it is one of these (a learned class's, or one
     * written the same way): a min-cardinality restriction or an intersection of them, each on a
     * scene property with a primitive type as filler. Names are read as short forms.
     */
    public static Optional<SceneDefinition> read(OWLClassExpression expression) {
        List<OWLClassExpression> parts = expression instanceof OWLObjectIntersectionOf intersection
                ? intersection.getOperandsAsList() : List.of(expression);
        List<Restriction> restrictions = new ArrayList<>();
        for (OWLClassExpression part : parts) {
            if (!(part instanceof OWLObjectMinCardinality min) || min.getProperty().isAnonymous()
                    || min.getFiller().isAnonymous()) {
                return Optional.empty();
            }
            Optional<Relation.Property> property = Relation.ofProperty(
                    min.getProperty().asOWLObjectProperty().getIRI().getShortForm());
            Optional<Shape> type = Shape.named(min.getFiller().asOWLClass().getIRI().getShortForm())
                    .filter(shape -> shape.name().equals(min.getFiller().asOWLClass().getIRI().getShortForm()));
            if (property.isEmpty() || type.isEmpty()) {
                return Optional.empty();
            }
            restrictions.add(new Restriction(property.get(), type.get(), min.getCardinality()));
        }
        restrictions.sort(ORDER);
        return Optional.of(new SceneDefinition(List.copyOf(restrictions)));
    }
}
