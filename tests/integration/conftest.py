# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Fixtures that start the real ARMOR node as a separate process and call it over ROS 2."""

import os
import pathlib
import random
import signal
import subprocess
import sys
import time

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
ONTOLOGIES = REPO / 'ontologies'
TEST_ONTOLOGIES = REPO / 'tests' / 'ontologies'
NS = 'http://www.example.org/robotics#'

# One DDS domain per test run, so that parallel runs on one machine never see each other's
# nodes; it must be chosen before rclpy starts.
os.environ.setdefault('ROS_DOMAIN_ID', str(random.Random(os.getpid()).randint(1, 100)))


def iri(name: str) -> str:
    return f'<{NS}{name}>'


def iris(*names: str) -> list:
    return sorted(iri(n) for n in names)


class ArmorNode:
    """A running `armor serve` process."""

    def __init__(self, scratch: pathlib.Path, *ros_args: str):
        self.scratch = scratch
        self.log_path = scratch / 'armor_service.log'
        params = ['-p', f'preload_file:={ONTOLOGIES / "robotics.owl"}',
                  '-p', 'preload_reference:=robotics',
                  '-p', f'allowed_dirs:=["{ONTOLOGIES}", "{TEST_ONTOLOGIES}", "{scratch}"]']
        params += list(ros_args)
        self._log = open(self.log_path, 'w')
        self.process = subprocess.Popen(
            [sys.executable, '-m', 'armor_client.cli', 'serve', '--ros-args', *params],
            stdout=self._log, stderr=subprocess.STDOUT, cwd=scratch)

    def core_pid(self, wait_s: float = 60.0) -> int:
        """PID of the Java core, the node's child process (waits through a restart)."""
        deadline = time.monotonic() + wait_s
        while time.monotonic() < deadline:
            for stat in pathlib.Path('/proc').glob('[0-9]*/stat'):
                try:
                    fields = stat.read_text().rsplit(')', 1)[1].split()
                    name = stat.read_text().split('(', 1)[1].rsplit(')', 1)[0]
                except (OSError, IndexError):
                    continue
                if int(fields[1]) == self.process.pid and name == 'java':
                    return int(stat.parent.name)
            time.sleep(0.1)
        raise AssertionError('the node has no Java core child')

    def log(self) -> str:
        return self.log_path.read_text()

    def stop(self) -> None:
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self._log.close()


@pytest.fixture(scope='session')
def armor_node(tmp_path_factory):
    node = ArmorNode(tmp_path_factory.mktemp('armor'))
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
