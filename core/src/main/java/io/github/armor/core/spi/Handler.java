// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

import io.github.armor.core.api.Response;

/** The code that answers a command. An {@link io.github.armor.core.api.ArmorException} keeps its exit code. */
@FunctionalInterface
public interface Handler {
    Response run(Context context);
}
