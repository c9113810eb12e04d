# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Fixtures that start the real ARMOR node as a separate process and call it over ROS 2."""

import fcntl
import os
import pathlib
import random

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
ONTOLOGIES = REPO / 'ontologies'
TEST_ONTOLOGIES = REPO / 'tests' / 'ontologies'
NS = 'http://www.example.org/robotics#'

def _reserve_domain() -> str:
    """A DDS domain no other test run on this machine is using, held until this process ends.

    Two runs in one domain would each reach the other's node (a request goes to every server
    of a service name). Child processes inherit ROS_DOMAIN_ID and so share this run's domain.
    """
    start = random.Random(os.getpid()).randint(1, 232)
    for offset in range(232):
        domain = (start + offset) % 232 + 1
        handle = open(f'/tmp/armor-ros-domain-{domain}.lock', 'w')
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            handle.close()
            continue
        _DOMAIN_LOCKS.append(handle)
        return str(domain)
    raise RuntimeError('every DDS domain 1-232 is held by another test run')


_DOMAIN_LOCKS = []
# Chosen before rclpy starts; a run that sets ROS_DOMAIN_ID itself keeps it.
if 'ROS_DOMAIN_ID' not in os.environ:
    os.environ['ROS_DOMAIN_ID'] = _reserve_domain()


def iri(name: str) -> str:
    return f'<{NS}{name}>'


def iris(*names: str) -> list:
    return sorted(iri(n) for n in names)


def start_node(scratch: pathlib.Path, *ros_args: str, namespace: str = ''):
    """A node preloading robotics.owl as "robotics", reading and writing in scratch only.

    Its state directory is scratch/state, so it restores nothing but its own earlier state.
    A node started beside the session's node needs a namespace of its own: two nodes serving
    one service name would both receive every request.
    """
    if namespace:
        ros_args = (*ros_args, '-r', f'__ns:={namespace}')
    from armor_client.launch import ArmorNodeProcess
    node = ArmorNodeProcess(scratch / 'armor_service.log', [
        '-p', f'preload_file:={ONTOLOGIES / "robotics.owl"}', '-p', 'preload_reference:=robotics',
        '-p', f'allowed_dirs:=["{ONTOLOGIES}", "{TEST_ONTOLOGIES}", "{scratch}"]',
        '-p', f'state_dir:={scratch / "state"}', *ros_args],
        cwd=scratch)
    node.scratch = scratch
    return node


@pytest.fixture(scope='session')
def armor_node(tmp_path_factory):
    node = start_node(tmp_path_factory.mktemp('armor'))
    yield node
    node.stop()


@pytest.fixture(scope='session')
def armor(armor_node):
    """An ArmorTransport connected to the session's node, ready to call."""
    from armor_client import ArmorTransport, directive
    transport = ArmorTransport(service_wait_s=90.0)
    response = transport.call(directive('test', '', 'GET', 'ALL', 'REFS'), timeout_s=120)
    assert response.success, armor_node.log()
    yield transport
    transport.close()


@pytest.fixture
def call(armor):
    """call('REF', 'COMMAND PRIMARY SECONDARY', *args) -> ArmorDirectiveRes."""
    from armor_client import directive

    def send(reference, words, *args, client='test', timeout_s=120):
        command, primary, secondary = (words.split() + ['', '', ''])[:3]
        return armor.call(directive(client, reference, command, primary, secondary, args),
                          timeout_s=timeout_s)
    return send
