# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Durations are counted on the monotonic clock: the wall clock stepping under the node and the
core stretches no mount lease and delays no checkpoint."""

import json
import os
import time

from armor_client import ArmorTransport, directive
from armor_contract.events import SUBSCRIBE_SERVICE
from armor_msgs.srv import ArmorSubscribe
from conftest import call_service, call_words, first_call_after_start, NS, start_node
import pytest

pytestmark = pytest.mark.runs_for_minutes(3)


LIBFAKETIME = '/usr/lib/x86_64-linux-gnu/faketime/libfaketime.so.1'


def test_clock_jumps_leave_mount_leases_and_checkpoints_on_time(tmp_path):
    """The system clock stepping back an hour and forward a day under the node and the core.

    libfaketime (installed by make test's set-up) moves the wall clock of both processes while
    they run; the monotonic clock is left alone, as a real clock step leaves it. Durations (a
    mount's lease, the checkpoint interval) must not stretch or shrink with the wall clock.
    """
    assert os.path.exists(LIBFAKETIME), 'no libfaketime: bash tools/setup.sh test installs it'
    offset = tmp_path / 'faketime'
    offset.write_text('+0\n')
    env = dict(os.environ, LD_PRELOAD=LIBFAKETIME, FAKETIME_TIMESTAMP_FILE=str(offset),
               FAKETIME_DONT_FAKE_MONOTONIC='1', FAKETIME_CACHE_DURATION='1')
    args = ('-p', 'mount_lease_s:=30', '-p', 'checkpoint_every_s:=2',
            '-p', 'checkpoint_every_changes:=100000', '-p', 'subscription_idle_s:=2.0')
    node = start_node(tmp_path, *args, namespace='/clock', env=env)
    armor = ArmorTransport(namespace='/clock', service_wait_s=300.0)

    def step(text):
        offset.write_text(text + '\n')
        time.sleep(2.5)  # past the processes' one-second cache of the offset

    def meta_checkpoint():
        meta = json.loads((tmp_path / 'state' / 'refs' / 'robotics' / 'meta.json').read_text())
        return meta['meta']['current']['file']

    try:
        assert call_words(armor, 'robotics', 'MOUNT', client='holder', timeout_s=300).success
        step('-3600')
        assert call_words(armor, 'robotics', 'ADD IND CLASS', 'early', 'Robot').exit_code == 102
        # The holder renews its lease just before the jump, so a loaded machine's slow calls
        # before it cannot run the lease out; only a lease counted on the wall clock would.
        assert call_words(armor, 'robotics', 'QUERY IND CLASS', 'Robot', client='holder').success
        renewed = time.monotonic()
        step('+86400')
        assert call_words(armor, 'robotics', 'ADD IND CLASS', 'early2', 'Robot').exit_code == 102
        assert time.monotonic() - renewed < 30, 'too slow to tell: the lease ran out meanwhile'
        time.sleep(max(0.0, renewed + 31.5 - time.monotonic()))
        assert call_words(armor, 'robotics', 'ADD IND CLASS', 'late', 'Robot').success
        step('-3600')
        # A subscription nobody listens to ends 2 s later: the node's sweep runs on the
        # monotonic clock too, not a day later when the wall clock is back where it was.
        subscribe = armor.node.create_client(ArmorSubscribe, f'/clock/{SUBSCRIBE_SERVICE}')
        assert subscribe.wait_for_service(timeout_sec=60)
        unheard = call_service(subscribe, ArmorSubscribe.Request(armor_request=directive(
            'watcher', 'robotics', 'QUERY', 'IND', 'CLASS', ['Robot'])))
        assert unheard.success, unheard.error_description
        deadline = time.monotonic() + 30
        while f'subscription {unheard.subscription_id} ended' not in node.log():
            assert time.monotonic() < deadline, 'the subscription sweep stopped with the clock'
            time.sleep(0.2)
        # Checkpoints every 2 s of the monotonic clock, whatever the wall clock did.
        before = meta_checkpoint()
        assert call_words(armor, 'robotics', 'ADD IND CLASS', 'c1', 'Robot').success
        time.sleep(3)
        assert call_words(armor, 'robotics', 'ADD IND CLASS', 'c2', 'Robot').success
        deadline = time.monotonic() + 60
        while meta_checkpoint() == before and time.monotonic() < deadline:
            time.sleep(0.2)
        assert meta_checkpoint() != before, 'no checkpoint after the clock stepped back'
        step('+0')
        node.stop()
        armor.close()
        # Restarted under a namespace of its own: a DDS client that knew the services of the
        # node whose clock was a day ahead can take minutes to match the new node's. The clock
        # is back where it was, so the restart goes without libfaketime, which slowed the JVM
        # under load so much that the restore's first reasoning ran past the 30-s time limit.
        node = start_node(tmp_path, *args, namespace='/clock_restarted')
        armor = ArmorTransport(namespace='/clock_restarted', service_wait_s=300.0)
        answer = first_call_after_start(armor, 'robotics', 'QUERY IND CLASS', 'Robot')
        robots = set(answer.queried_objects)
        assert {f'<{NS}late>', f'<{NS}c1>', f'<{NS}c2>'} <= robots
        assert not {f'<{NS}early>', f'<{NS}early2>'} & robots
    finally:
        armor.close()
        node.stop()
