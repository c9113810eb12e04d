# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Calls the two ARMOR services from any Python program.

The transport either owns a node (spun on a background thread, so calls may come from any
thread) or uses a node the caller already spins. Every wait has a deadline.
"""

import itertools
import os
import threading
import time
from typing import Any, FrozenSet, Optional, Sequence, Set, Tuple

from armor_client import commands
from armor_client.errors import ArmorCallTimeout, ArmorServiceCallError
from armor_client.paths import absolute_args
from armor_contract.events import CHANGE_TOPIC, SUBSCRIBE_SERVICE, UNSUBSCRIBE_SERVICE
from armor_contract.services import DIRECTIVE_SERVICE, LIST_SERVICE, SERVICE_QOS
from armor_contract.spinning import spin_while
from armor_msgs.msg import ArmorDirectiveReq, ArmorDirectiveRes
from armor_msgs.srv import ArmorDirective, ArmorDirectiveList, ArmorSubscribe, ArmorUnsubscribe
import rclpy
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions

_node_numbers = itertools.count()


def directive(client: str, reference: str, command: str, primary: str = '',
              secondary: str = '', args: Sequence[str] = (),
              cwd: Optional[str] = None) -> ArmorDirectiveReq:
    """Build an ArmorDirectiveReq; every argument is sent as a string.

    Path arguments (LOAD FILE's, SAVE's, ...: the catalogue says which) are made absolute
    against ``cwd``, by default this process's working directory (armor_client.paths).
    """
    texts = absolute_args(commands.find(command, primary, secondary), [str(a) for a in args], cwd)
    return ArmorDirectiveReq(client_name=client, reference_name=reference, command=command,
                             primary_command_spec=primary, secondary_command_spec=secondary,
                             args=texts)


def call_service(client: Any, request: Any, timeout_s: Optional[float]) -> Any:
    """Call one of ARMOR's services and wait for its answer: the client's one way of calling.

    Raises:
        ArmorCallTimeout: no answer within timeout_s (the request is forgotten).
        ArmorServiceCallError: the call broke.
    """
    done = threading.Event()
    future = client.call_async(request)
    future.add_done_callback(lambda _: done.set())
    if not done.wait(timeout_s):
        client.remove_pending_request(future)
        raise ArmorCallTimeout(f'no answer from {client.srv_name} within {timeout_s} s')
    if future.exception() is not None:
        raise ArmorServiceCallError(f'call to {client.srv_name} failed: {future.exception()}')
    return future.result()


class ArmorTransport:
    """The two ARMOR service clients behind one object.

    Args:
        node: a node the caller spins; None to create and spin one here.
        namespace: namespace of the ARMOR node ('' for the caller's own).
        service_wait_s: how long the first call waits for the services to appear.
    """

    def __init__(self, node: Optional[Node] = None, namespace: str = '',
                 service_wait_s: float = 30.0):
        self._owns_node = node is None
        self._owns_context = False
        if node is None:
            if not rclpy.ok():
                # Without rclpy's signal handlers: theirs shut the context down from the signal
                # while this transport's spinner waits in it, which could end the process in a
                # segmentation fault; Python's own (KeyboardInterrupt, a SIGTERM handler of the
                # caller's) leave through the caller's with block, which closes in order.
                rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
                self._owns_context = True
            node = rclpy.create_node(f'armor_client_{os.getpid()}_{next(_node_numbers)}')
            self._executor = MultiThreadedExecutor(num_threads=2)
            self._executor.add_node(node)
            self._closing = threading.Event()
            self._spinner = threading.Thread(target=self._spin, daemon=True,
                                             name='armor-client-spin')
        self.node: Node = node
        if self._owns_node:
            self._spinner.start()
        self.namespace = namespace
        self.service_wait_s = service_wait_s
        prefix = namespace.rstrip('/') + '/' if namespace else ''
        self._directive: Any = node.create_client(
            ArmorDirective, prefix + DIRECTIVE_SERVICE, qos_profile=SERVICE_QOS)
        self._list: Any = node.create_client(
            ArmorDirectiveList, prefix + LIST_SERVICE, qos_profile=SERVICE_QOS)
        self._prefix = prefix
        self._service_wait_s = service_wait_s
        self._ready: Set[str] = set()
        self._change_topic = prefix + CHANGE_TOPIC
        # armor_subscribe and armor_unsubscribe: made at the first subscription.
        self._subscription_clients: Optional[Tuple[Any, Any]] = None
        self._subscription_lock = threading.Lock()

    def call(self, request: ArmorDirectiveReq,
             timeout_s: Optional[float] = None) -> ArmorDirectiveRes:
        """Send one directive and return ARMOR's response (failed directives included)."""
        message = ArmorDirective.Request(armor_request=request)
        return self._call(self._directive, message, timeout_s).armor_response

    def call_list(self, requests: Sequence[ArmorDirectiveReq],
                  timeout_s: Optional[float] = None) -> ArmorDirectiveList.Response:
        """Send an atomic list of directives through armor_interface_serialized_srv."""
        message = ArmorDirectiveList.Request(armor_requests=list(requests))
        return self._call(self._list, message, timeout_s)

    def subscribe(self, request: ArmorDirectiveReq, timeout_s: Optional[float] = None) -> Any:
        """Start a standing query on the node (armor_subscribe); its response."""
        subscribe, _ = self._subscription_services()
        return call_service(subscribe, ArmorSubscribe.Request(armor_request=request), timeout_s)

    def unsubscribe(self, subscription_id: str, timeout_s: Optional[float] = None) -> Any:
        """End a standing query (armor_unsubscribe); its response."""
        _, unsubscribe = self._subscription_services()
        return call_service(unsubscribe, ArmorUnsubscribe.Request(subscription_id=subscription_id),
                            timeout_s)

    def _subscription_services(self) -> Tuple[Any, Any]:
        """The subscription services' clients, once armor_unsubscribe has answered.

        Proved as the directive services are (_wait_until_answered), with an unsubscribe of
        nothing, the one harmless request they take; again after the node went away (a
        restarted node).
        """
        with self._subscription_lock:
            if self._subscription_clients is None:
                self._subscription_clients = (
                    self.node.create_client(ArmorSubscribe, self._prefix + SUBSCRIBE_SERVICE,
                                            qos_profile=SERVICE_QOS),
                    self.node.create_client(ArmorUnsubscribe, self._prefix + UNSUBSCRIBE_SERVICE,
                                            qos_profile=SERVICE_QOS))
            subscribe, unsubscribe = self._subscription_clients
            if unsubscribe.srv_name not in self._ready or not subscribe.service_is_ready():
                hint = 'is an ARMOR node (of this version) running?'
                if not subscribe.wait_for_service(timeout_sec=self._service_wait_s):
                    raise self._unanswered(subscribe, hint)
                self._wait_until_answered(unsubscribe, hint)
            return self._subscription_clients

    def node_identity(self) -> FrozenSet[bytes]:
        """Which ARMOR node serves this namespace now, as far as the ROS graph tells.

        The endpoints that publish its armor_changes topic: every ARMOR node has that publisher
        from its start, and a restarted node has a new one. Read from this process's graph
        cache: nothing is sent, and a node just started may show only a moment later.
        """
        return frozenset(bytes(info.endpoint_gid)
                         for info in self.node.get_publishers_info_by_topic(self._change_topic))

    def node_replaced(self) -> None:
        """The node behind the services was replaced: prove each again before its next call."""
        self._ready.clear()

    def close(self) -> None:
        if self._owns_node:
            # The spinner first: destroying clients its wait set may hold (in a context a
            # caller's rclpy signal handler may already have shut down) could crash the exit.
            self._closing.set()
            self._executor.shutdown()
            self._spinner.join()
        for client in (self._directive, self._list, *(self._subscription_clients or ())):
            self.node.destroy_client(client)
        if self._owns_node:
            self.node.destroy_node()
        if self._owns_context:
            rclpy.try_shutdown()

    def __enter__(self) -> 'ArmorTransport':
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def _spin(self) -> None:
        spin_while(self._executor,
                   lambda: not self._closing.is_set() and rclpy.ok(context=self.node.context),
                   timeout_s=0.5)

    def _call(self, client, message, timeout_s):
        if client.srv_name not in self._ready:
            self._wait_until_answered(client)
        try:
            return call_service(client, message, timeout_s)
        except ArmorCallTimeout:
            # The node behind the service may have been replaced: prove the new one's response
            # path before the next call instead of risking another lost answer.
            self._ready.discard(client.srv_name)
            raise

    def _wait_until_answered(self, client,
                             hint: str = 'is the ARMOR node running (armor serve)?') -> None:
        """Block until the service has answered a harmless request from this client.

        wait_for_service() only proves that requests reach the service. Fast DDS drops a
        response when the service has not yet matched the client's response reader, which
        takes longer than its 100 ms grace on a loaded machine; a lost answer to a change is
        unrecoverable, a lost answer to a read is simply asked again.
        """
        deadline = time.monotonic() + self._service_wait_s
        harmless = (
            ArmorDirective.Request(armor_request=directive('', '', 'GET', 'ALL', 'REFS'))
            if client is self._directive else ArmorDirectiveList.Request() if client is self._list
            else ArmorUnsubscribe.Request(subscription_id=''))
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0 or not client.wait_for_service(timeout_sec=remaining):
                raise self._unanswered(client, hint)
            try:
                call_service(client, harmless, min(2.0, max(0.1, remaining)))
                self._ready.add(client.srv_name)
                return
            except ArmorServiceCallError:
                continue

    def _unanswered(self, client, hint: str) -> ArmorServiceCallError:
        return ArmorServiceCallError(
            f'service {client.srv_name} did not answer within {self._service_wait_s:.0f} s; '
            f'{hint}')
