# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A node's plugin faces become methods of one session's references (no node needed here).

The session's transport is a stand-in that answers GET CATALOGUE with a catalogue holding
plugin commands and records every other directive; over ROS 2 with real plugin jars:
tests/integration/test_plugins.py.
"""

import inspect
import json
import warnings

from armor_client import Armor
from armor_client.aio import AsyncArmor
from armor_msgs.msg import ArmorDirectiveRes
import pytest


def _command(key, kind, required, face, origin='shop.jar', variadic=False):
    return {'key': key, 'words': key.split(), 'aliases': [], 'kind': kind,
            'changes_ontology': kind == 'manipulation',
            'summary': f'does {key.lower().rstrip(" -")}',
            'origin': origin, 'face': face,
            'args': {'required': required, 'optional': [], 'variadic': variadic}}


def _face(method, answer, *parameters):
    return {'method': method, 'answer': answer,
            'parameters': [{'name': n, 'type': t} for n, t in parameters]}


CATALOGUE = {'format': 1, 'exit_codes': [], 'settings': [], 'commands': [
    _command('ADD STOCK -', 'manipulation', ['ind', 'n'],
             _face('stock', 'none', ('item', 'string'), ('count', 'int'))),
    _command('QUERY SHELVES -', 'query', ['class', 'class'],
             _face('shelves', 'entities', ('classes', 'string')), variadic=True),
    _command('QUERY CLASH -', 'query', ['class'],
             _face('instances', 'entities', ('cls', 'string'))),
    _command('QUERY TWICE -', 'query', [], _face('stock', 'entities'), origin='other.jar'),
    _command('QUERY IND CLASS', 'query', ['class'], None, origin='core'),
]}


class FakeTransport:
    """Answers GET CATALOGUE with CATALOGUE, every other directive with two entities."""

    def __init__(self):
        self.sent = []

    def call(self, request, timeout_s=None):
        response = ArmorDirectiveRes(success=True, is_consistent=True)
        if (request.command, request.primary_command_spec) == ('GET', 'CATALOGUE'):
            response.queried_objects = [json.dumps(CATALOGUE)]
        else:
            self.sent.append((request.reference_name, request.command,
                              request.primary_command_spec, list(request.args)))
            response.queried_objects = ['<http://example.org/shop#b>',
                                        '<http://example.org/shop#a>']
        return response

    def close(self):
        pass


def test_a_plugin_face_is_a_method_reading_its_answer_as_a_built_in_face_does():
    transport = FakeTransport()
    shop = Armor('t', transport=transport).reference('shop')
    with pytest.warns(RuntimeWarning) as warned:
        assert shop.shelves('Shelf', 'Rack') == ['b', 'a']
    assert shop.stock('apple', 3) is None
    assert transport.sent == [('shop', 'QUERY', 'SHELVES', ['Shelf', 'Rack']),
                              ('shop', 'ADD', 'STOCK', ['apple', '3'])]
    assert str(inspect.signature(shop.stock)) == '(item: str, count: int) -> None'
    assert str(inspect.signature(shop.shelves)) == '(*classes: str) -> List[str]'
    assert shop.stock.__doc__.startswith('Does add stock (ADD STOCK; plugin shop.jar).')
    # Refused: a name the client has, and one an earlier plugin took; each warned once.
    assert sorted(str(w.message) for w in warned) == [
        'QUERY CLASH (plugin shop.jar) gets no method instances(): Reference already has '
        'instances(); send it with call()',
        'QUERY TWICE (plugin other.jar) gets no method stock(): ADD STOCK (plugin shop.jar) '
        'has that method; send it with call()']
    with pytest.raises(TypeError, match=r"stock\(\): count must be a whole number, not 'x'"):
        shop.stock('apple', 'x')
    with pytest.raises(TypeError, match=r'stock\(\): count must be a whole number, not bool'):
        shop.stock('apple', True)
    with pytest.raises(TypeError, match=r"stock\(\): missing a required argument: 'count'"):
        shop.stock('apple')
    assert len(transport.sent) == 2, 'a refused call sends nothing'


def test_a_batch_queues_a_plugin_change_and_has_no_plugin_query():
    transport = FakeTransport()
    with pytest.warns(RuntimeWarning):
        batch = Armor('t', transport=transport).reference('shop').batch()
    assert batch.stock('pear', 2) is None
    assert [(r.command, r.primary_command_spec, list(r.args)) for r in batch.requests] == [
        ('ADD', 'STOCK', ['pear', '2'])]
    assert not hasattr(batch, 'shelves') and transport.sent == []


def test_only_the_session_that_learned_has_the_methods():
    learned = Armor('t', transport=FakeTransport())
    other = Armor('u', transport=FakeTransport())
    with pytest.warns(RuntimeWarning):
        added = learned.learn_plugin_methods().added
    assert sorted(added) == ['shelves', 'stock']
    assert 'stock' in vars(type(learned.reference('shop')))
    assert 'stock' not in vars(type(other.reference('shop')))


def test_an_async_reference_awaits_a_plugin_method():
    import asyncio

    async def run():
        transport = FakeTransport()
        async with AsyncArmor('t', transport=transport) as armor:
            with pytest.warns(RuntimeWarning):
                await armor.learn_plugin_methods()
            return await armor.reference('shop').shelves('Shelf')

    assert asyncio.run(run()) == ['b', 'a']


class RestartingTransport(FakeTransport):
    """A node that can be replaced by one with other plugins (another catalogue, identity)."""

    def __init__(self, commands):
        super().__init__()
        self.commands, self.identity, self.catalogues_read, self.replaced = commands, 1, 0, 0

    def restart(self, commands):
        self.commands, self.identity = commands, self.identity + 1

    def node_identity(self):
        return frozenset({self.identity})

    def node_replaced(self):
        self.replaced += 1

    def call(self, request, timeout_s=None):
        if (request.command, request.primary_command_spec) == ('GET', 'CATALOGUE'):
            self.catalogues_read += 1
            return ArmorDirectiveRes(success=True, queried_objects=[json.dumps(
                {**CATALOGUE, 'commands': self.commands})])
        return super().call(request, timeout_s)


STOCK, SHELVES = CATALOGUE['commands'][0], CATALOGUE['commands'][1]


def test_a_node_restarted_with_other_plugins_is_learned_again_on_its_own():
    transport = RestartingTransport([STOCK])
    shop = Armor('t', transport=transport).reference('shop')
    assert shop.stock('apple', 1) is None and transport.catalogues_read == 1
    assert shop.stock('apple', 2) is None and transport.catalogues_read == 1, 'asked once'
    # Restarted without the plugin of ADD STOCK, with the one of QUERY SHELVES.
    transport.restart([SHELVES])
    with pytest.raises(AttributeError, match='nor does a plugin of the node give one'):
        shop.stock('apple', 3)
    assert transport.catalogues_read == 2 and transport.replaced == 1
    assert 'stock' not in dir(shop) and shop.shelves('Shelf') == ['b', 'a']
    # Restarted with both: a name it lacks is learned again without learn_plugin_methods().
    transport.restart([STOCK, SHELVES])
    assert shop.stock('pear', 4) is None and transport.catalogues_read == 3
    assert [sent[1:] for sent in transport.sent] == [
        ('ADD', 'STOCK', ['apple', '1']), ('ADD', 'STOCK', ['apple', '2']),
        ('QUERY', 'SHELVES', ['Shelf']), ('ADD', 'STOCK', ['pear', '4'])]


def test_a_method_written_by_hand_for_a_plugin_command_keeps_its_name_without_a_warning():
    planner = _command('QUERY PDDL PROBLEM', 'query', ['mapping path or text'],
                       _face('pddl_problem', 'expressions', ('mapping', 'string')),
                       origin='armor-pddl.jar')
    other = _command('QUERY OTHER PROBLEM', 'query', ['mapping path or text'],
                     _face('pddl_problem', 'expressions', ('mapping', 'string')))
    transport = RestartingTransport([planner])
    armor = Armor('t', transport=transport)
    with warnings.catch_warnings():
        warnings.simplefilter('error')
        learned = armor.learn_plugin_methods()
    assert learned.added == {} and learned.refused == {}
    transport.restart([other])
    with pytest.warns(RuntimeWarning, match='Reference already has pddl_problem'):
        assert 'QUERY OTHER PROBLEM' in armor.learn_plugin_methods().refused
