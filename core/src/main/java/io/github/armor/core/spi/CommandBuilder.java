// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.spi;

/**
 * One command's shape (its argument names, a one-line summary), ended by registering its
 * handler under the kind that decides how the core runs it.
 */
public interface CommandBuilder {
    /** Other words answered the same way. */
    CommandBuilder alias(String words);

    /** The required arguments' names (error messages and the catalogue show them). */
    CommandBuilder args(String... names);

    /** The optional arguments' names, after the required ones. */
    CommandBuilder optional(String... names);

    /** The last required argument may be repeated. */
    CommandBuilder variadic();

    /** Empty strings after the last argument are accepted and ignored (ROS 1 clients send dummies). */
    CommandBuilder emptySurplusIgnored();

    /** What the command does, in one line (required: the catalogue, the CLI and the docs show it). */
    CommandBuilder summary(String text);

    /**
     * The method the clients get for it: a Python client finds it in the node's catalogue and
     * adds it to its references; its name, what it answers, and one parameter per required
     * argument, {@code "count:int"} for a whole number (a variadic command's one list). Only a
     * query (answering something) or a manipulation ({@link FaceAnswer#NONE}) has one.
     */
    CommandBuilder face(String method, FaceAnswer answer, String... parameters);

    /**
     * A query answered, while another directive holds its reference, from the state its
     * reasoner last published; sources are asked in the order given, then the handler waits.
     */
    CommandBuilder whileBusy(StateAnswer source);

    /** A subscription to this query asks the query written {@code words} instead, with the same arguments. */
    CommandBuilder subscribedAs(String words);

    /** A read of an existing reference: never refused under a mount, never journaled. */
    void query(Handler handler);

    /** A change of an existing reference: refused under another client's mount, journaled, undone on failure. */
    void manipulation(Handler handler);

    /** Works on an existing reference without changing it (as SAVE does). */
    void onReference(Handler handler);

    /** Needs no reference. */
    void global(Handler handler);
}
