# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The asyncio client against the live node: same answers as the sync client, concurrently.

AsyncReference shares its command methods with Reference (armor_client.operations); the unit
test test_client_catalogue checks that each sends its command, these check the answers.
"""

import asyncio

from armor_client import (Armor, ArmorArgumentError, ArmorCallTimeout, ArmorFileError,
                          ArmorMountError, ArmorUnknownReferenceError)
from armor_client.aio import AsyncArmor
from conftest import ONTOLOGIES
import pytest

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')

# Every query method with arguments; the async answer must equal the sync one.
QUERIES = [
    ('types_of', ('robot1',)), ('classes_of', ('robot1', True)), ('instances', ('Room',)),
    ('dl_instances', ('Agent and isIn some Room',)), ('same_individuals', ('robot1',)),
    ('data_properties_of', ('robot1',)), ('object_properties_of', ('robot1',)),
    ('data_values', ('batteryLevel', 'robot1')), ('object_values', ('isIn', 'robot1')),
    ('subclasses', ('Agent',)), ('dl_subclasses', ('Agent and isIn some Room',)),
    ('superclasses', ('Robot',)), ('equivalent_classes', ('Robot',)),
    ('disjoint_classes', ('Room',)), ('restrictions', ('OccupiedRoom',)),
    ('object_subproperties', ('isIn',)), ('data_subproperties', ('visitedAt',)),
    ('sparql', ('SELECT ?r WHERE { ?r a :Room }',)), ('sparql_lines', ('ASK { ?r a :Room }',)),
    ('ask', ('ASK { :robot1 :isIn :kitchen }',)), ('check_consistency', ()),
]


def run(coroutine):
    return asyncio.run(coroutine)


@pytest.fixture
def loaded(armor):
    """A copy of robotics.owl as "aio_robotics", dropped afterwards; yields its name."""
    Armor('aio_test', transport=armor).load_file('aio_robotics', ROBOTICS)
    yield 'aio_robotics'
    Armor('aio_test', transport=armor).reference('aio_robotics').drop()


def test_every_query_answers_as_the_sync_client(armor, loaded):
    sync = Armor('aio_test', transport=armor).reference(loaded)

    async def ask_all():
        async with AsyncArmor('aio_test', transport=armor) as session:
            reference = session.reference(loaded)
            return await asyncio.gather(*(getattr(reference, name)(*args)
                                          for name, args in QUERIES))
    answers = run(ask_all())
    for (name, args), answer in zip(QUERIES, answers):
        assert answer == getattr(sync, name)(*args), name
    assert answers[2] == ['bedroom', 'kitchen'] and answers[-2] is True


def test_changes_batches_and_mounts(armor, loaded):
    async def scenario():
        async with AsyncArmor('aio_test', transport=armor) as session:
            reference = session.reference(loaded)
            await reference.add_individual_to_class('bob', 'Person')
            await reference.add_object_value('isIn', 'bob', 'bedroom')
            occupied = await reference.instances('OccupiedRoom')
            async with reference.batch() as batch:
                batch.replace_object_value('isIn', 'bob', 'kitchen', 'bedroom')
                batch.add_data_value('visitedAt', 'kitchen', 1700000100, 'LONG')
            after_batch = await reference.instances('OccupiedRoom')
            with pytest.raises(ArmorArgumentError) as failed:
                async with reference.batch() as batch:
                    batch.remove_individual('bob')
                    batch.add_data_value('batteryLevel', 'robot1', 'x', 'INTEGER')
            people = await reference.instances('Person')
            other = AsyncArmor('aio_other', transport=armor)
            async with reference.mounted():
                holder = await reference.mounted_by()
                with pytest.raises(ArmorMountError):
                    await other.reference(loaded).remove_individual('bob')
            await other.close()
            await reference.mount()
            held = await session.mounted_by(loaded)
            await reference.unmount()
            return occupied, after_batch, failed.value, people, holder, held, batch.consistent
    occupied, after_batch, failure, people, holder, held, consistent = run(scenario())
    assert occupied == ['bedroom', 'kitchen'] and after_batch == ['kitchen']
    assert failure.index == 1 and [r.exit_code for r in failure.responses] == [212, 101]
    assert people == ['alice', 'bob'] and consistent is None
    assert holder == 'aio_test' and held == 'aio_test'


def test_session_methods(armor, armor_node):
    log = armor_node.scratch / 'aio.log'

    async def scenario():
        async with AsyncArmor('aio_test', transport=armor) as session:
            loaded = await session.load_file('aio_mounted', ROBOTICS, mount=True)
            holder = await loaded.mounted_by()
            await loaded.unmount()
            await loaded.save(str(armor_node.scratch / 'aio.ttl'), 'turtle')
            created = await session.create('aio_created', 'http://example.org/aio')
            names = await session.references()
            await session.log_to_file(str(log))
            await created.add_individual('thing1')
            await session.log_to_file(None)
            await session.log_to_screen(True)
            await session.log_to_screen(False)
            await loaded.drop()
            await created.drop()
            with pytest.raises(ArmorUnknownReferenceError):
                await created.instances('Room')
            raw = await session.call('', 'GET', 'ALL', 'REFS')
            with pytest.raises(ArmorFileError) as no_web:
                await session.load_web('aio_web', 'https://example.org/onto.owl')
            return holder, names, list(raw.queried_objects), no_web.value
    holder, names, remaining, no_web = run(scenario())
    assert holder == 'aio_test' and {'aio_mounted', 'aio_created'} <= set(names)
    assert 'aio_mounted' not in remaining and no_web.exit_code == 218
    assert 'thing1' in log.read_text()
    assert '@prefix' in (armor_node.scratch / 'aio.ttl').read_text()


def test_awaits_time_out(armor):
    async def impatient():
        async with AsyncArmor('aio_test', transport=armor, timeout_s=1e-6) as session:
            await session.references()
    with pytest.raises(ArmorCallTimeout):
        run(impatient())
