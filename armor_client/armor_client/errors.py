# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Exceptions raised by the client.

The two classes ROS 1 ARMOR's armor_api had keep their names and their meaning:
``ArmorServiceCallError`` when the service could not be called at all, and
``ArmorServiceInternalError`` when ARMOR answered that a directive failed (it carries the exit
code). The subclasses of ``ArmorServiceInternalError`` group the exit codes by what a program
usually does about them, so ``except ArmorUnknownReferenceError`` reads better than comparing
codes; every one of them is still an ``ArmorServiceInternalError``.
"""

from typing import Any, Dict, List, Optional, Type

from armor_contract.exit_codes import ExitCode


class ArmorError(Exception):
    """Base of every error the ARMOR client raises.

    Attributes:
        exit_code: ARMOR's exit code, or None when the service never answered.
        description: what went wrong, in words.
    """

    def __init__(self, description: str, exit_code: Optional[int] = None):
        super().__init__(description if exit_code is None else f'{exit_code}: {description}')
        self.exit_code = exit_code
        self.description = description

    @property
    def msg(self) -> str:
        """The description (the attribute name of ROS 1 armor_api's exceptions)."""
        return self.description


class ArmorServiceCallError(ArmorError):
    """The service could not be called: not running, no answer in time, or the call broke."""

    def __init__(self, description: str):
        super().__init__(description)


class ArmorCallTimeout(ArmorServiceCallError, TimeoutError):
    """The service did not answer within the client's time limit."""


class ArmorServiceInternalError(ArmorError):
    """ARMOR answered, and the directive failed.

    Args:
        description: ARMOR's error_description.
        exit_code: ARMOR's exit code (see docs/commands.md#exit-codes); None when a check of
            the client itself failed before anything was sent.
        timeout: the response's timeout flag (a time limit of the service was reached).
        response: the whole ArmorDirectiveRes, when there is one.

    Attributes:
        index: for a failed atomic list, the position of the directive that failed (None when
            the whole list was rolled back without one failing).
        responses: for a failed atomic list, every directive's response.
    """

    def __init__(self, description: str, exit_code: Optional[int] = None, timeout: bool = False,
                 response: Any = None):
        super().__init__(description, exit_code)
        self.timeout = timeout
        self.response = response
        self.index: Optional[int] = None
        self.responses: List[Any] = []

    @property
    def code(self) -> Optional[int]:
        """The exit code, by the attribute name of ROS 1 armor_api's exceptions."""
        return self.exit_code


class ArmorMountError(ArmorServiceInternalError):
    """102 (another client holds the mount, nothing changed) or 203 (mount refused)."""


class ArmorArgumentError(ArmorServiceInternalError):
    """The directive itself is wrong.

    Codes 101, 201, 202, 205, 207, 208, 215, 221 (too large) or 223 (a federated SPARQL query
    the node does not allow).
    """


class ArmorUnknownReferenceError(ArmorServiceInternalError):
    """206: no reference is loaded under that name."""


class ArmorFileError(ArmorServiceInternalError):
    """An ontology could not be read or written: 209, 213, 214, 218 or 222 (unresolved imports)."""


class ArmorReasonerError(ArmorServiceInternalError):
    """The reasoner failed, cannot answer, or the ontology is inconsistent: 210, 217, 219."""


class ArmorTimeLimitError(ArmorServiceInternalError, TimeoutError):
    """211: a time limit of the service (lock wait, reasoner, SPARQL) was reached."""


class ArmorNotEntailedError(ArmorServiceInternalError):
    """227: the fact an EXPLAIN command names does not hold (or the reference is consistent)."""


class ArmorRolledBackError(ArmorServiceInternalError):
    """212: undone or not run because another directive of the same list failed."""


class ArmorCoreUnavailableError(ArmorServiceInternalError):
    """216: the knowledge core is restarting; the same directive may succeed when retried."""


_CLASS_OF_CODE: Dict[int, Type[ArmorServiceInternalError]] = {
    **dict.fromkeys((ExitCode.REFERENCE_MOUNTED, ExitCode.MOUNT_REFUSED), ArmorMountError),
    **dict.fromkeys((ExitCode.BAD_DATA_TYPE, ExitCode.NO_REFERENCE_NAME, ExitCode.NO_COMMAND,
                     ExitCode.UNKNOWN_COMMAND, ExitCode.WRONG_ARGUMENTS, ExitCode.BAD_SYNTAX,
                     ExitCode.AMBIGUOUS_NAME, ExitCode.TOO_LARGE,
                     ExitCode.FEDERATED_QUERY_DISABLED), ArmorArgumentError),
    ExitCode.UNKNOWN_REFERENCE: ArmorUnknownReferenceError,
    **dict.fromkeys((ExitCode.LOAD_FAILED, ExitCode.PATH_NOT_ALLOWED, ExitCode.REFERENCE_EXISTS,
                     ExitCode.WEB_LOADING_DISABLED, ExitCode.IMPORTS_UNRESOLVED), ArmorFileError),
    **dict.fromkeys((ExitCode.REASONER_FAILED, ExitCode.INCONSISTENT, ExitCode.NOT_SUPPORTED),
                    ArmorReasonerError),
    ExitCode.TIMEOUT: ArmorTimeLimitError,
    ExitCode.ROLLED_BACK: ArmorRolledBackError,
    ExitCode.CORE_UNAVAILABLE: ArmorCoreUnavailableError,
    ExitCode.NOT_ENTAILED: ArmorNotEntailedError,
}


def error_for(response: Any) -> ArmorServiceInternalError:
    """The exception that describes a failed ArmorDirectiveRes.

    Args:
        response: an ArmorDirectiveRes with success=False.

    Returns:
        An instance of the ArmorServiceInternalError subclass for its exit code (the base class
        for codes this client does not know).
    """
    error_class = _CLASS_OF_CODE.get(response.exit_code, ArmorServiceInternalError)
    return error_class(response.error_description, response.exit_code, response.timeout, response)
