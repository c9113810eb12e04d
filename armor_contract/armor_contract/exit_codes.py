# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ARMOR's exit codes (ExitCode.java); a test checks this enum against the core's catalogue.

Codes up to 205 are ROS 1 ARMOR's own; 206 and up were added for failures ARMOR reported
vaguely or not at all. A code is never renumbered once released: clients compare them.
"""

import enum


class ExitCode(enum.IntEnum):
    """Every exit code a response can carry."""

    SUCCESS = 0
    BAD_DATA_TYPE = 101
    REFERENCE_MOUNTED = 102
    NO_REFERENCE_NAME = 201
    NO_COMMAND = 202
    MOUNT_REFUSED = 203
    UNKNOWN_COMMAND = 205
    UNKNOWN_REFERENCE = 206
    WRONG_ARGUMENTS = 207
    BAD_SYNTAX = 208
    LOAD_FAILED = 209
    REASONER_FAILED = 210
    TIMEOUT = 211
    ROLLED_BACK = 212
    PATH_NOT_ALLOWED = 213
    REFERENCE_EXISTS = 214
    AMBIGUOUS_NAME = 215
    CORE_UNAVAILABLE = 216
    INCONSISTENT = 217
    WEB_LOADING_DISABLED = 218
    NOT_SUPPORTED = 219
    INTERNAL_ERROR = 220
    TOO_LARGE = 221
    IMPORTS_UNRESOLVED = 222
    FEDERATED_QUERY_DISABLED = 223
    UNKNOWN_NAME = 224
    NOT_DURABLE = 225
    CLIENT_LIMIT = 226
    NOT_ENTAILED = 227
