# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""CoreProcess against a fake core process: concurrency, death mid-request, restarts.

fake_core.py speaks the core's socket protocol and does what each directive's command tells
it (answer, wait for others, hang, die), so these tests reach the paths a real reasoner
reaches only by accident.
"""

import concurrent.futures
import pathlib
import sys
import threading
import time

from armor_service.core_process import CoreProcess, CoreUnavailable
import pytest

FAKE_CORE = pathlib.Path(__file__).with_name('fake_core.py')


def directive(command: str, *args: str) -> dict:
    return {'op': 'directive', 'directive': {
        'client_name': 't', 'reference_name': 'r', 'command': command,
        'primary_command_spec': '', 'secondary_command_spec': '', 'args': list(args)}}


@pytest.fixture
def make_core(tmp_path):
    """make_core(**config) -> a started CoreProcess over the fake core; stopped afterwards."""
    java = tmp_path / 'java'
    # CoreProcess runs `java [options] -jar JAR SOCKET CONFIG`: drop -jar, run the fake in Python.
    java.write_text(f'#!/bin/sh\nshift\nexec {sys.executable} "$@"\n')
    java.chmod(0o755)
    made = []

    def make(on_ready=None, start=True, **config) -> CoreProcess:
        config.setdefault('starts_file', str(tmp_path / 'starts'))
        core = CoreProcess(str(FAKE_CORE), config, java=str(java), start_timeout_s=30,
                           restart_wait_s=30, on_ready=on_ready)
        made.append(core)
        if start:
            core.start()
        return core
    yield make
    for core in made:
        core.stop()


def starts(tmp_path) -> int:
    path = tmp_path / 'starts'
    return len(path.read_text().split()) if path.exists() else 0


def wait_until(condition, timeout_s=30.0) -> None:
    deadline = time.monotonic() + timeout_s
    while not condition():
        assert time.monotonic() < deadline, 'condition not reached'
        time.sleep(0.02)


def test_many_requests_are_in_flight_at_once_and_each_gets_its_own_answer(make_core):
    core = make_core()
    count = 24
    with concurrent.futures.ThreadPoolExecutor(count) as pool:
        # Each BARRIER is answered only when all of them have reached the core.
        futures = [pool.submit(core.request, directive('BARRIER', str(count), f'r{i}'), 30)
                   for i in range(count)]
        replies = [future.result(timeout=60) for future in futures]
    assert [r['response']['queried_objects'] for r in replies] == [
        [str(count), f'r{i}'] for i in range(count)]


def test_a_core_dying_mid_request_answers_every_request_in_flight_core_unavailable(make_core):
    core = make_core()
    with concurrent.futures.ThreadPoolExecutor(6) as pool:
        hanging = [pool.submit(core.request, directive('HANG')) for _ in range(5)]
        time.sleep(0.3)  # let them reach the core; ordering only, nothing is timed
        dying = pool.submit(core.request, directive('DIE'))
        for future in [*hanging, dying]:
            with pytest.raises(CoreUnavailable):
                future.result(timeout=30)


def test_one_death_starts_one_new_core_and_waiting_callers_are_served_by_it(make_core, tmp_path):
    preloads = []
    core = make_core(on_ready=lambda send: preloads.append(send(directive('ECHO', 'preload'))))
    first_pid = core.pid
    with pytest.raises(CoreUnavailable):
        core.request(directive('DIE'))
    # Callers arriving during the restart wait for the new core instead of failing.
    with concurrent.futures.ThreadPoolExecutor(8) as pool:
        echoes = [pool.submit(core.request, directive('ECHO', str(i)), 30) for i in range(8)]
        answers = [f.result(timeout=60)['response']['queried_objects'] for f in echoes]
    assert answers == [[str(i)] for i in range(8)]
    assert core.pid != first_pid
    # The reader and the exit watcher both saw the death: still exactly one restart.
    time.sleep(1.0)
    assert starts(tmp_path) == 2
    assert [p['response']['queried_objects'] for p in preloads] == [['preload'], ['preload']]


def test_a_core_that_cannot_start_is_reported_with_its_reason(make_core):
    with pytest.raises(CoreUnavailable, match='told to refuse'):
        make_core(refuse_to_start=True)


def test_a_failing_preload_fails_the_start(make_core):
    def preload(send):
        raise RuntimeError('preload file unreadable')
    with pytest.raises(CoreUnavailable, match='preload file unreadable'):
        make_core(on_ready=preload)


def test_stop_answers_waiting_requests_and_ends_the_core(make_core):
    core = make_core()
    pid = core.pid
    results = []
    waiter = threading.Thread(target=lambda: results.append(
        pytest.raises(CoreUnavailable, core.request, directive('HANG'))))
    waiter.start()
    time.sleep(0.3)
    core.stop()
    waiter.join(timeout=30)
    assert results and not waiter.is_alive()
    wait_until(lambda: not pathlib.Path(f'/proc/{pid}').exists()
               or 'Z' in pathlib.Path(f'/proc/{pid}/stat').read_text().split()[2])
    assert 'shutting down' in str(results[0].value)


def test_events_reach_every_listener_in_order_and_a_failing_listener_stops_none(make_core):
    core = make_core()
    first, second = [], []
    done = threading.Event()

    def failing(event):
        first.append(event['revision'])
        raise ValueError('a listener with a bug')

    def recording(event):
        second.append(event['revision'])
        if event['revision'] == 200:
            done.set()
    core.add_event_listener(failing)
    core.add_event_listener(recording)
    reply = core.request(directive('EVENTS', '200'))
    assert reply['response']['queried_objects'] == ['200'], 'the reply is not taken for an event'
    assert done.wait(30)
    assert first == second == list(range(1, 201))

    core.remove_event_listener(recording)
    core.request(directive('EVENTS', '3'))
    wait_until(lambda: len(first) == 203)
    assert len(second) == 200
