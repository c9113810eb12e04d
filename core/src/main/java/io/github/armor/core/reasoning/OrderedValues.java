// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import io.github.armor.core.reasoning.Builtins.DataValue;
import java.math.BigDecimal;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.NavigableMap;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.BiConsumer;
import org.semanticweb.owlapi.model.OWLNamedIndividual;

/**
 * The values of one data property held by the rules, in numeric order (the decimal family: what
 * the arithmetic built-ins compute on), with every other value beside them unordered. A change
 * of the robot's clock then reaches the rooms whose last visit lies in a range ({@link
 * FlipRanges}) without walking every room.
 */
final class OrderedValues {
    private final TreeMap<BigDecimal, Map<OWLNamedIndividual, DataValue>> numbers = new TreeMap<>();
    private final Map<OWLNamedIndividual, Set<DataValue>> others = new HashMap<>();

    void add(OWLNamedIndividual subject, DataValue value) {
        BigDecimal number = value.decimal();
        if (number != null) {
            numbers.computeIfAbsent(number, k -> new LinkedHashMap<>()).put(subject, value);
        } else {
            others.computeIfAbsent(subject, k -> new java.util.LinkedHashSet<>()).add(value);
        }
    }

    void remove(OWLNamedIndividual subject, DataValue value) {
        BigDecimal number = value.decimal();
        if (number != null) {
            Map<OWLNamedIndividual, DataValue> holders = numbers.get(number);
            if (holders != null && holders.remove(subject) != null && holders.isEmpty()) {
                numbers.remove(number);
            }
        } else {
            Set<DataValue> held = others.get(subject);
            if (held != null && held.remove(value) && held.isEmpty()) {
                others.remove(subject);
            }
        }
    }

    void clear() {
        numbers.clear();
        others.clear();
    }

    /**
     * Each held (subject, value) whose value lies in one of the ranges, and every value that is
     * not a number (ranges say nothing about those). Reads only: the caller collects.
     */
    void within(Iterable<FlipRanges.Range> ranges, BiConsumer<OWLNamedIndividual, DataValue> each) {
        for (FlipRanges.Range range : ranges) {
            NavigableMap<BigDecimal, Map<OWLNamedIndividual, DataValue>> part = numbers;
            if (range.low() != null) {
                part = part.tailMap(range.low(), range.lowIncluded());
            }
            if (range.high() != null) {
                part = part.headMap(range.high(), range.highIncluded());
            }
            part.values().forEach(holders -> holders.forEach(each));
        }
        others.forEach((subject, held) -> held.forEach(value -> each.accept(subject, value)));
    }
}
