# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The ROS face of the core's standing queries: armor_subscribe, armor_unsubscribe, a topic each.

The core asks the queries again after each change and says what appeared and disappeared
(``"answer"`` events, see core_process.py); this module only gives each subscription a topic,
numbers its messages, and keeps what its client was told so that a restarted core can be
given the subscriptions again with the answers their clients already have (the core then
tells only what changed meanwhile). A subscription ends when its client calls
armor_unsubscribe, or when its topic has had no subscriber for ``subscription_idle_s`` (the
client went away without saying so).

Answer topics are reused: a topic whose subscription ended, once no subscriber is left on it,
is given to the next subscription (with a new publisher, so its history starts afresh; each
message names its subscription). Every new topic name costs the ROS middleware memory it never
gives back, so 10,000 subscriptions one after the other use a handful of names, not 10,000.
"""

import itertools
import secrets
import threading
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Set

from armor_contract.events import (ANSWER_QOS, ANSWER_TOPICS, SUBSCRIBE_SERVICE,
                                   UNSUBSCRIBE_SERVICE)
from armor_contract.exit_codes import ExitCode
from armor_contract.services import SERVICE_QOS
from armor_msgs.msg import ArmorAnswer
from armor_msgs.srv import ArmorSubscribe, ArmorUnsubscribe
from armor_service import core_ops, wire
from armor_service.callback_guard import guarded
from armor_service.core_process import CoreProcess, CoreUnavailable
from rclpy.clock import Clock, ClockType
from rclpy.event_handler import PublisherEventCallbacks

# No QoS event handlers on answer publishers: rclpy keeps a reference to each handler it ever
# made in their callback group (memory that a destroyed publisher does not give back).
_NO_EVENT_HANDLERS = PublisherEventCallbacks(use_default_callbacks=False)


@dataclass
class _Subscription:
    """One subscription: its query, its topic, and what its client has been told."""

    id: str
    directive: Dict[str, Any]
    topic: str
    publisher: Any
    answer: Set[str] = field(default_factory=set)
    sequence: int = 0
    without_subscriber_since: float = field(default_factory=time.monotonic)


class SubscriptionTopics:
    """Serves armor_subscribe and armor_unsubscribe for a node; publishes each answer's changes.

    Args:
        node: the ARMOR node (services, publishers and a timer are created on it).
        core: its core process.
        callback_group: the group of the node's service callbacks.
        idle_s: a function giving subscription_idle_s (it may change while the node runs).
        per_client: a function giving subscriptions_per_client (likewise).
    """

    def __init__(self, node, core: CoreProcess, callback_group, idle_s: Callable[[], float],
                 per_client: Callable[[], int]):
        self._node = node
        self._core = core
        self._idle_s = idle_s
        self._per_client = per_client
        self._lock = threading.Lock()
        self._sweeping = threading.Lock()
        self._subscriptions: Dict[str, _Subscription] = {}
        # Subscriptions being made, by client: counted against the client's share meanwhile.
        self._being_made: Dict[str, int] = {}
        # Ids unique to this node process: a client of an earlier node never mistakes a new
        # subscription's topic for its own.
        self._token = secrets.token_hex(3)
        self._numbers = itertools.count(1)
        self._topic_numbers = itertools.count(1)
        # Topics of ended subscriptions: free once nobody subscribes to them any more.
        self._free_topics: List[str] = []
        self._draining_topics: List[str] = []
        core.add_event_listener(self.on_core_event)
        logger = node.get_logger()
        node.create_service(ArmorSubscribe, SUBSCRIBE_SERVICE,
                            guarded(self.subscribe_callback, logger,
                                    f'service {SUBSCRIBE_SERVICE}', _refuse),
                            qos_profile=SERVICE_QOS, callback_group=callback_group)
        node.create_service(ArmorUnsubscribe, UNSUBSCRIBE_SERVICE,
                            guarded(self.unsubscribe_callback, logger,
                                    f'service {UNSUBSCRIBE_SERVICE}', _refuse),
                            qos_profile=SERVICE_QOS, callback_group=callback_group)
        # On the steady clock: a ROS-time timer waits for the wall clock to come back to its
        # next call, so a clock stepped back an hour stopped the sweep for an hour.
        node.create_timer(1.0, guarded(self.end_abandoned, logger, 'the subscription sweep'),
                          callback_group=callback_group,
                          clock=Clock(clock_type=ClockType.STEADY_TIME))

    def __len__(self) -> int:
        """How many subscriptions the node holds."""
        return len(self._subscriptions)

    def subscribe_callback(self, request, response):
        directive = wire.directive_to_json(request.armor_request)
        client = directive['client_name']
        limit = self._per_client()
        with self._lock:
            held = self._being_made.get(client, 0) + sum(
                1 for s in self._subscriptions.values() if s.directive['client_name'] == client)
            if 0 < limit <= held:
                response.success = False
                response.exit_code = ExitCode.CLIENT_LIMIT
                response.error_description = (
                    f'client {client!r} holds {held} live subscriptions, the most one client may '
                    '(node parameter subscriptions_per_client); unsubscribe one first')
                return response
            self._being_made[client] = self._being_made.get(client, 0) + 1
        try:
            return self._subscribe(directive, response)
        finally:
            with self._lock:
                self._being_made[client] -= 1
                if not self._being_made[client]:
                    del self._being_made[client]

    def _subscribe(self, directive: Dict[str, Any], response):
        subscription_id = f's{self._token}_{next(self._numbers)}'
        topic = self._topic()
        publisher = self._node.create_publisher(ArmorAnswer, topic, ANSWER_QOS,
                                                event_callbacks=_NO_EVENT_HANDLERS)
        subscription = _Subscription(subscription_id, directive, topic, publisher)
        # Registered before the core is asked: its first answer event may come before its reply.
        with self._lock:
            self._subscriptions[subscription_id] = subscription
        try:
            reply = core_ops.subscribe(self._core.request, subscription_id, directive)
            first = reply['response']
        except CoreUnavailable as error:
            first = {'success': False, 'exit_code': ExitCode.CORE_UNAVAILABLE,
                     'error_description': str(error)}
        response.success = bool(first['success'])
        response.exit_code = int(first['exit_code'])
        response.error_description = first['error_description']
        if not response.success:
            self._end(subscription_id)
            return response
        response.subscription_id = subscription_id
        response.topic = topic
        response.revision = int(reply['revision'])
        response.answer = list(dict.fromkeys(first['queried_objects']))
        return response

    def _topic(self) -> str:
        """A topic for a new subscription: a free one if there is one."""
        with self._lock:
            if self._free_topics:
                return self._free_topics.pop()
        return self._node.resolve_topic_name(
            f'{ANSWER_TOPICS}/t{self._token}_{next(self._topic_numbers)}')

    def unsubscribe_callback(self, request, response):
        response.success = self._end(request.subscription_id)
        if not response.success:
            response.error_description = (f'no subscription {request.subscription_id!r}: it '
                                          'ended already, or was made by an earlier node')
        return response

    def on_core_event(self, event: dict) -> None:
        """Publish an answer event on its subscription's topic (on the core's event thread)."""
        if event.get('event') != 'answer':
            return
        with self._lock:
            subscription = self._subscriptions.get(event['subscription'])
            if subscription is None:
                return
            subscription.answer.difference_update(event['removed'])
            subscription.answer.update(event['added'])
            self._publish(subscription, event)

    def register_again(self, send: Callable[[dict], dict]) -> None:
        """Give a new core the subscriptions, with what their clients know (core on_ready)."""
        with self._lock:
            subscriptions = list(self._subscriptions.values())
        for subscription in subscriptions:
            try:
                first = core_ops.subscribe(send, subscription.id, subscription.directive,
                                           sorted(subscription.answer))['response']
            except CoreUnavailable as error:
                first = {'success': False, 'exit_code': ExitCode.CORE_UNAVAILABLE,
                         'error_description': str(error)}
            if not first['success']:
                # Its query fails on the new core (its reference was not restored): say so; its
                # client decides (and the next core is asked again).
                with self._lock:
                    self._publish(subscription, {
                        'reference': subscription.directive['reference_name'], 'revision': -1,
                        'added': [], 'removed': [], 'exit_code': first['exit_code'],
                        'error_description': first['error_description'],
                        'stamp_ns': time.time_ns()})

    def end_abandoned(self) -> None:
        """End the subscriptions whose topic has had no subscriber for subscription_idle_s.

        Also frees the topics of ended subscriptions that nobody subscribes to any more.
        """
        # One sweep at a time: a sweep that ends many subscriptions outlasts the timer's period,
        # and a second one would touch the publishers the first destroyed (the node died of it).
        if not self._sweeping.acquire(blocking=False):
            return
        try:
            self._sweep()
        finally:
            self._sweeping.release()

    def _sweep(self) -> None:
        now = time.monotonic()
        idle_s = self._idle_s()
        with self._lock:
            subscriptions = list(self._subscriptions.values())
            draining = list(self._draining_topics)
        free = [topic for topic in draining if self._node.count_subscribers(topic) == 0]
        with self._lock:
            self._draining_topics = [t for t in self._draining_topics if t not in free]
            self._free_topics.extend(free)
        for subscription in subscriptions:
            if subscription.id not in self._subscriptions:
                continue  # ended meanwhile (unsubscribed): its publisher is gone
            if subscription.publisher.get_subscription_count() > 0:
                subscription.without_subscriber_since = now
            elif now - subscription.without_subscriber_since > idle_s:
                self._node.get_logger().info(
                    f'subscription {subscription.id} ended: its topic had no subscriber for '
                    f'{idle_s:g} s')
                self._end(subscription.id)

    def end_all(self) -> None:
        for subscription_id in list(self._subscriptions):
            self._end(subscription_id, tell_core=False)

    def _end(self, subscription_id: str, tell_core: bool = True) -> bool:
        with self._lock:
            subscription = self._subscriptions.pop(subscription_id, None)
        if subscription is None:
            return False
        if tell_core:
            try:
                core_ops.unsubscribe(self._core.request, subscription_id)
            except CoreUnavailable:
                pass  # a new core is given only the subscriptions still here
        self._node.destroy_publisher(subscription.publisher)
        with self._lock:
            self._draining_topics.append(subscription.topic)
        return True

    def _publish(self, subscription: _Subscription, event: Dict[str, Any]) -> None:
        """Publish one message with the subscription's next sequence number (lock held)."""
        message = wire.answer_from_json(subscription.id, subscription.sequence, event)
        subscription.sequence += 1
        subscription.publisher.publish(message)


def _refuse(request, response, description: str) -> None:
    response.success = False
    if hasattr(response, 'exit_code'):
        response.exit_code = ExitCode.INTERNAL_ERROR
    response.error_description = description
