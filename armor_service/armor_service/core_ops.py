# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The knowledge core's socket operations: their names and the shapes of their replies.

Every frame the node sends the core is built here and every reply is read here; the process
supervisor (core_process.py) only carries frames. Each operation takes ``send``, a way of
sending a frame and waiting for its reply: ``CoreProcess.request``, or the ``send`` a new core
hands to its on_ready hook.
"""

from typing import Any, Callable, Dict, List, Optional, Sequence

Frame = Dict[str, Any]
Send = Callable[..., Frame]


def directive(client: str, reference: str, command: str, primary: str = '',
              secondary: str = '', args: Sequence[Any] = ()) -> Frame:
    """A directive as the core reads it (the armor_msgs fields of ArmorDirectiveReq)."""
    return {'client_name': client, 'reference_name': reference, 'command': command,
            'primary_command_spec': primary, 'secondary_command_spec': secondary,
            'args': [str(arg) for arg in args]}


def _exchange(send: Send, frame: Frame, timeout_s: Optional[float]) -> Frame:
    return send(frame) if timeout_s is None else send(frame, timeout_s)


def answer(send: Send, directive: Frame, timeout_s: Optional[float] = None) -> Frame:
    """The response to one directive (the armor_msgs fields of ArmorDirectiveRes)."""
    return _exchange(send, {'op': 'directive', 'directive': directive}, timeout_s)['response']


def answer_list(send: Send, directives: List[Frame],
                timeout_s: Optional[float] = None) -> Frame:
    """The answer to an atomic list: success, is_consistent, armor_responses."""
    return _exchange(send, {'op': 'list', 'directives': directives}, timeout_s)['list']


def view(send: Send, request: Frame, timeout_s: Optional[float] = None) -> Frame:
    """A web view's answer, or {"error": {"exit_code", "description"}}."""
    return _exchange(send, {'op': 'view', 'view': request}, timeout_s)['view']


def subscribe(send: Send, subscription: str, directive: Frame,
              known: Optional[Sequence[str]] = None) -> Frame:
    """Start (or, with the answer known so far, resume) a standing query.

    Returns:
        The reply: ``response`` (the first answer) and ``revision`` (the reference's).
    """
    frame: Frame = {'op': 'subscribe', 'subscription': subscription, 'directive': directive}
    if known is not None:
        frame['known'] = list(known)
    return send(frame)


def unsubscribe(send: Send, subscription: str) -> None:
    """End a standing query."""
    send({'op': 'unsubscribe', 'subscription': subscription})


def catalogue(send: Send, timeout_s: Optional[float] = None) -> Frame:
    """The running core's catalogue: commands (plugins' too), exit codes, settings."""
    return _exchange(send, {'op': 'catalogue'}, timeout_s)['catalogue']
