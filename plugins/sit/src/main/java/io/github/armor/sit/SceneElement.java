// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

/**
 * One perceived primitive: its shape, its centre and, for an orientable one, its axis (null when
 * not given). {@code label} names it in explanations: its type and its place in the scene,
 * counted from 1 ({@code CONE#2}).
 */
public record SceneElement(String label, Shape shape, double[] centre, double[] axis) {
    public boolean hasAxis() {
        return axis != null;
    }

    double x() {
        return centre[0];
    }

    double y() {
        return centre[1];
    }

    double z() {
        return centre[2];
    }
}
