// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

/**
 * Every exit code a response can carry. Codes up to 205 are ARMOR's own; 206 and up are ours,
 * one per kind of failure, and never renumbered once released (clients test them).
 */
public enum ExitCode {
    SUCCESS(0, "success"),
    BAD_DATA_TYPE(101, "unsupported or unparsable data type or value"),
    REFERENCE_MOUNTED(102, "reference busy: mounted by another client"),
    NO_REFERENCE_NAME(201, "no reference name"),
    NO_COMMAND(202, "no command"),
    MOUNT_REFUSED(203, "mount or unmount refused"),
    UNKNOWN_COMMAND(205, "unknown command / spec combination"),
    UNKNOWN_REFERENCE(206, "no reference loaded under that name"),
    WRONG_ARGUMENTS(207, "wrong number or shape of arguments"),
    BAD_SYNTAX(208, "malformed name, IRI, class expression, rule or query"),
    LOAD_FAILED(209, "ontology could not be read or written"),
    REASONER_FAILED(210, "reasoner could not be created or failed"),
    TIMEOUT(211, "time limit reached"),
    ROLLED_BACK(212, "rolled back: another directive of the same list failed"),
    PATH_NOT_ALLOWED(213, "path outside the configured directories"),
    REFERENCE_EXISTS(214, "a reference with that name is loaded from another source"),
    AMBIGUOUS_NAME(215, "a plain name matches several entities"),
    CORE_UNAVAILABLE(216, "knowledge core restarting or unreachable"),
    INCONSISTENT(217, "the ontology is inconsistent, the query has no meaningful answer"),
    WEB_LOADING_DISABLED(218, "loading from the web is disabled"),
    NOT_SUPPORTED(219, "not supported by this reasoner"),
    INTERNAL_ERROR(220, "internal error in the knowledge core"),
    TOO_LARGE(221, "an argument, directive, list or answer exceeds its size limit"),
    IMPORTS_UNRESOLVED(222, "owl:imports that could not be resolved"),
    FEDERATED_QUERY_DISABLED(223, "SPARQL SERVICE (federated query) is disabled"),
    UNKNOWN_NAME(224, "a query names an entity the reference does not know (node parameter strict_names)"),
    NOT_DURABLE(225, "not durable: the state directory did not take the change (disk full, I/O error,"
            + " read-only); nothing changed"),
    CLIENT_LIMIT(226, "the client holds as many references or subscriptions as one client may"),
    NOT_ENTAILED(227, "the fact to explain does not hold (or the reference is consistent): nothing to explain");

    private final int code;
    private final String meaning;

    ExitCode(int code, String meaning) {
        this.code = code;
        this.meaning = meaning;
    }

    public int code() {
        return code;
    }

    public String meaning() {
        return meaning;
    }
}
