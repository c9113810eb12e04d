# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""armor watch at a terminal (issue 12): one terminal watches, another changes the ontology."""

import signal
import subprocess
import sys
import time

from conftest import ONTOLOGIES
import pytest
from terminal import Terminal

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')


def ctrl_c(terminal: Terminal) -> None:
    """What the terminal does on Ctrl-C (the test's pseudo-terminal is not the process's own)."""
    terminal.process.send_signal(signal.SIGINT)


def armor_call(*words: str) -> subprocess.CompletedProcess:
    """`armor call ...` from another process, as in a second terminal."""
    return subprocess.run([sys.executable, '-m', 'armor_client.cli', 'call', *words],
                          capture_output=True, text=True, timeout=120)


@pytest.fixture
def watched(call):
    assert call('watched', 'LOAD FILE', ROBOTICS, '', 'false', 'HERMIT', 'false').success
    yield 'watched'
    call('watched', 'DROP')


def test_watch_prints_the_answer_then_each_room_as_it_becomes_and_stops_being_occupied(watched):
    terminal = Terminal(['-m', 'armor_client.cli', 'watch', watched, 'QUERY', 'IND', 'CLASS',
                         '--', 'OccupiedRoom'])
    terminal.wait_for('kitchen')
    assert f'# {watched} QUERY IND CLASS OccupiedRoom: 1 answer at revision 0 (Ctrl-C ends)\r\n' \
        'kitchen' in terminal.screen, terminal.screen

    moved = armor_call(watched, 'ADD', 'OBJECTPROP', 'IND', '--', 'isIn', 'alice', 'bedroom')
    assert moved.returncode == 0, moved.stderr
    terminal.wait_for('+ bedroom  (revision 1)')
    left = armor_call(watched, 'REMOVE', 'OBJECTPROP', 'IND', '--', 'isIn', 'alice', 'bedroom')
    assert left.returncode == 0, left.stderr
    terminal.wait_for('- bedroom  (revision 2)')
    assert '+ kitchen' not in terminal.screen and '- kitchen' not in terminal.screen

    ctrl_c(terminal)
    assert terminal.close() == 0, terminal.screen
    assert 'Traceback' not in terminal.screen, terminal.screen


def test_watch_takes_a_query_as_armor_query_does_and_says_when_it_is_answered_again(watched):
    """Issue 35 item 8: no QUERY nor "--" needed; after an inconsistency is repaired, a line
    says so (else the "!" line stays the last on screen although the answer is back)."""
    terminal = Terminal(['-m', 'armor_client.cli', 'watch', watched, 'IND', 'CLASS', 'Robot'])
    terminal.wait_for(f'# {watched} QUERY IND CLASS Robot: 1 answer at revision 0')
    terminal.wait_for('robot1')
    broken = armor_call(watched, 'ADD', 'IND', 'CLASS', '--', 'kitchen', 'Corridor')
    assert broken.returncode == 0, broken.stderr
    terminal.wait_for('! revision 1: error 217')
    repaired = armor_call(watched, 'REMOVE', 'IND', 'CLASS', '--', 'kitchen', 'Corridor')
    assert repaired.returncode == 0, repaired.stderr
    terminal.wait_for('# revision 2: answered again, 1 answer')
    assert '+ robot1' not in terminal.screen and '- robot1' not in terminal.screen
    ctrl_c(terminal)
    assert terminal.close() == 0, terminal.screen


def test_watch_refuses_what_is_not_a_query(watched):
    terminal = Terminal(['-m', 'armor_client.cli', 'watch', watched, 'ADD', 'IND', 'CLASS',
                         '--', 'robot9', 'Robot'])
    terminal.wait_for('error 205')
    assert terminal.close() == 1, terminal.screen


def test_watch_without_a_query_prints_each_change(watched):
    terminal = Terminal(['-m', 'armor_client.cli', 'watch', watched])
    terminal.wait_for('# watching the changes of watched')
    deadline = time.monotonic() + 60
    robot = 0
    while True:  # the watch joins the topic in a moment: change until it has printed one
        robot += 1
        assert armor_call(watched, 'ADD', 'IND', 'CLASS', '--', f'r{robot}', 'Robot').returncode == 0
        try:
            terminal.wait_for(f'{watched}  revision {robot}  armor_cli: ADD IND CLASS r{robot} '
                              'Robot', timeout_s=1.0)
            break
        except AssertionError:
            assert time.monotonic() < deadline, terminal.screen
    moved = armor_call(watched, 'ADD', 'OBJECTPROP', 'IND', '--', 'isIn', 'alice', 'bedroom')
    assert moved.returncode == 0
    terminal.wait_for(f'{watched}  revision {robot + 1}  armor_cli: ADD OBJECTPROP IND isIn alice '
                      'bedroom')
    ctrl_c(terminal)
    assert terminal.close() == 0, terminal.screen


def test_watch_subscribes_again_when_the_node_is_restarted(tmp_path):
    from conftest import start_node
    node = start_node(tmp_path, namespace='/watched_node')
    terminal = Terminal(['-m', 'armor_client.cli', 'watch', '--namespace', '/watched_node',
                         '--wait', '120', 'robotics', 'QUERY', 'IND', 'CLASS', '--',
                         'OccupiedRoom'])
    try:
        terminal.wait_for('kitchen', timeout_s=120)
        node.stop()
        node = start_node(tmp_path, namespace='/watched_node')
        terminal.wait_for('subscribing again', timeout_s=60)
        terminal.wait_for('kitchen', timeout_s=120)
        moved = armor_call('--namespace', '/watched_node', '--wait', '60', 'robotics', 'ADD',
                           'OBJECTPROP', 'IND', '--', 'isIn', 'alice', 'bedroom')
        assert moved.returncode == 0, moved.stderr
        terminal.wait_for('+ bedroom', timeout_s=60)
    finally:
        ctrl_c(terminal)
        code = terminal.close()
        node.stop()
    assert code == 0, terminal.screen
