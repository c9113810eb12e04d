# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""What Armor and AsyncArmor share: the session, written once for both.

A session is a client name, a transport and how answers are read. The sync and the asyncio
sessions differ in two things only: how a directive is sent (``call``: at once, or on a worker
thread as an awaitable) and how its answer is carried on (``_then``: ``Blocking`` applies the
next step to the response, ``Awaiting`` returns a coroutine that awaits it first). Every
command method (operations.py), of the session and of its references, goes through those
two, so a method added once serves both clients.
"""

import os
from typing import (Any, Awaitable, Callable, FrozenSet, Generic, Optional, Sequence, Type,
                    TypeVar)

from armor_client.batch import BatchBase
from armor_client.errors import ArmorError, error_for
from armor_client.operations import _catalogue, Parser, ReferenceBase, SessionCommands, Words
from armor_client.plugin_faces import add_methods, PluginMethods
from armor_client.transport import ArmorTransport, directive
from rclpy.node import Node

R = TypeVar('R', bound=ReferenceBase)


class Blocking:
    """Answers carried on at once: the sync client's ``_then``."""

    @staticmethod
    def _then(response: Any, then: Callable[[Any], Any]) -> Any:
        return then(response)


class Awaiting:
    """Answers carried on when awaited: the asyncio client's ``_then``."""

    @staticmethod
    def _then(response: Awaitable[Any], then: Callable[[Any], Any]) -> Awaitable[Any]:
        async def carried_on() -> Any:
            return then(await response)
        return carried_on()


class SessionBase(SessionCommands, Generic[R]):
    """A connection to one ARMOR node, speaking as one client (see Armor for the arguments)."""

    _reference_class: Type[R]
    _batch_class: Type[BatchBase]

    def __init__(self, client_name: Optional[str] = None, *, namespace: str = '',
                 node: Optional[Node] = None, timeout_s: Optional[float] = 60.0,
                 service_wait_s: float = 30.0, iris: bool = False,
                 transport: Optional[ArmorTransport] = None):
        self.client_name = client_name or default_client_name()
        self.timeout_s = timeout_s
        self.iris = iris
        self._owns_transport = transport is None
        self.transport = transport or ArmorTransport(node=node, namespace=namespace,
                                                     service_wait_s=service_wait_s)
        # This session's own reference and batch classes: its node's plugins' methods go there.
        self._reference_class = _own(type(self)._reference_class)
        self._batch_class = _own(type(self)._batch_class)
        self._plugin_methods: Optional[PluginMethods] = None
        # The node that answered the catalogue the methods come from (transport.node_identity).
        self._learned_from: Optional[FrozenSet[bytes]] = None

    def reference(self, name: str, iris: Optional[bool] = None) -> R:
        """The object for a reference that is loaded (or will be); nothing is sent yet.

        Args:
            name: the reference name.
            iris: answer entities as IRIs (default: this session's setting).

        Returns:
            A Reference (AsyncReference from AsyncArmor).
        """
        return self._reference_class(self, name, self.iris if iris is None else iris)

    def learn_plugin_methods(self) -> Any:
        """Ask the node for its catalogue; give this session's references its plugins' methods.

        Done on its own the first time a reference is asked for a method it does not have, or
        makes a batch (which gets the plugins' changes), and again when the node has restarted
        since (its plugins may be others): methods of commands it no longer has are removed.

        Returns:
            A PluginMethods (an awaitable of it from AsyncArmor): the methods added and the
            faces refused because the client already has their method name.
        """
        self._learned_from = self._node_identity()
        return self._session('', ('GET', 'CATALOGUE', ''), [], self._add_plugin_methods)

    def _batch_with_plugin_methods(self, *args: Any) -> Any:
        """A batch of this session, with the changes of its node's plugins (asked once)."""
        try:
            self._plugin_method('')
        except ArmorError:
            pass  # the node's catalogue cannot be read now: the built-in changes still queue
        return self._batch_class(*args)

    def _plugin_method(self, name: str) -> bool:
        """Whether the node's plugins give the references a method ``name``.

        Asked once, and again when the node has restarted since (_plugin_methods_stale).
        """
        if self._plugin_methods is None or self._plugin_methods_stale():
            if self._plugin_methods is not None:
                self.transport.node_replaced()  # a new node may drop an early answer
            self._learned_from = self._node_identity()
            # Blocking in both clients: an attribute lookup cannot await (one round trip).
            request = directive(self.client_name, '', 'GET', 'CATALOGUE', '')
            self._add_plugin_methods(_checked(self.transport.call(request,
                                                                  timeout_s=self.timeout_s)))
        return name in self._plugin_methods.added  # type: ignore[union-attr]

    def _plugin_methods_stale(self) -> bool:
        """Whether the plugin methods come from a node that no longer serves the namespace.

        A restarted node may load other plugins. A look-up in the ROS graph: nothing is sent.
        """
        return self._plugin_methods is not None and self._node_identity() != self._learned_from

    def _node_identity(self) -> Optional[FrozenSet[bytes]]:
        # A stand-in transport (tests) that cannot tell never reports a restart.
        identity = getattr(self.transport, 'node_identity', None)
        return identity() if identity is not None else None

    def _add_plugin_methods(self, response: Any) -> PluginMethods:
        answered = _catalogue(response).commands
        self._plugin_methods = add_methods(
            {self._reference_class: type(self)._reference_class,
             self._batch_class: type(self)._batch_class},
            answered, self._plugin_methods or PluginMethods())
        return self._plugin_methods

    def call(self, reference: str, command: str, primary: str = '', secondary: str = '',
             args: Sequence[Any] = ()) -> Any:
        raise NotImplementedError

    @staticmethod
    def _then(response: Any, then: Callable[[Any], Any]) -> Any:
        raise NotImplementedError

    def _loaded(self, name: str, response: Any) -> R:
        reference = self.reference(name)
        reference.consistent = response.is_consistent
        return reference

    def _session(self, reference: str, words: Words, args: Sequence[Any], parse: Parser) -> Any:
        return self._then(self.call(reference, *words, args),
                          lambda response: parse(_checked(response)))


def _own(built_in: type) -> Any:
    """A class of one session, to which the methods of its node's plugins are added."""
    return type(built_in.__name__, (built_in,), {'__module__': built_in.__module__,
                                                 '__doc__': built_in.__doc__})


def _checked(response: Any) -> Any:
    if not response.success:
        raise error_for(response)
    return response


def default_client_name() -> str:
    """A client name unique to this process: ``armor_py_<pid>``."""
    return f'armor_py_{os.getpid()}'
