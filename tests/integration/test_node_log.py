# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""What a node prints, read from the log of a node started here (issue 11 items 3, 9 and 10,
issue 18 item 4): routine lines at INFO, a quiet Ctrl-C, what a restart restored, and one
clear line when the state directory is taken."""

import re
import time

from conftest import start_node

NAMESPACE = '/logged'


def _call(namespace, reference, command, primary='', secondary='', *args):
    from armor_client import ArmorTransport, directive
    with ArmorTransport(namespace=namespace, service_wait_s=120.0) as armor:
        return armor.call(directive('log_test', reference, command, primary, secondary, args),
                          timeout_s=120)


def _levels(log: str) -> set:
    return set(re.findall(r'^\[(DEBUG|INFO|WARN|ERROR|FATAL)\]', log, re.MULTILINE))


def test_routine_lines_are_info_and_ctrl_c_is_quiet(tmp_path):
    node = start_node(tmp_path, namespace=NAMESPACE)
    try:
        assert _call(NAMESPACE, '', 'LOG', 'SCREEN', 'ON').success, node.log()
        assert _call(NAMESPACE, 'robotics', 'QUERY', 'IND', 'CLASS', 'Room').success
        assert _call(NAMESPACE, '', 'LOG', 'SCREEN', 'OFF').success
    finally:
        node.stop()
    log = node.log()
    assert node.process.returncode == 0, log
    directive_line = re.search(r'^\[INFO\] .* core: .*\[log_test\] robotics: QUERY IND CLASS \[Room\] -> 0$',
                               log, re.MULTILINE)
    assert directive_line, log
    assert _levels(log) == {'INFO'}, log
    assert 'rosout' not in log and 'connection to the core lost' not in log, log


def test_a_restart_says_what_it_restored_and_a_clean_start_restores_nothing(tmp_path):
    node = start_node(tmp_path, namespace=NAMESPACE)
    try:
        assert _call(NAMESPACE, 'robotics', 'ADD', 'IND', 'CLASS', 'carol', 'Person').success, \
            node.log()
    finally:
        node.stop()
    first = node.log()
    assert 'preloaded' in first and 'restored' not in first, first

    node = start_node(tmp_path, namespace=NAMESPACE)
    try:
        assert _call(NAMESPACE, 'robotics', 'QUERY', 'IND', 'CLASS', 'Person').success
    finally:
        node.stop()
    restarted = node.log()
    restored = re.search(r"^\[INFO\] .* restored reference 'robotics' from the state directory \S+: "
                         r"(\d+) axioms, (\d+) individuals, 1 journal record\(s\)", restarted,
                         re.MULTILINE)
    assert restored, restarted
    assert re.search(r'^\[INFO\] .*reference "robotics" restored with the changes of earlier '
                     r'sessions, not reloaded .*restore_state:=false', restarted, re.MULTILINE), \
        restarted
    assert 'preloaded' not in restarted, restarted

    node = start_node(tmp_path, '-p', 'restore_state:=false', namespace=NAMESPACE)
    try:
        answer = _call(NAMESPACE, 'robotics', 'QUERY', 'IND', 'CLASS', 'Person')
    finally:
        node.stop()
    clean = node.log()
    assert 'restored' not in clean and 'preloaded' in clean, clean
    assert not any(a.endswith('#carol>') for a in answer.queried_objects), answer.queried_objects


def test_a_second_node_on_a_state_directory_in_use_says_so_once(tmp_path):
    (tmp_path / "first").mkdir()
    first = start_node(tmp_path / "first",
                       '-p', f'state_dir:={tmp_path / "shared"}', namespace=NAMESPACE)
    try:
        assert _call(NAMESPACE, '', 'GET', 'ALL', 'REFS').success, first.log()
        (tmp_path / 'second').mkdir()
        started = time.monotonic()
        second = start_node(tmp_path / 'second', '-p', f'state_dir:={tmp_path / "shared"}',
                            namespace='/second')
        code = second.process.wait(timeout=120)
        waited = time.monotonic() - started
        second.stop()
    finally:
        first.stop()
    log = second.log()
    assert code != 0, log
    expected = (f'state directory {tmp_path / "shared"} is in use by another ARMOR node '
                f'(pid {first.process.pid})')
    assert log.count(expected) == 1, log
    assert 'Exception' not in log and '\tat ' not in log, log
    # Another live node is no dying predecessor: no waiting for it to let go.
    assert waited < 60, waited
