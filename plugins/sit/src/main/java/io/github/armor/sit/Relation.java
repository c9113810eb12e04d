// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The qualitative spatial relations between two elements of a scene (docs/scenes.md). A relation
 * {@code rel(d, x)} becomes the assertion {@code <rel><TYPE of d>(scene, x)}, so each is read from
 * the second element's side: {@code right(d, x)} says that d is right of x, that is, x is left of
 * a d; {@link #fromObject} is that reading.
 */
public enum Relation {
    RIGHT("right", "left of"),
    LEFT("left", "right of"),
    BEHIND("behind", "in front of"),
    FRONT("front", "behind"),
    ABOVE("above", "below"),
    BELOW("below", "above"),
    ALONG_X("alongX", "along X with"),
    ALONG_Y("alongY", "along Y with"),
    ALONG_Z("alongZ", "along Z with"),
    PARALLEL("parallel", "parallel to"),
    PERPENDICULAR("perpendicular", "perpendicular to"),
    COAXIAL("coaxial", "coaxial with");

    private final String word;
    private final String fromObject;

    Relation(String word, String fromObject) {
        this.word = word;
        this.fromObject = fromObject;
    }

    /** Its name in property names ({@code alongX} in {@code alongXCONE}). */
    public String word() {
        return word;
    }

    /** How x relates to d when {@code rel(d, x)} holds: "left of" for right. */
    public String fromObject() {
        return fromObject;
    }

    /** Whether {@code rel(d, x)} always comes with {@code rel(x, d)}. */
    public boolean symmetric() {
        return this == ALONG_X || this == ALONG_Y || this == ALONG_Z || this == PARALLEL || this == PERPENDICULAR;
    }

    /** The property of this relation from an element of {@code subject}'s type: {@code rightSPHERE}. */
    public String property(Shape subject) {
        return word + subject.name();
    }

    /** The relation and subject type a property name stands for, if it is one of these. */
    public static Optional<Property> ofProperty(String name) {
        return Optional.ofNullable(Names.BY_NAME.get(name));
    }

    /** Every scene property by name (a holder: built once the enum's constants exist). */
    private static final class Names {
        static final Map<String, Property> BY_NAME = new HashMap<>();

        static {
            for (Relation relation : values()) {
                for (Shape shape : Shape.values()) {
                    BY_NAME.put(relation.property(shape), new Property(relation, shape));
                }
            }
        }
    }

    /** A scene property: a relation from an element of a type. */
    public record Property(Relation relation, Shape subject) {
        public String name() {
            return relation.property(subject);
        }
    }
}
