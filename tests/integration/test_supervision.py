# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The node survives its core: SIGKILL mid-request, errors for requests in flight, a new core."""

import os
import signal
import threading
import time

from armor_client import ArmorTransport, directive
from conftest import iris, start_node
from ontology_factory import write_abox
import pytest

CORE_UNAVAILABLE = 216


@pytest.fixture(scope='module')
def supervised(tmp_path_factory):
    # A node of its own, in its own namespace, so killing its core disturbs no other test.
    node = start_node(tmp_path_factory.mktemp('supervised'), '-r', '__ns:=/supervised')
    transport = ArmorTransport(namespace='/supervised', service_wait_s=90.0)
    assert transport.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=120).success
    yield node, transport
    transport.close()
    node.stop()


def test_core_killed_mid_reason_answers_in_flight_and_restarts(supervised):
    node, armor = supervised
    big = write_abox(node.scratch / 'big.owl', rooms=800, robots=4000)
    assert armor.call(directive('t', 'big', 'LOAD', 'FILE', '',
                                [str(big), '', 'false', 'JFACT', 'true']), timeout_s=300).success
    armor.call(directive('t', 'big', 'ADD', 'OBJECTPROP', 'IND', ['isIn', 'bot0', 'room2']))
    first_core = node.core_pid()

    in_flight = {}
    worker = threading.Thread(target=lambda: in_flight.setdefault(
        'response', armor.call(directive('t', 'big', 'REASON'), timeout_s=300)))
    worker.start()
    time.sleep(1.0)
    os.kill(first_core, signal.SIGKILL)
    worker.join(timeout=120)

    response = in_flight['response']
    assert not response.success
    assert response.exit_code == CORE_UNAVAILABLE, response.error_description
    assert node.process.poll() is None, 'the node died with its core'

    # A new core comes up, with the preloaded ontology back; the node answers throughout.
    deadline = time.monotonic() + 120
    while True:
        answer = armor.call(directive('t', 'robotics', 'QUERY', 'IND', 'CLASS', ['Robot']),
                            timeout_s=120)
        if answer.success or time.monotonic() > deadline:
            break
        assert answer.exit_code == CORE_UNAVAILABLE, answer.error_description
        time.sleep(0.2)
    assert answer.queried_objects == iris('robot1')
    assert node.core_pid() != first_core
    assert 'starting a new core' in node.log()


def test_core_killed_while_idle_is_replaced(supervised):
    node, armor = supervised
    os.kill(node.core_pid(), signal.SIGKILL)
    deadline = time.monotonic() + 120
    answer = None
    while time.monotonic() < deadline:
        answer = armor.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=120)
        if answer.success:
            break
        time.sleep(0.2)
    assert answer.success and 'robotics' in answer.queried_objects
