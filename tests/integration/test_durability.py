# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""No acknowledged change is lost, whatever the disk does: short forms of the fault campaigns.

Kills of the core and the node (the full run: `fault_injection.py --kills 100 --target core`),
a state directory on a real full filesystem (a 4 MiB tmpfs this test mounts), on an ext4 image
that turns read-only under the node, and restores that find damage. The storage campaigns that
fail every I/O call in turn are JUnit tests (StorageFaultsTest); `fault_injection.py --storage`
runs them longer and prints their figures.
"""

import json
import socket
import time
import urllib.request

from conftest import NS, start_node
from fault_injection import Campaign, FilesystemFaults
import pytest


@pytest.mark.parametrize('target', ['core', 'node'])
def test_sigkill_loses_no_acknowledged_change(tmp_path, target):
    campaign = Campaign(tmp_path, target, seed=7)
    try:
        audit = campaign.run(kills=3)
    finally:
        campaign.close()
    assert audit.kills == 3
    assert audit.acknowledged_singles > 10 and audit.acknowledged_lists > 2, audit.summary()
    assert audit.lost == 0, audit.summary()
    assert audit.half_applied_lists == 0, audit.summary()
    assert audit.failed_list_leaks == 0, audit.summary()


def test_full_disk_refuses_with_225_and_takes_changes_again_when_space_returns(tmp_path):
    faults = FilesystemFaults(tmp_path)
    try:
        audit = faults.full_disk(changes=40)
    finally:
        faults.close()
    print(audit.summary())
    assert audit.refused > 0 and audit.acknowledged > 0, audit.summary()
    assert audit.other_codes == [], audit.summary()
    assert audit.memory_differs == 0, audit.summary()
    assert audit.refusal_reported, audit.summary()
    assert audit.recovery_s is not None and audit.recovery_s < 5.0, audit.summary()
    assert audit.lost == 0 and audit.refused_present == 0, audit.summary()
    assert audit.damage_after_restart == [], audit.summary()


def test_filesystem_turning_read_only_refuses_with_225_and_loses_nothing(tmp_path):
    faults = FilesystemFaults(tmp_path)
    try:
        audit = faults.read_only(changes=6)
    finally:
        faults.close()
    print(audit.summary())
    assert audit.acknowledged == 6 and audit.refused == 6, audit.summary()
    assert audit.other_codes == [] and audit.memory_differs == 0, audit.summary()
    assert audit.lost == 0 and audit.refused_present == 0, audit.summary()


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(('127.0.0.1', 0))
        return probe.getsockname()[1]


def _call(armor, reference, words, *args):
    from armor_client import directive
    command, primary, secondary = (words.split() + ['', ''])[:3]
    return armor.call(directive('t', reference, command, primary, secondary, list(args)),
                      timeout_s=120)


def _first_call(armor, reference, words, *args):
    """The first call to a node just started again: it may take a while to be discovered."""
    deadline = time.monotonic() + 300
    while True:
        try:
            return _call(armor, reference, words, *args)
        except Exception:  # noqa: BLE001 - retried until the deadline
            if time.monotonic() > deadline:
                raise


def test_a_restore_that_fails_says_so_and_the_preload_file_is_not_loaded_over_it(tmp_path):
    from armor_client import ArmorTransport
    node = start_node(tmp_path, namespace='/unrestorable')
    armor = ArmorTransport(namespace='/unrestorable', service_wait_s=120.0)
    try:
        for i in range(3):
            assert _call(armor, 'robotics', 'ADD IND CLASS', f'kept{i}', 'Robot').success
        node.stop()
        refs = tmp_path / 'state' / 'refs' / 'robotics'
        for meta in ('meta.json', 'meta-copy.json'):
            (refs / meta).write_text('{"meta": {"name": "robotics"}, "crc32c": 1}')
        port = _free_port()
        node = start_node(tmp_path, '-p', f'web_port:={port}', namespace='/unrestorable')
        answer = _first_call(armor, '', 'GET ALL REFS')
        assert answer.success and 'robotics' not in answer.queried_objects, node.log()
        damage = [json.loads(line) for line in _call(armor, '', 'GET STATE DAMAGE').queried_objects]
        assert [d['reference'] for d in damage] == ['robotics'] and damage[0]['restored'] is False
        assert 'meta.json is damaged' in ' '.join(damage[0]['problems'])
        assert 'NOT preloading' in node.log()
        with urllib.request.urlopen(f'http://127.0.0.1:{port}/api/overview', timeout=60) as page:
            overview = json.loads(page.read())
        assert overview['state_damage'] == damage
    finally:
        armor.close()
        node.stop()


def test_a_damaged_journal_record_is_reported_and_the_changes_before_it_restored(tmp_path):
    from armor_client import ArmorTransport
    node = start_node(tmp_path, namespace='/damaged')
    armor = ArmorTransport(namespace='/damaged', service_wait_s=120.0)
    try:
        for i in range(4):
            assert _call(armor, 'robotics', 'ADD IND CLASS', f'bot{i}', 'Robot').success
        node.stop()
        journal = sorted((tmp_path / 'state' / 'refs' / 'robotics').glob('journal-*.log'))[-1]
        data = bytearray(journal.read_bytes())
        # A bit flipped inside the third record: the first two come back, the loss is reported.
        offsets, at = [], 0
        while at < len(data):
            offsets.append(at)
            at += 8 + int.from_bytes(data[at:at + 4], 'big')
        data[offsets[2] + 12] ^= 0x04
        journal.write_bytes(bytes(data))
        node = start_node(tmp_path, namespace='/damaged')
        robots = set(_first_call(armor, 'robotics', 'QUERY IND CLASS', 'Robot').queried_objects)
        assert {f'<{NS}bot0>', f'<{NS}bot1>'} <= robots, node.log()
        assert not {f'<{NS}bot2>', f'<{NS}bot3>'} & robots
        damage = [json.loads(line) for line in _call(armor, '', 'GET STATE DAMAGE').queried_objects]
        assert len(damage) == 1 and damage[0]['restored'] is True, damage
        assert 'record 3 is damaged' in ' '.join(damage[0]['problems'])
        kept = damage[0]['kept_in']
        assert (tmp_path / 'state' / 'damaged').exists() and kept.endswith(tuple('0123456789'))
        # The reference takes changes again, and they survive a restart next to the intact ones.
        assert _call(armor, 'robotics', 'ADD IND CLASS', 'bot4', 'Robot').success
        node.stop()
        node = start_node(tmp_path, namespace='/damaged')
        robots = set(_first_call(armor, 'robotics', 'QUERY IND CLASS', 'Robot').queried_objects)
        assert {f'<{NS}bot0>', f'<{NS}bot1>', f'<{NS}bot4>'} <= robots
    finally:
        armor.close()
        node.stop()


LIBFAKETIME = '/usr/lib/x86_64-linux-gnu/faketime/libfaketime.so.1'


def test_clock_jumps_leave_mount_leases_and_checkpoints_on_time(tmp_path):
    """The system clock stepping back an hour and forward a day under the node and the core.

    libfaketime (installed by make test's set-up) moves the wall clock of both processes while
    they run; the monotonic clock is left alone, as a real clock step leaves it. Durations (a
    mount's lease, the checkpoint interval) must not stretch or shrink with the wall clock.
    """
    import os
    from armor_client import ArmorTransport
    assert os.path.exists(LIBFAKETIME), 'no libfaketime: bash tools/setup.sh test installs it'
    offset = tmp_path / 'faketime'
    offset.write_text('+0\n')
    env = dict(os.environ, LD_PRELOAD=LIBFAKETIME, FAKETIME_TIMESTAMP_FILE=str(offset),
               FAKETIME_DONT_FAKE_MONOTONIC='1', FAKETIME_CACHE_DURATION='1')
    args = ('-p', 'mount_lease_s:=30', '-p', 'checkpoint_every_s:=2',
            '-p', 'checkpoint_every_changes:=100000')
    node = start_node(tmp_path, *args, namespace='/clock', env=env)
    armor = ArmorTransport(namespace='/clock', service_wait_s=300.0)

    def step(text):
        offset.write_text(text + '\n')
        time.sleep(2.5)  # past the processes' one-second cache of the offset

    def meta_checkpoint():
        meta = json.loads((tmp_path / 'state' / 'refs' / 'robotics' / 'meta.json').read_text())
        return meta['meta']['current']['file']

    try:
        from armor_client import directive
        assert armor.call(directive('holder', 'robotics', 'MOUNT', '', '', []), timeout_s=300).success
        mounted = time.monotonic()
        step('-3600')
        assert _call(armor, 'robotics', 'ADD IND CLASS', 'early', 'Robot').exit_code == 102
        step('+86400')
        # A lease counted on the wall clock would have expired a day ago.
        assert _call(armor, 'robotics', 'ADD IND CLASS', 'early2', 'Robot').exit_code == 102
        assert time.monotonic() - mounted < 30, 'too slow to tell: the lease ran out meanwhile'
        time.sleep(max(0.0, mounted + 31.5 - time.monotonic()))
        assert _call(armor, 'robotics', 'ADD IND CLASS', 'late', 'Robot').success
        # Checkpoints every 2 s of the monotonic clock, whatever the wall clock did.
        step('-3600')
        before = meta_checkpoint()
        assert _call(armor, 'robotics', 'ADD IND CLASS', 'c1', 'Robot').success
        time.sleep(3)
        assert _call(armor, 'robotics', 'ADD IND CLASS', 'c2', 'Robot').success
        deadline = time.monotonic() + 60
        while meta_checkpoint() == before and time.monotonic() < deadline:
            time.sleep(0.2)
        assert meta_checkpoint() != before, 'no checkpoint after the clock stepped back'
        step('+0')
        node.stop()
        node = start_node(tmp_path, *args, namespace='/clock', env=env)
        robots = set(_first_call(armor, 'robotics', 'QUERY IND CLASS', 'Robot').queried_objects)
        assert {f'<{NS}late>', f'<{NS}c1>', f'<{NS}c2>'} <= robots
        assert not {f'<{NS}early>', f'<{NS}early2>'} & robots
    finally:
        armor.close()
        node.stop()
