// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

import java.util.List;

/** The answer of an atomic list of directives: one response per directive, in order. */
public record ListResponse(boolean success, boolean isConsistent, List<Response> responses) {}
