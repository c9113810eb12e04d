// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
/**
 * What a plugin of the knowledge core may use, and all it needs: a {@link CommandGroup} found
 * with {@link java.util.ServiceLoader} registers its commands through a {@link CommandTable};
 * each command's {@link Handler} sees its directive through a {@link Context}, the reference's
 * knowledge through the read-only {@link Knowledge}, submits changes through
 * {@link Context#change} and checks client paths through {@link Paths}. A registration may add,
 * as a built-in command's does, a face (the clients' method, {@link FaceAnswer}), a
 * {@link StateAnswer} that answers from the last {@link PublishedState} while a writer holds the
 * reference, and the form a subscription asks. Nothing here can set a
 * revision, acknowledge a change or end a transaction: the core does that by the command's kind.
 * These types, with the api package, are the core's stable surface; everything else may change.
 */
package io.github.armor.core.spi;
