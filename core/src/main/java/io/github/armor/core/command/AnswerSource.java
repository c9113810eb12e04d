// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.api.Response;
import java.util.Optional;

/**
 * A way to answer a question without waiting for a reference another directive holds (a writer
 * reasoning for seconds), registered beside the command's handler
 * ({@link CommandTable.Builder#whileBusy}). The core asks a command's sources in registration
 * order; the first answer wins, and when none answers the handler does, holding the reference.
 */
@FunctionalInterface
public interface AnswerSource {
    /**
     * The answer, or empty when only the handler, holding the reference, can give it exactly.
     * Runs without the reference's lock: it must not read the live ontology.
     */
    Optional<Response> answer(CommandContext context);
}
