// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

import java.util.List;
import java.util.Optional;

/**
 * A query's answer from the state the reference's reasoner last published, so that it need not
 * wait while a writer holds the reference ({@link CommandBuilder#whileBusy}). The core asks it
 * only when a state is published and not older than the asking client's own last change.
 */
@FunctionalInterface
public interface StateAnswer {
    /**
     * The answer's objects, or empty when only the handler, holding the reference, can answer
     * exactly (a name the state does not know, a question it cannot say).
     */
    Optional<List<String>> objects(PublishedState state);
}
