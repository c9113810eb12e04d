# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The first `armor call` after `armor serve` finds the service already discovered (issue 33).

armor serve has armor call's relay discover its node as soon as the node is ready, so the
first call in another terminal costs what later ones cost. Its speed is measured by
bench/cold_start.sh and bench/call_latency.py, not here.
"""

import os
import signal
import subprocess
import sys
import time

from armor_client.cli import call_relay
from conftest import ONTOLOGIES

NAMESPACE = f'/first_call_{os.getpid()}'


def test_armor_serve_prepares_the_relay_for_the_first_call(tmp_path):
    call_relay.stop()
    log = tmp_path / 'armor_serve.log'
    with open(log, 'w') as out:
        node = subprocess.Popen(
            [sys.executable, '-m', 'armor_client.cli', 'serve', '--ros-args',
             '-p', f'preload_file:={ONTOLOGIES / "robotics.owl"}', '-p', 'preload_reference:=robotics',
             '-p', f'allowed_dirs:={ONTOLOGIES}', '-p', f'state_dir:={tmp_path / "state"}',
             '-p', 'web_port:=0', '-r', f'__ns:={NAMESPACE}'], stdout=out, stderr=subprocess.STDOUT)
    try:
        deadline = time.monotonic() + 180
        while 'ARMOR ready' not in log.read_text():
            assert node.poll() is None and time.monotonic() < deadline, log.read_text()
            time.sleep(0.2)
        # Nobody has called yet: a relay is there, and it has reached the node by itself.
        while not _ready():
            assert time.monotonic() < deadline, 'the relay did not discover the node by itself'
            time.sleep(0.2)
        states = []
        answer = call_relay.call(
            {'directive': {'client': 'test', 'reference': 'robotics', 'command': 'QUERY',
                           'primary': 'IND', 'secondary': 'CLASS', 'args': ['Room']},
             'namespace': NAMESPACE, 'wait_s': call_relay.DEFAULT_WAIT_S, 'timeout_s': 60},
            on_state=states.append)
        assert answer['response']['success'], answer
        assert states == [], 'the first call still had to discover the service'
        first = subprocess.run([sys.executable, '-m', 'armor_client.cli', 'call', '--namespace',
                                NAMESPACE, 'robotics', 'QUERY', 'IND', 'CLASS', '--', 'Room'],
                               capture_output=True, text=True, timeout=120)
        assert first.returncode == 0 and first.stderr == '', first.stderr
    finally:
        call_relay.stop()
        node.send_signal(signal.SIGINT)
        node.wait(timeout=60)


def _ready() -> bool:
    try:
        return call_relay.call({'prepare': NAMESPACE}, lambda state: None, connect_s=0)['ready']
    except call_relay.RelayUnavailable:
        return False
