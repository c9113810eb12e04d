# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The armor_changes topic (issue 12): every acknowledged change, once, with its revision."""

import os
import signal
import time

from armor_client import ArmorTransport, directive
from change_listener import ChangeListener
from conftest import ONTOLOGIES, start_node
import pytest

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')


def load(reference: str, client: str = 'loader'):
    return directive(client, reference, 'LOAD', 'FILE', '', [ROBOTICS, '', 'false', 'HERMIT',
                                                            'false'])


@pytest.fixture
def changes(armor):
    """A listener that has received a change (of a reference of its own, dropped after)."""
    listener = ChangeListener(armor.node)
    assert armor.call(load('topic_probe')).success
    listener.wait_until_live(lambda: armor.call(directive(
        'probe', 'topic_probe', 'ADD', 'IND', 'CLASS', ['probe_robot', 'Robot'])))
    yield listener
    armor.call(directive('probe', 'topic_probe', 'DROP'))
    listener.close()


def test_every_acknowledged_change_is_one_revision_and_failures_none(armor, changes):
    started_ns = time.time_ns()
    assert armor.call(load('topic_ref')).success
    assert armor.call(directive('alice_app', 'topic_ref', 'ADD', 'OBJECTPROP', 'IND',
                                ['isIn', 'alice', 'bedroom'])).success
    assert armor.call(directive('alice_app', 'topic_ref', 'QUERY', 'IND', 'CLASS',
                                ['OccupiedRoom'])).success
    assert not armor.call(directive('alice_app', 'topic_ref', 'ADD', 'IND', 'CLASS',
                                    ['too-few-arguments'])).success
    good = armor.call_list([
        directive('lister', 'topic_ref', 'ADD', 'IND', 'CLASS', ['r2', 'Robot']),
        directive('lister', 'topic_ref', 'ADD', 'IND', 'CLASS', ['r3', 'Robot'])])
    assert good.success
    bad = armor.call_list([
        directive('lister', 'topic_ref', 'ADD', 'IND', 'CLASS', ['r4', 'Robot']),
        directive('lister', 'topic_ref', 'ADD', 'IND', 'CLASS', ['broken'])])
    assert not bad.success
    assert armor.call(directive('dropper', 'topic_ref', 'DROP')).success

    changes.wait_for(lambda: len(changes.of('topic_ref')) >= 4)
    time.sleep(0.5)  # anything wrongly published would arrive meanwhile
    received = changes.of('topic_ref')
    assert [m.revision for m in received] == [0, 1, 2, 3]
    creation, add, listed, drop = received
    assert creation.directives[0].command == 'LOAD' and creation.client_name == 'loader'
    assert add.client_name == 'alice_app'
    assert [(d.command, d.primary_command_spec, d.secondary_command_spec, list(d.args))
            for d in add.directives] == [('ADD', 'OBJECTPROP', 'IND', ['isIn', 'alice', 'bedroom'])]
    assert add.exit_code == 0 and add.is_consistent
    stamp_ns = add.stamp.sec * 1_000_000_000 + add.stamp.nanosec
    assert started_ns <= stamp_ns <= time.time_ns()
    assert [list(d.args) for d in listed.directives] == [['r2', 'Robot'], ['r3', 'Robot']]
    assert drop.directives[0].command == 'DROP' and drop.client_name == 'dropper'


def test_an_inconsistent_change_says_so(armor, changes):
    assert armor.call(load('topic_inconsistent')).success
    assert armor.call(directive('t', 'topic_inconsistent', 'ADD', 'IND', 'CLASS',
                                ['kitchen', 'Corridor'])).success
    changes.wait_for(lambda: len(changes.of('topic_inconsistent')) >= 2)
    assert [m.is_consistent for m in changes.of('topic_inconsistent')] == [True, False]
    armor.call(directive('t', 'topic_inconsistent', 'DROP'))


@pytest.fixture
def own_node(tmp_path):
    """A node of its own (its core is killed, it is restarted), in a namespace of its own."""
    nodes = [start_node(tmp_path, namespace='/revisions')]
    transport = ArmorTransport(namespace='/revisions', service_wait_s=90.0)
    assert transport.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=120).success
    yield nodes, transport
    transport.close()
    nodes[-1].stop()


def _add(transport, individual):
    return transport.call(directive('t', 'robotics', 'ADD', 'IND', 'CLASS', [individual, 'Robot']),
                          timeout_s=120)


def _add_until_answered(transport, individual, timeout_s=120.0):
    """ADD once the node answers again (216 while its new core comes up changes nothing)."""
    deadline = time.monotonic() + timeout_s
    while True:
        response = _add(transport, individual)
        if response.success:
            return
        assert response.exit_code == 216 and time.monotonic() < deadline, response
        time.sleep(0.2)


def test_revisions_continue_across_a_core_restart_and_a_node_restart(own_node, tmp_path):
    nodes, transport = own_node
    changes = ChangeListener(transport.node, '/revisions')
    changes.wait_until_live(lambda: _add(transport, 'warmup'))
    for name in ('bot1', 'bot2'):
        assert _add(transport, name).success
    changes.wait_for(lambda: len(changes.of('robotics')) >= 3)
    before = changes.of('robotics')[-1].revision
    assert [m.revision for m in changes.of('robotics')] == [before - 2, before - 1, before]

    os.kill(nodes[0].core_pid(), signal.SIGKILL)
    _add_until_answered(transport, 'after_core_restart')
    changes.wait_for(lambda: changes.of('robotics')[-1].revision == before + 1)

    nodes[0].stop()
    nodes.append(start_node(tmp_path, namespace='/revisions'))
    _answered_again(transport)
    acknowledged = []

    def probe():
        if _add(transport, f'after_node_restart{len(acknowledged)}').success:
            acknowledged.append(True)
    changes.wait_until_live(probe)
    # Every ADD acknowledged by the new node continued the revisions of the first.
    changes.wait_for(lambda: changes.of('robotics')[-1].revision == before + 1 + len(acknowledged))
    changes.close()


def _answered_again(transport, timeout_s=120.0):
    """Wait until a restarted node answers (it is not discoverable at once)."""
    from armor_client import ArmorError
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        try:
            if transport.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=5).success:
                return
        except ArmorError:
            pass
        time.sleep(0.1)
    raise AssertionError('the restarted node did not answer')
