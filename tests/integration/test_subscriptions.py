# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Subscriptions to answers over ROS 2 (issue 12): armor_subscribe, a topic each, armor_unsubscribe.

These talk to the node's services and topics with plain rclpy, so they test the node, not the
client library (test_client_subscriptions.py tests that).
"""

import os
import signal
import threading
import time

from armor_client import ArmorTransport, directive
from armor_contract.events import ANSWER_QOS, SUBSCRIBE_SERVICE, UNSUBSCRIBE_SERVICE
from armor_msgs.msg import ArmorAnswer
from armor_msgs.srv import ArmorSubscribe, ArmorUnsubscribe
from conftest import call_service, iri, iris, ONTOLOGIES, start_node
import pytest

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')


class Answers:
    """The ArmorAnswer messages of one subscription's topic, as received."""

    def __init__(self, node, topic):
        self._node = node
        self._condition = threading.Condition()
        self.messages = []
        self._subscription = node.create_subscription(ArmorAnswer, topic, self._received,
                                                      ANSWER_QOS)

    def _received(self, message):
        with self._condition:
            self.messages.append(message)
            self._condition.notify_all()

    def wait_for(self, count, timeout_s=30.0):
        with self._condition:
            assert self._condition.wait_for(lambda: len(self.messages) >= count, timeout_s), (
                f'{len(self.messages)} of {count} messages: {self.messages}')
            return self.messages[count - 1]

    def close(self):
        self._node.destroy_subscription(self._subscription)


class Subscriber:
    """armor_subscribe and armor_unsubscribe of one node, called with plain rclpy."""

    def __init__(self, node, namespace=''):
        prefix = f'{namespace}/' if namespace else ''
        self._node = node
        self._subscribe = node.create_client(ArmorSubscribe, prefix + SUBSCRIBE_SERVICE)
        self._unsubscribe = node.create_client(ArmorUnsubscribe, prefix + UNSUBSCRIBE_SERVICE)
        assert self._subscribe.wait_for_service(timeout_sec=60)
        assert self._unsubscribe.wait_for_service(timeout_sec=60)

    @staticmethod
    def _call(client, request, timeout_s=120.0):
        return call_service(client, request, timeout_s)

    def subscribe(self, reference, words, *args):
        command, primary, secondary = (words.split() + ['', '', ''])[:3]
        return self._call(self._subscribe, ArmorSubscribe.Request(armor_request=directive(
            'watcher', reference, command, primary, secondary, args)))

    def unsubscribe(self, subscription_id):
        return self._call(self._unsubscribe,
                          ArmorUnsubscribe.Request(subscription_id=subscription_id))


@pytest.fixture
def subscriber(armor):
    return Subscriber(armor.node)


@pytest.fixture
def room_map(call):
    """A reference of this test's own, dropped afterwards."""
    assert call('sub_map', 'LOAD FILE', ROBOTICS, '', 'false', 'HERMIT', 'false').success
    yield 'sub_map'
    call('sub_map', 'DROP')


def test_an_inferred_room_is_announced_when_a_person_enters_and_leaves(
        armor, call, subscriber, room_map):
    subscribed = subscriber.subscribe(room_map, 'QUERY IND CLASS', 'OccupiedRoom')
    assert subscribed.success, subscribed.error_description
    assert list(subscribed.answer) == iris('kitchen')
    assert subscribed.topic.startswith('/armor_answers/')
    answers = Answers(armor.node, subscribed.topic)
    first = answers.wait_for(1)
    assert (first.sequence, list(first.added), list(first.removed)) == (0, iris('kitchen'), [])
    assert first.revision == subscribed.revision and first.subscription_id == \
        subscribed.subscription_id

    assert call(room_map, 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom').success
    entered = answers.wait_for(2)
    assert (entered.sequence, list(entered.added), list(entered.removed)) == (
        1, [iri('bedroom')], [])
    assert entered.revision == subscribed.revision + 1 and entered.exit_code == 0

    assert call(room_map, 'REMOVE OBJECTPROP IND', 'isIn', 'alice', 'bedroom').success
    left = answers.wait_for(3)
    assert (list(left.added), list(left.removed)) == ([], [iri('bedroom')])
    assert left.revision == subscribed.revision + 2
    assert subscriber.unsubscribe(subscribed.subscription_id).success
    answers.close()


def test_asserted_answers_and_sparql_rows(armor, call, subscriber, room_map):
    robots = subscriber.subscribe(room_map, 'QUERY IND CLASS', 'Robot')
    rows = subscriber.subscribe(room_map, 'QUERY SPARQL', 'SELECT ?who WHERE { ?who :isIn :bedroom }')
    assert robots.success and rows.success, (robots, rows)
    assert list(rows.answer) == []
    robot_answers, row_answers = Answers(armor.node, robots.topic), Answers(armor.node, rows.topic)
    assert call(room_map, 'ADD IND CLASS', 'robot2', 'Robot').success
    assert call(room_map, 'ADD OBJECTPROP IND', 'isIn', 'robot2', 'bedroom').success
    assert list(robot_answers.wait_for(2).added) == [iri('robot2')]
    assert list(row_answers.wait_for(2).added) == [iri('robot2')]
    # Changes in quick succession may be answered together, at the later revision.
    assert robot_answers.messages[1].revision in (robots.revision + 1, robots.revision + 2)
    assert row_answers.messages[1].revision == rows.revision + 2
    for subscription in (robots, rows):
        assert subscriber.unsubscribe(subscription.subscription_id).success
    robot_answers.close()
    row_answers.close()


def test_only_queries_are_subscribed_and_a_refusal_changes_nothing(call, subscriber, room_map):
    refused = subscriber.subscribe(room_map, 'ADD IND CLASS', 'robot9', 'Robot')
    assert not refused.success and refused.exit_code == 205 and 'query' in \
        refused.error_description
    assert refused.subscription_id == '' and refused.topic == ''
    malformed = subscriber.subscribe(room_map, 'QUERY SPARQL', 'SELECT WHERE {')
    assert not malformed.success and malformed.exit_code == 208
    unknown = subscriber.subscribe('no_such_ref', 'QUERY IND CLASS', 'Robot')
    assert not unknown.success and unknown.exit_code == 206
    assert call(room_map, 'QUERY IND CLASS', 'Robot').queried_objects == iris('robot1')


def test_unsubscribe_ends_the_messages(armor, call, subscriber, room_map):
    subscribed = subscriber.subscribe(room_map, 'QUERY IND CLASS', 'Robot')
    answers = Answers(armor.node, subscribed.topic)
    answers.wait_for(1)
    assert subscriber.unsubscribe(subscribed.subscription_id).success
    again = subscriber.unsubscribe(subscribed.subscription_id)
    assert not again.success and 'ended already' in again.error_description
    assert call(room_map, 'ADD IND CLASS', 'robot3', 'Robot').success
    time.sleep(1.0)
    assert len(answers.messages) == 1
    answers.close()


@pytest.fixture
def own_node(tmp_path):
    """A node of its own: its idle limit is short, its core is killed."""
    node = start_node(tmp_path, '-p', 'subscription_idle_s:=1.5', namespace='/subscribed')
    transport = ArmorTransport(namespace='/subscribed', service_wait_s=90.0)
    assert transport.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=120).success
    yield node, transport, Subscriber(transport.node, '/subscribed')
    transport.close()
    node.stop()


def test_a_subscription_whose_client_went_away_ends(own_node):
    node, transport, subscriber = own_node
    kept = subscriber.subscribe('robotics', 'QUERY IND CLASS', 'Robot')
    forgotten = subscriber.subscribe('robotics', 'QUERY IND CLASS', 'Room')
    answers = Answers(transport.node, kept.topic)
    answers.wait_for(1)
    gone = Answers(transport.node, forgotten.topic)
    gone.wait_for(1)
    gone.close()
    deadline = time.monotonic() + 30
    while f'subscription {forgotten.subscription_id} ended' not in node.log():
        assert time.monotonic() < deadline, node.log()
        time.sleep(0.2)
    assert not subscriber.unsubscribe(forgotten.subscription_id).success
    # The one whose client listens is kept, and still announces.
    assert transport.call(directive('t', 'robotics', 'ADD', 'IND', 'CLASS', ['robot7', 'Robot']),
                          timeout_s=60).success
    assert list(answers.wait_for(2).added) == [iri('robot7')]
    assert subscriber.unsubscribe(kept.subscription_id).success
    answers.close()


def test_a_subscription_outlives_its_core(own_node):
    node, transport, subscriber = own_node
    subscribed = subscriber.subscribe('robotics', 'QUERY IND CLASS', 'OccupiedRoom')
    answers = Answers(transport.node, subscribed.topic)
    answers.wait_for(1)
    os.kill(node.core_pid(), signal.SIGKILL)
    deadline = time.monotonic() + 120
    while True:
        moved = transport.call(directive('t', 'robotics', 'ADD', 'OBJECTPROP', 'IND',
                                         ['isIn', 'alice', 'bedroom']), timeout_s=120)
        if moved.success:
            break
        assert moved.exit_code == 216 and time.monotonic() < deadline, moved
        time.sleep(0.2)
    entered = answers.wait_for(2)
    assert (entered.sequence, list(entered.added)) == (1, [iri('bedroom')])
    assert subscriber.unsubscribe(subscribed.subscription_id).success
    answers.close()
