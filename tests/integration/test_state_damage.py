# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A restore that finds damage says what it found, brings back what it can and loads nothing
over what it could not."""

import json
import socket
import urllib.request

from conftest import NS, ONTOLOGIES, call_words, first_call_after_start, start_node
import pytest

pytestmark = pytest.mark.runs_for_minutes(1)


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(('127.0.0.1', 0))
        return probe.getsockname()[1]


def test_a_restore_that_fails_says_so_and_the_preload_file_is_not_loaded_over_it(tmp_path):
    from armor_client import ArmorTransport
    node = start_node(tmp_path, namespace='/unrestorable')
    armor = ArmorTransport(namespace='/unrestorable', service_wait_s=120.0)
    try:
        for i in range(3):
            assert call_words(armor, 'robotics', 'ADD IND CLASS', f'kept{i}', 'Robot').success
        node.stop()
        refs = tmp_path / 'state' / 'refs' / 'robotics'
        for meta in ('meta.json', 'meta-copy.json'):
            (refs / meta).write_text('{"meta": {"name": "robotics"}, "crc32c": 1}')
        port = _free_port()
        node = start_node(tmp_path, '-p', f'web_port:={port}', namespace='/unrestorable')
        answer = first_call_after_start(armor, '', 'GET ALL REFS')
        assert answer.success and 'robotics' not in answer.queried_objects, node.log()
        damage = [json.loads(line)
                  for line in call_words(armor, '', 'GET STATE DAMAGE').queried_objects]
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
            assert call_words(armor, 'robotics', 'ADD IND CLASS', f'bot{i}', 'Robot').success
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
        answer = first_call_after_start(armor, 'robotics', 'QUERY IND CLASS', 'Robot')
        robots = set(answer.queried_objects)
        assert {f'<{NS}bot0>', f'<{NS}bot1>'} <= robots, node.log()
        assert not {f'<{NS}bot2>', f'<{NS}bot3>'} & robots
        damage = [json.loads(line)
                  for line in call_words(armor, '', 'GET STATE DAMAGE').queried_objects]
        assert len(damage) == 1 and damage[0]['restored'] is True, damage
        assert 'record 3 is damaged' in ' '.join(damage[0]['problems'])
        kept = damage[0]['kept_in']
        assert (tmp_path / 'state' / 'damaged').exists() and kept.endswith(tuple('0123456789'))
        # The reference takes changes again, and they survive a restart next to the intact ones.
        assert call_words(armor, 'robotics', 'ADD IND CLASS', 'bot4', 'Robot').success
        node.stop()
        node = start_node(tmp_path, namespace='/damaged')
        answer = first_call_after_start(armor, 'robotics', 'QUERY IND CLASS', 'Robot')
        robots = set(answer.queried_objects)
        assert {f'<{NS}bot0>', f'<{NS}bot1>', f'<{NS}bot4>'} <= robots
    finally:
        armor.close()
        node.stop()


def test_a_list_over_two_references_a_crash_left_in_one_journal_comes_back_in_neither(tmp_path):
    """A power cut between the two journal appends of an atomic list leaves its record in the
    first reference's journal only (the second's was never forced): the list was not
    acknowledged, and the restore must bring back none of it, without reporting damage."""
    from armor_client import ArmorTransport, directive
    node = start_node(tmp_path, namespace='/halflist')
    armor = ArmorTransport(namespace='/halflist', service_wait_s=120.0)
    try:
        assert call_words(armor, 'second', 'LOAD FILE', str(ONTOLOGIES / 'robotics.owl'),
                          'http://www.example.org/robotics', 'false', 'PELLET', 'true').success
        assert call_words(armor, 'robotics', 'ADD IND CLASS', 'before', 'Robot').success
        assert call_words(armor, 'second', 'ADD IND CLASS', 'before', 'Robot').success
        listed = armor.call_list([directive('test', reference, 'ADD', 'IND', 'CLASS', ['both', 'Robot'])
                                  for reference in ('robotics', 'second')], timeout_s=120)
        assert listed.success
        node.stop()
        # Cut the list's record off the end of the second reference's journal, as a power cut
        # before its fsync would have left it.
        journal = sorted((tmp_path / 'state' / 'refs' / 'second').glob('journal-*.log'))[-1]
        data = journal.read_bytes()
        records, at = [], 0
        while at < len(data):
            records.append(at)
            at += 8 + int.from_bytes(data[at:at + 4], 'big')
        assert len(records) == 2 and b'both' in data[records[-1]:], records
        journal.write_bytes(data[:records[-1]])
        node = start_node(tmp_path, namespace='/halflist')
        for reference in ('robotics', 'second'):
            robots = set(first_call_after_start(armor, reference, 'QUERY IND CLASS', 'Robot').queried_objects)
            assert f'<{NS}before>' in robots and f'<{NS}both>' not in robots, (reference, node.log())
        assert call_words(armor, '', 'GET STATE DAMAGE').queried_objects == []
        assert 'cut the record of an atomic list' in node.log()
    finally:
        armor.close()
        node.stop()
