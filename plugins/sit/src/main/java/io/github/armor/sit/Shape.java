// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import java.util.Locale;
import java.util.Optional;

/** The kinds of geometric primitive a scene is made of; each is a class of the ontology, named as here. */
public enum Shape {
    SPHERE(false),
    PLANE(true),
    CONE(true),
    CYLINDER(true);

    private final boolean orientable;

    Shape(boolean orientable) {
        this.orientable = orientable;
    }

    /** Whether it may have an axis (PLANE's normal, CONE's and CYLINDER's axis): a subclass of ORIENTABLE. */
    public boolean orientable() {
        return orientable;
    }

    /** The shape a type name names, in any case. */
    public static Optional<Shape> named(String name) {
        String wanted = name.trim().toUpperCase(Locale.ROOT);
        for (Shape shape : values()) {
            if (shape.name().equals(wanted)) {
                return Optional.of(shape);
            }
        }
        return Optional.empty();
    }
}
