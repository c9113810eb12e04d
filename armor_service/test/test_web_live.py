# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The web view's live updates and shared answers, without a browser or a core.

LiveUpdates must coalesce: a page is sent the newest table of revisions, never a backlog, so a
robot changing facts every few milliseconds costs an open page constant memory and at most one
table per COALESCE_S. SharedAnswers must fetch once for everyone asking at the same revision,
and again once the revision moves.
"""

import asyncio
import json
import threading
import time

from armor_service.web import live as live_module
from armor_service.web.live import LiveUpdates
from armor_service.web.reads import BUSY_SHARE_INVERSE, SharedAnswers


def change(reference: str, revision: int, command: str = 'ADD', consistent: bool = True) -> dict:
    return {'event': 'change', 'reference': reference, 'revision': revision,
            'client_name': 'robot', 'directives': [{'command': command}], 'exit_code': 0,
            'is_consistent': consistent, 'stamp_ns': 1}


def test_a_burst_of_changes_reaches_a_page_as_a_few_tables_ending_with_the_newest():
    async def scenario():
        hub = LiveUpdates(asyncio.get_running_loop())
        broadcaster = asyncio.create_task(hub.broadcast())
        page = hub.join()
        first = json.loads(await page.next_message())
        assert first['references'] == {}

        # Events arrive on another thread, as CoreProcess delivers them.
        def robot():
            for revision in range(1, 2001):
                hub.on_event(change('map', revision))
        sender = threading.Thread(target=robot)
        sender.start()
        sender.join()
        received = []
        while True:
            try:
                received.append(json.loads(await asyncio.wait_for(page.next_message(), 1.0)))
            except asyncio.TimeoutError:
                break
        broadcaster.cancel()
        return received

    tables = asyncio.run(scenario())
    # 2000 changes in far less than a coalescing period each: a handful of tables, not 2000.
    assert 1 <= len(tables) <= 5
    assert tables[-1]['references']['map']['revision'] == 2000
    assert tables[-1]['events'] == 2000


def test_a_page_that_does_not_read_holds_one_table_not_a_queue(monkeypatch):
    monkeypatch.setattr(live_module, 'COALESCE_S', 0.0)

    async def scenario():
        hub = LiveUpdates(asyncio.get_running_loop())
        broadcaster = asyncio.create_task(hub.broadcast())
        page = hub.join()
        for revision in range(1, 301):
            hub.on_event(change('map', revision))
            await asyncio.sleep(0)  # the broadcaster offers each table
        await asyncio.sleep(0.05)
        only = json.loads(await page.next_message())
        try:
            extra = await asyncio.wait_for(page.next_message(), 0.2)
        except asyncio.TimeoutError:
            extra = None
        broadcaster.cancel()
        return only, extra

    only, extra = asyncio.run(scenario())
    assert only['references']['map']['revision'] == 300
    assert extra is None


def test_consistency_and_drops_are_in_the_table():
    async def scenario():
        hub = LiveUpdates(asyncio.get_running_loop())
        hub.on_event(change('a', 0, command='LOAD'))
        hub.on_event(change('b', 4, consistent=False))
        hub.on_event(change('a', 1, command='DROP'))
        hub.on_event({'event': 'something_else', 'reference': 'b'})
        return json.loads(hub.table()), hub.version('b'), hub.version('a'), hub.version()

    table, version_b, version_a, events = asyncio.run(scenario())
    assert table['references'] == {'b': {'revision': 4, 'consistent': False, 'client': 'robot',
                                         'stamp_ns': 1}}
    assert (version_b, version_a, events) == (4, None, 3)


def test_pages_that_leave_are_forgotten():
    async def scenario():
        hub = LiveUpdates(asyncio.get_running_loop())
        pages = [hub.join() for _ in range(1000)]
        for page in pages:
            hub.leave(page)
        return len(hub._pages)

    assert asyncio.run(scenario()) == 0


def test_shared_answers_fetch_once_per_revision():
    async def scenario():
        answers = SharedAnswers()
        fetches = []
        release = asyncio.Event()

        async def fetch():
            fetches.append(1)
            await release.wait()
            return {'fetch': len(fetches)}

        waiting = [asyncio.create_task(answers.get('classes', 7, 30.0, fetch)) for _ in range(5)]
        await asyncio.sleep(0.01)
        release.set()
        bodies = await asyncio.gather(*waiting)
        again = await answers.get('classes', 7, 30.0, fetch)
        moved = await answers.get('classes', 8, 30.0, fetch)
        expired = await answers.get('classes', 8, 0.0, fetch)
        return bodies, again, moved, expired, len(fetches)

    bodies, again, moved, expired, fetches = asyncio.run(scenario())
    assert {json.loads(body)['fetch'] for body in bodies} == {1}
    assert json.loads(again) == {'fetch': 1}
    assert json.loads(moved) == {'fetch': 2}
    assert json.loads(expired) == {'fetch': 3}
    assert fetches == 3


def test_reads_of_a_reference_take_turns_and_leave_it_nine_tenths_of_the_time():
    async def scenario():
        answers = SharedAnswers()
        spans = []

        def slow(name):
            async def fetch():
                started = time.monotonic()
                await asyncio.sleep(0.05)
                spans.append((name, started, time.monotonic()))
                return {}
            return fetch
        # Two views of one reference asked at once, and one of another reference.
        await asyncio.gather(answers.get('graph', 1, 30.0, slow('graph'), 'map'),
                             answers.get('classes', 1, 30.0, slow('classes'), 'map'),
                             answers.get('graph-b', 1, 30.0, slow('other'), 'other'))
        return {name: (start, end) for name, start, end in spans}

    spans = asyncio.run(scenario())
    first, second = sorted([spans['graph'], spans['classes']])
    # One after the other, the second no sooner than 9 times the first's duration (however
    # long a loaded machine made it) after the first ended; the other reference did not wait.
    # The slack is the event loop's: a timer may fire up to its clock resolution early.
    took = first[1] - first[0]
    assert second[0] - first[1] >= (BUSY_SHARE_INVERSE - 1) * took - 0.001
    assert spans['other'][0] < first[1]


def test_a_question_asked_once_takes_its_turn_but_holds_no_panel_back():
    async def scenario():
        answers = SharedAnswers()
        spans = {}

        def timed(name, duration):
            async def fetch():
                started = time.monotonic()
                await asyncio.sleep(duration)
                spans[name] = (started, time.monotonic())
                return {}
            return fetch
        view = asyncio.create_task(answers.get('classes', 1, 30.0, timed('classes', 0.05), 'map'))
        await asyncio.sleep(0.01)
        await answers.get('why', 1, 30.0, timed('why', 0.3), 'map', on_demand=True)
        await view
        await answers.get('individual', 1, 30.0, timed('individual', 0.01), 'map')
        return spans

    spans = asyncio.run(scenario())
    # The question waited for the view in flight (turns), not for the view's pause after it.
    assert spans['why'][0] >= spans['classes'][1] - 0.001
    assert spans['why'][0] - spans['classes'][1] < (BUSY_SHARE_INVERSE - 1) * 0.05
    # The next panel owes the view before the question its pause, not 9 x the question's 0.3 s.
    waited = spans['individual'][0] - spans['why'][1]
    assert waited < (BUSY_SHARE_INVERSE - 1) * 0.3 / 2, waited


def test_a_failed_fetch_is_not_kept():
    async def scenario():
        answers = SharedAnswers()
        calls = []

        async def failing():
            calls.append(1)
            raise RuntimeError('core gone')

        outcomes = []
        for _ in range(2):
            try:
                await answers.get('overview', 1, 30.0, failing)
            except RuntimeError as error:
                outcomes.append(str(error))
        return outcomes, len(calls)

    outcomes, calls = asyncio.run(scenario())
    assert outcomes == ['core gone', 'core gone'] and calls == 2


def test_shared_answers_keep_a_bounded_number():
    async def scenario():
        answers = SharedAnswers(entries=10)

        async def fetch():
            return {}
        for key in range(100):
            await answers.get(key, 0, 30.0, fetch)
        return len(answers._entries)

    assert asyncio.run(scenario()) == 10


def test_bound_to_loopback_only_loopback_names_are_answered():
    from armor_service.web.server import _host_allowed
    for host in ('127.0.0.1:8080', 'localhost:8080', '[::1]:8080', 'LOCALHOST', '127.0.0.2'):
        assert _host_allowed('127.0.0.1', host), host
    for host in ('attacker.example:8080', 'attacker.example', '10.0.0.5:8080', ''):
        assert not _host_allowed('127.0.0.1', host), host
    assert _host_allowed('0.0.0.0', 'robot.lab:8080')
