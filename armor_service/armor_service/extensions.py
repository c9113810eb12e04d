# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ROS-side extensions: Python packages that add their own services and topics to the node.

An extension is an entry point of the group ``armor_service.extensions`` naming a callable
(a function or a class) that takes an :class:`ExtensionContext`; the node calls it at start
for every name in its ``extensions`` parameter. Through the context it creates its services,
topics and timers on the node and sends directives to the core by the very path
``armor_interface_srv`` takes (size limits, mount checks, locks, journal, exit codes). What
it returns is kept; if it has a ``close()`` method, the node calls it at shutdown.

An extension that fails at start is logged and left out; an exception in one of its callbacks
is logged and answered with an empty response: neither stops the node. A name that no
installed package provides stops the node, naming the installed ones (like a misspelt
parameter).
"""

import importlib.metadata
import traceback
from typing import Any, Callable, List, Optional, Sequence

from armor_msgs.msg import ArmorDirectiveReq, ArmorDirectiveRes
from armor_msgs.srv import ArmorDirective, ArmorDirectiveList
from armor_service.callback_guard import guarded
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.clock import Clock, ClockType
from rclpy.node import Node

ENTRY_POINT_GROUP = 'armor_service.extensions'


class ExtensionContext:
    """What an extension gets: the node to add services and topics to, and the core's path.

    Args:
        node: the ARMOR node.
        name: the extension's name (its entry point's).
        directive: answers one directive as armor_interface_srv does.
        directive_list: answers a list as armor_interface_serialized_srv does.
    """

    def __init__(self, node: Node, name: str,
                 directive: Callable[[ArmorDirectiveReq], ArmorDirectiveRes],
                 directive_list: Callable[[Sequence[ArmorDirectiveReq]], Any]):
        self._node = node
        self.name = name
        self._directive = directive
        self._directive_list = directive_list
        # Reentrant: a callback waiting for the core never holds up the node's other callbacks.
        self.callback_group = ReentrantCallbackGroup()
        self.logger = node.get_logger().get_child(name)
        self.client_name = f'extension:{name}'

    @property
    def node(self) -> Node:
        """The ARMOR node itself, for what the methods below do not offer (unguarded)."""
        return self._node

    def directive(self, request: ArmorDirectiveReq) -> ArmorDirectiveRes:
        """Send one directive to the core, exactly as armor_interface_srv would.

        Args:
            request: the directive (its client_name is what mount checks see).

        Returns:
            The core's response (exit code 216 while the core restarts).
        """
        return self._directive(request)

    def directive_list(self, requests: Sequence[ArmorDirectiveReq]) -> Any:
        """Send a list of directives, run atomically as armor_interface_serialized_srv does.

        Args:
            requests: the directives.

        Returns:
            An ``ArmorDirectiveList.Response`` (success, is_consistent, armor_responses).
        """
        return self._directive_list(list(requests))

    def call(self, reference: str, command: str, primary: str = '', secondary: str = '',
             args: Sequence[Any] = (), client_name: Optional[str] = None) -> ArmorDirectiveRes:
        """Send one directive built from its parts.

        Args:
            reference: the reference name ('' for none).
            command: the command word.
            primary: the primary spec.
            secondary: the secondary spec.
            args: the arguments (each sent as str).
            client_name: the client the core sees (default ``extension:<name>``).

        Returns:
            The core's response.
        """
        return self.directive(ArmorDirectiveReq(
            client_name=self.client_name if client_name is None else client_name,
            reference_name=reference, command=command, primary_command_spec=primary,
            secondary_command_spec=secondary, args=[str(arg) for arg in args]))

    def create_service(self, srv_type: Any, name: str, callback: Callable, **kwargs: Any) -> Any:
        """A service on the node whose callback cannot take the node down."""
        kwargs.setdefault('callback_group', self.callback_group)
        return self._node.create_service(srv_type, name, self._guarded(callback, name), **kwargs)

    def create_subscription(self, msg_type: Any, topic: str, callback: Callable, qos: Any,
                            **kwargs: Any) -> Any:
        """A subscription on the node whose callback cannot take the node down."""
        kwargs.setdefault('callback_group', self.callback_group)
        return self._node.create_subscription(msg_type, topic, self._guarded(callback, topic),
                                              qos, **kwargs)

    def create_publisher(self, msg_type: Any, topic: str, qos: Any, **kwargs: Any) -> Any:
        """A publisher on the node."""
        return self._node.create_publisher(msg_type, topic, qos, **kwargs)

    def create_timer(self, period_s: float, callback: Callable) -> Any:
        """A timer on the node whose callback cannot take the node down.

        Its period is counted on the steady clock, so a wall clock that steps back does not
        stop it.
        """
        return self._node.create_timer(period_s, self._guarded(callback, 'timer'),
                                       callback_group=self.callback_group,
                                       clock=Clock(clock_type=ClockType.STEADY_TIME))

    def _guarded(self, callback: Callable, what: str) -> Callable:
        return guarded(callback, self.logger, f'{what} of extension {self.name}')


class Extensions:
    """The extensions a node loaded, closed together at shutdown."""

    def __init__(self, loaded: List[Any], logger: Any):
        self._loaded = loaded
        self._logger = logger

    def close(self) -> None:
        """Close every loaded extension that has a close method, each guarded."""
        for extension in self._loaded:
            close = getattr(extension, 'close', None)
            if callable(close):
                try:
                    close()
                except Exception as error:
                    self._logger.error(f'closing extension {extension!r} failed: {error}')


def installed() -> List[str]:
    """The names of every installed extension."""
    return sorted({entry.name for entry in
                   importlib.metadata.entry_points(group=ENTRY_POINT_GROUP)})


def load_extensions(node: Any, names: Sequence[str]) -> Extensions:
    """Start the named extensions on an ARMOR node (armor_service.node.ArmorService).

    Args:
        node: the node; its directive callbacks are the path extensions send through.
        names: the extensions to load, in order.

    Returns:
        The loaded extensions.

    Raises:
        RuntimeError: a name no installed package provides.
    """
    available = {entry.name: entry for entry in
                 importlib.metadata.entry_points(group=ENTRY_POINT_GROUP)}
    missing = [name for name in names if name not in available]
    if missing:
        raise RuntimeError(
            f'extension(s) not installed: {", ".join(missing)}; installed: '
            f'{", ".join(sorted(available)) or "none"} (entry point group {ENTRY_POINT_GROUP})')

    def directive(request: ArmorDirectiveReq) -> ArmorDirectiveRes:
        return node.directive_callback(ArmorDirective.Request(armor_request=request),
                                       ArmorDirective.Response()).armor_response

    def directive_list(requests: List[ArmorDirectiveReq]) -> Any:
        return node.directive_list_callback(ArmorDirectiveList.Request(armor_requests=requests),
                                            ArmorDirectiveList.Response())

    logger = node.get_logger()
    loaded = []
    for name in names:
        try:
            start = available[name].load()
            loaded.append(start(ExtensionContext(node, name, directive, directive_list)))
        except Exception:
            logger.error(f'extension {name} failed to start and is left out:\n'
                         f'{traceback.format_exc().rstrip()}')
            continue
        logger.info(f'extension {name} started ({available[name].value})')
    return Extensions(loaded, logger)
