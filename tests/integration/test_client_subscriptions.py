# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The client library's subscriptions and change watches against the live node (issue 12)."""

import asyncio
import queue
import time

from armor_client import Armor, ArmorArgumentError, ArmorUnknownReferenceError
from armor_client.aio import AsyncArmor
from conftest import ONTOLOGIES
import pytest

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')


@pytest.fixture
def session(armor):
    return Armor('subscriber', transport=armor, timeout_s=120)


@pytest.fixture
def house(session):
    """A copy of robotics.owl of this test's own."""
    reference = session.load_file('client_sub_house', ROBOTICS)
    yield reference
    reference.drop()


def take(changes: queue.Queue, timeout_s: float = 30.0):
    return changes.get(timeout=timeout_s)


def test_a_callback_hears_the_answer_then_each_room_that_becomes_and_stops_being_occupied(house):
    changes = queue.Queue()
    with house.subscribe('QUERY IND CLASS OccupiedRoom', changes.put) as rooms:
        initial = changes.get_nowait()
        assert initial.initial and initial.added == ['kitchen'] and initial.answer == ['kitchen']
        house.replace_object_value('isIn', 'alice', 'bedroom', 'corridor1')
        entered = take(changes)
        assert (entered.added, entered.removed, entered.answer) == (
            ['bedroom'], [], ['bedroom', 'kitchen'])
        assert entered.revision == initial.revision + 1 and entered.missed == 0
        house.replace_object_value('isIn', 'alice', 'corridor1', 'bedroom')
        left = take(changes)
        assert (left.added, left.removed) == ([], ['bedroom'])
        assert rooms.answer == ['kitchen'] and rooms.revision == left.revision
    house.replace_object_value('isIn', 'alice', 'bedroom', 'corridor1')
    with pytest.raises(queue.Empty):
        changes.get(timeout=1.0)


def test_sparql_rows_and_full_iris(house):
    changes = queue.Queue()
    query = 'SELECT ?who ?room WHERE { ?who :isIn ?room . ?room a :Room }'
    with house.subscribe(query, changes.put):
        assert take(changes).answer == ['who=robot1; room=kitchen']
        house.add_object_value('isIn', 'alice', 'bedroom')
        assert take(changes).added == ['who=alice; room=bedroom']
    with house.subscribe('IND CLASS Robot', changes.put, iris=True):
        assert take(changes).answer == ['http://www.example.org/robotics#robot1']


def test_what_is_not_a_query_is_refused(session, house):
    with pytest.raises(ArmorArgumentError) as refused:
        house.subscribe('ADD IND CLASS robot9 Robot', print)
    assert 'no QUERY command' in str(refused.value)
    with pytest.raises(ArmorArgumentError) as malformed:
        house.subscribe('SELECT WHERE {', print)
    assert malformed.value.exit_code == 208
    with pytest.raises(ArmorUnknownReferenceError):
        session.reference('no_such_house').subscribe('QUERY IND CLASS Robot', print)


def test_the_change_watch_hears_each_change_with_its_revision(session, house):
    changes = queue.Queue()
    with session.changes(changes.put, reference=house.name):
        deadline = time.monotonic() + 30
        while changes.empty():  # the watch joins the topic in a fraction of a second
            house.add_individual_to_class(f'probe{time.monotonic_ns()}', 'Robot')
            assert time.monotonic() < deadline
            time.sleep(0.3)
        while not changes.empty():
            probe = changes.get()
        with house.batch() as batch:
            batch.add_object_value('isIn', 'alice', 'bedroom')
            batch.add_individual_to_class('robot2', 'Robot')
        listed = take(changes)
    assert listed.reference == house.name and listed.revision == probe.revision + 1
    assert listed.missed == () and listed.client == 'subscriber' and listed.consistent
    assert listed.describe() == 'ADD OBJECTPROP IND isIn alice bedroom; ADD IND CLASS robot2 Robot'


def test_async_iterators_of_answers_and_changes(armor, house):
    async def main():
        async with AsyncArmor('aio_subscriber', transport=armor) as session:
            reference = session.reference(house.name)
            async with session.changes(house.name) as changes:
                while True:  # the watch joins the topic in a fraction of a second
                    await reference.add_individual_to_class(f'probe{time.monotonic_ns()}', 'Robot')
                    try:
                        await asyncio.wait_for(changes.__anext__(), 1.0)
                        break
                    except asyncio.TimeoutError:
                        continue
                async with reference.subscribe('QUERY IND CLASS OccupiedRoom') as rooms:
                    iterator = rooms.__aiter__()
                    initial = await asyncio.wait_for(iterator.__anext__(), 30)
                    await reference.add_object_value('isIn', 'alice', 'bedroom')
                    entered = await asyncio.wait_for(iterator.__anext__(), 30)
                change = await asyncio.wait_for(changes.__anext__(), 30)
                while change.revision < entered.revision:
                    change = await asyncio.wait_for(changes.__anext__(), 30)
            return initial, entered, change
    initial, entered, change = asyncio.run(main())
    assert initial.initial and initial.answer == ['kitchen']
    assert entered.added == ['bedroom'] and entered.revision == initial.revision + 1
    assert change.revision == entered.revision and change.client == 'aio_subscriber'
    assert change.describe() == 'ADD OBJECTPROP IND isIn alice bedroom'
