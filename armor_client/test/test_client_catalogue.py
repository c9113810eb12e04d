# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Every command of the catalogue has a method, and every method sends what the catalogue says.

A recording transport stands in for the node: the directives are captured, never sent.
"""

import asyncio
import inspect
from typing import Any, List, Tuple

from armor_client import commands, Reference
from armor_client.aio import AsyncArmor, AsyncReference
from armor_client.reference import Armor
from armor_msgs.msg import ArmorDirectiveRes, QueryItem
import pytest

# Keyword arguments that make a method send its other variants (MOUNTED, INFERENCE, OFF...).
VARIANTS = {
    'load_file': [{}, {'mount': True}], 'load_web': [{}, {'mount': True}],
    'save': [{}, {'inferences': True}], 'log_to_screen': [{'on': True}, {'on': False}],
    'log_to_file': [{'path': '/tmp/armor.log'}, {'path': None}],
    'sparql': [{}, {'timeout_ms': 10}], 'classes_of': [{}, {'most_specific': True}],
    'learn_scene': [{'elements': [('SPHERE', [0.0, 0.0, 0.0])], 'threshold': 0.5}],
}


class RecordingTransport:
    """Answers every directive with success and remembers its words and arguments."""

    def __init__(self):
        self.sent: List[Tuple[Tuple[str, str, str], List[str]]] = []

    def call(self, request: Any, timeout_s: Any = None) -> ArmorDirectiveRes:
        self.sent.append(((request.command, request.primary_command_spec,
                           request.secondary_command_spec), list(request.args)))
        return ArmorDirectiveRes(success=True, is_consistent=True, sparql_queried_objects=[
            QueryItem(key='ASK', value='true')])

    def call_list(self, requests: Any, timeout_s: Any = None) -> Any:
        raise AssertionError('no list expected')

    def close(self) -> None:
        """Nothing to release."""


def placeholder(parameter: inspect.Parameter) -> Any:
    annotation = str(parameter.annotation)
    if 'int' in annotation and 'Union' not in annotation:
        return 1
    if 'bool' in annotation and 'Union' not in annotation:
        return True
    if 'float' in annotation and 'Union' not in annotation:
        return 0.5
    return 'FUNCTIONAL' if parameter.name == 'characteristic' else 'x'


def call_args(method: Any, overrides: dict) -> Tuple[list, dict]:
    args, kwargs = [], dict(overrides)
    for parameter in inspect.signature(method).parameters.values():
        if parameter.name in overrides:
            continue
        if parameter.kind == parameter.VAR_POSITIONAL:
            args += ['a', 'b']
        elif parameter.default is parameter.empty:
            args.append(placeholder(parameter))
    return args, kwargs


# Public methods that send no catalogue command of their own (subscribe and changes use the
# subscription services and the change topic).
NOT_COMMANDS = {'call', 'call_list', 'close', 'reference', 'batch', 'mounted', 'subscribe',
                'changes'}


def command_methods(target: Any) -> List[str]:
    return [name for name in dir(target) if not name.startswith('_') and name not in NOT_COMMANDS
            and callable(getattr(target, name))]


def sent_by_sync() -> dict:
    """For each command method of Armor and Reference, the words it sends."""
    sent = {}
    for owner in ('armor', 'reference'):
        for name in command_methods(Armor('me', transport=RecordingTransport()).reference('ref')
                                    if owner == 'reference' else Armor):
            transport = RecordingTransport()
            armor = Armor('me', transport=transport)
            method = getattr(armor.reference('ref') if owner == 'reference' else armor, name)
            for overrides in VARIANTS.get(name, [{}]):
                args, kwargs = call_args(method, overrides)
                method(*args, **kwargs)
            sent[name] = {words for words, _ in transport.sent}
    return sent


def sent_by_async() -> dict:
    """The same for AsyncArmor and AsyncReference."""
    sent = {}

    async def run() -> None:
        for owner in ('armor', 'reference'):
            probe = AsyncArmor('me', transport=RecordingTransport())
            names = command_methods(probe.reference('ref') if owner == 'reference' else probe)
            await probe.close()
            for name in names:
                transport = RecordingTransport()
                armor = AsyncArmor('me', transport=transport)
                method = getattr(armor.reference('ref') if owner == 'reference' else armor, name)
                for overrides in VARIANTS.get(name, [{}]):
                    args, kwargs = call_args(method, overrides)
                    await method(*args, **kwargs)
                await armor.close()
                sent[name] = {words for words, _ in transport.sent}
    asyncio.run(run())
    return sent


SENT_BY_SYNC = sent_by_sync()
SENT_BY_ASYNC = sent_by_async()


@pytest.mark.parametrize('command', commands.COMMANDS, ids=lambda c: c.name)
def test_the_method_of_every_command_sends_it(command):
    assert [name for name, sent in SENT_BY_SYNC.items() if command.words in sent]
    assert [name for name, sent in SENT_BY_ASYNC.items() if command.words in sent]


def test_every_public_method_of_the_sync_client_has_an_async_twin():
    for sync, twin in ((Reference, AsyncReference), (Armor, AsyncArmor)):
        public = {name for name in dir(sync) if not name.startswith('_')}
        assert public - set(dir(twin)) == set(), sync.__name__


def test_arguments_are_sent_in_armors_order():
    transport = RecordingTransport()
    reference = Armor('me', transport=transport).reference('ref')
    reference.replace_data_value('visitedAt', 'kitchen', 20, 10, 'LONG')
    reference.replace_object_value('isIn', 'robot1', 'bedroom', 'kitchen')
    reference.add_data_value('charging', 'robot1', True)
    reference.add_min_cardinality('Robot', 'isIn', 1, 'Location')
    assert transport.sent == [
        (('REPLACE', 'DATAPROP', 'IND'), ['visitedAt', 'kitchen', 'LONG', '20', '10']),
        (('REPLACE', 'OBJECTPROP', 'IND'), ['isIn', 'robot1', 'bedroom', 'kitchen']),
        (('ADD', 'DATAPROP', 'IND'), ['charging', 'robot1', 'BOOLEAN', 'true']),
        (('ADD', 'CARDINALITY', 'MIN'), ['Robot', 'isIn', '1', 'Location'])]


def test_split_directive_takes_the_longest_known_command():
    assert commands.split_directive(['QUERY', 'IND', 'CLASS', 'Room'])[0].name == 'QUERY IND CLASS'
    command, args = commands.split_directive(['query', 'ind', 'robot1'])
    assert (command.name, args) == ('QUERY IND', ['robot1'])
    command, args = commands.split_directive(['QUERY', 'IND', '--', 'CLASS'])
    assert (command.name, args) == ('QUERY IND', ['CLASS'])
    assert commands.split_directive(['ADD', 'MIN', 'CARDINALITY', 'A'])[0].name == \
        'ADD CARDINALITY MIN'
    assert commands.split_directive(['FLY', 'AWAY']) == (None, ['FLY', 'AWAY'])


def test_next_words_lists_the_specs_that_can_follow():
    assert commands.next_words(['QUERY', 'CLASS']) == [
        'CLASS', 'DISJOINT', 'DL', 'EQUIVALENT', 'IND', 'RESTRICTIONS', 'SUPER']
    assert commands.next_words(['LOG']) == ['FILE', 'SCREEN']
    assert commands.next_words(['QUERY', 'IND', 'CLASS']) == []
