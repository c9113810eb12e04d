# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Issue 18: ROS 1 client code's argument idioms, sent over ROS 2 to the live node.

ROS 1 ARMOR read only the arguments a command named, so old client code sends dummies
(``REASON`` with ``['']``), flags as Python prints them (``True``) and type words in any case
(``Long``). Every command ARMOR had is sent here with ARMOR's idioms and must answer, and change,
exactly what the same call without them does; a surplus argument that says something is 207.
"""

import json
import re
import time

from armor_client.armor_api import ArmorClient
from armor_msgs.msg import ArmorDirectiveReq
from armor_msgs.srv import ArmorDirective
from conftest import iris, ONTOLOGIES
import pytest

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')

# One valid call of each fixed-argument command ARMOR had (ARMOR's dispatch table), on robotics.owl
# loaded as '@ref' and mounted by the caller. '@file' is a new file in the node's scratch folder.
ARMOR_CALLS = [
    ('LOAD FILE', [ROBOTICS, 'http://www.example.org/robotics', 'false', 'PELLET', 'false']),
    ('LOAD FILE MOUNTED', [ROBOTICS, '', 'False', 'HERMIT', 'True']),
    ('LOAD WEB', ['https://example.org/onto.owl', '', 'false', '', 'false']),
    ('LOAD WEB MOUNTED', ['https://example.org/onto.owl', '', 'false', '', 'false']),
    ('SAVE', ['@file']), ('SAVE INFERENCE', ['@file']), ('DROP', []), ('MOUNT', []),
    ('UNMOUNT', []), ('GET ALL REFS', []), ('GET REF CLIENT', ['@ref']), ('LOG SCREEN ON', []),
    ('LOG SCREEN OFF', []), ('LOG FILE ON', ['@file']), ('LOG FILE OFF', []), ('APPLY', []),
    ('REASON', []), ('QUERY IND', ['robot1']), ('QUERY IND CLASS', ['OccupiedRoom']),
    ('QUERY DATAPROP IND', ['batteryLevel', 'robot1']),
    ('QUERY OBJECTPROP IND', ['isIn', 'robot1']), ('QUERY CLASS IND', ['robot1', 'true']),
    ('QUERY CLASS CLASS', ['Location']), ('QUERY CLASS RESTRICTIONS', ['OccupiedRoom']),
    ('QUERY IND DATAPROP', ['robot1']), ('QUERY IND OBJECTPROP', ['robot1']),
    ('ADD IND', ['box1']), ('ADD CLASS', ['Charger']), ('ADD IND CLASS', ['bob', 'Person']),
    ('ADD CLASS CLASS', ['Charger', 'Location']),
    ('ADD DATAPROP IND', ['batteryLevel', 'robot1', 'INT', '75']),
    ('ADD OBJECTPROP IND', ['isIn', 'alice', 'bedroom']),
    ('ADD CARDINALITY MIN', ['Robot', 'isIn', '1', 'Location']),
    ('DISJOINT IND CLASS', ['Room']), ('DISJOINT CLASS CLASS', ['Agent']),
    ('MAKE EQUIVALENT CLASS', ['Corridor']), ('REMOVE IND', ['alice']),
    ('REMOVE CLASS', ['Person']), ('REMOVE IND CLASS', ['alice', 'Person']),
    ('REMOVE CLASS CLASS', ['Robot', 'Agent']),
    ('REMOVE DATAPROP IND', ['batteryLevel', 'robot1', 'INTEGER', '80']),
    ('REMOVE OBJECTPROP IND', ['isIn', 'robot1', 'kitchen']),
    ('REPLACE DATAPROP IND', ['batteryLevel', 'robot1', 'INT', '60', '80']),
    ('REPLACE OBJECTPROP IND', ['isIn', 'robot1', 'bedroom', 'kitchen']),
    ('RENAME IND', ['robot1', 'turtlebot']), ('RENAME CLASS', ['Person', 'Human']),
    ('RENAME DATAPROP', ['batteryLevel', 'charge']), ('RENAME OBJECTPROP', ['isIn', 'locatedIn']),
]


def test_every_command_armor_had_is_sent(armor):
    from armor_client import directive
    catalogue = armor.call(directive('test', '', 'GET', 'CATALOGUE'), timeout_s=60)
    commands = json.loads(catalogue.queried_objects[0])['commands']
    fixed = {c['key'].replace(' -', '') for c in commands if not c['args']['variadic']}
    sent = {words for words, _ in ARMOR_CALLS}
    assert sent <= fixed
    # The commands ARMOR had beyond these are variadic: an empty argument is read there.
    assert len(sent) == 48


class _Scene:
    """A reference of its own, robotics.owl mounted by 'test', for one call."""

    def __init__(self, call, scratch, name):
        self.call, self.scratch, self.name = call, scratch, name
        self.loaded = name + '_loaded'
        response = call(name, 'LOAD FILE', ROBOTICS, 'http://www.example.org/robotics', 'false',
                        'PELLET', 'false')
        assert response.success, response.error_description
        assert call(name, 'MOUNT').success

    def send(self, words, args):
        target = self.loaded if words.startswith('LOAD') else self.name
        names = {'@ref': self.name, '@file': str(self.scratch / f'{self.name}.out')}
        return self.call(target, words, *[names.get(a, a) for a in args])

    def state(self):
        """What the node holds for this scene: which of its references exist, mounts, axioms."""
        refs = self.call('', 'GET ALL REFS').queried_objects
        text = [str(sorted(r.replace(self.name, '@') for r in refs if r.startswith(self.name)))]
        for reference in (self.name, self.loaded):
            if reference in refs:
                text.append(str(self.call('', 'GET REF CLIENT', reference).queried_objects))
        if self.name in refs:
            saved = self.scratch / f'{self.name}.ofn'
            assert self.call(self.name, 'SAVE', str(saved), 'functional').success
            text.append(saved.read_text())
        return '\n'.join(text)

    def drop(self):
        for reference in (self.name, self.loaded):
            self.call(reference, 'DROP')


def _answer(response):
    return (response.success, response.exit_code, list(response.queried_objects),
            response.is_consistent)


@pytest.mark.parametrize('words,args', ARMOR_CALLS, ids=[w for w, _ in ARMOR_CALLS])
def test_an_empty_surplus_argument_answers_as_the_call_without(call, armor_node, words, args):
    tag = re.sub(r'\W', '_', words.lower())
    plain = _Scene(call, armor_node.scratch, f'idiom_{tag}_plain')
    dummy = _Scene(call, armor_node.scratch, f'idiom_{tag}_dummy')
    try:
        expected = _answer(plain.send(words, args))
        got = dummy.send(words, [*args, ''])
        assert _answer(got) == expected, got.error_description
        assert dummy.state() == plain.state()
    finally:
        call('', 'LOG FILE OFF')
        call('', 'LOG SCREEN OFF')
        plain.drop()
        dummy.drop()


def test_a_surplus_argument_that_says_something_is_refused(call, armor_node):
    scene = _Scene(call, armor_node.scratch, 'idiom_surplus')
    try:
        before = scene.state()
        for words, args in ARMOR_CALLS:
            refused = scene.send(words, [*args, '', 'kitchen'])
            assert (refused.success, refused.exit_code) == (False, 207), (words, refused)
            assert f'got {len(args) + 2}' in refused.error_description
        assert scene.state() == before
    finally:
        scene.drop()


def test_old_client_code_reasons_with_a_dummy_argument(armor_node):
    """The field case, as the course's state machine sends it through armor_api's ArmorClient."""
    client = ArmorClient('example', 'idiom_patrol', timeout=90, call_timeout=120)
    try:
        # armor_api sends its flags as str(bool): 'True'.
        client.utils.load_ref_from_file(ROBOTICS, 'http://www.example.org/robotics', True,
                                        'PELLET', True)
        assert client.call('ADD', 'IND', 'CLASS', ['bob', 'Person']).success
        assert client.call('ADD', 'OBJECTPROP', 'IND', ['isIn', 'bob', 'bedroom']).success
        before = client.call('QUERY', 'IND', 'CLASS', ['OccupiedRoom'])
        assert before.queried_objects == iris('kitchen')
        reason = client.call('REASON', '', '', [''])
        assert reason.success, reason.error_description
        after = client.call('QUERY', 'IND', 'CLASS', ['OccupiedRoom'])
        assert after.queried_objects == iris('bedroom', 'kitchen')
        assert client.call('APPLY', '', '', ['']).success
        assert client.call('GET', 'ALL', 'REFS', ['']).success
    finally:
        client.call('DROP', '', '', [''])
        client.transport.close()


def test_plain_rclpy_client_with_armors_idioms(armor_node, armor):
    """Ported ROS 1 code calls the service with a plain rclpy client, as rospy's ServiceProxy."""
    import rclpy
    node = rclpy.create_node('idiom_plain_rclpy')
    try:
        service = node.create_client(ArmorDirective, 'armor_interface_srv')
        assert service.wait_for_service(timeout_sec=60)

        def send(command, primary, secondary, args):
            request = ArmorDirective.Request(armor_request=ArmorDirectiveReq(
                client_name='ported', reference_name='idiom_rclpy', command=command,
                primary_command_spec=primary, secondary_command_spec=secondary, args=args))
            future = service.call_async(request)
            deadline = time.monotonic() + 120
            while not future.done() and time.monotonic() < deadline:
                rclpy.spin_once(node, timeout_sec=0.1)
            assert future.done(), command
            return future.result().armor_response

        assert send('LOAD', 'FILE', '', [ROBOTICS, '', 'True', 'Pellet', 'True']).success
        assert send('MOUNT', '', '', ['']).success
        assert send('REPLACE', 'DATAPROP', 'IND', ['visitedAt', 'bedroom', 'Long', '17',
                                                   '1700000000']).success
        assert send('ADD', 'DATAPROP', 'IND', ['charging', 'robot1', 'Boolean', 'True']).success
        assert send('REASON', '', '', ['']).success
        assert send('QUERY', 'DATAPROP', 'IND', ['visitedAt', 'bedroom', '']).queried_objects == [
            '"17"^^xsd:long']
        assert send('QUERY', 'DATAPROP', 'IND', ['charging', 'robot1']).queried_objects == [
            '"true"^^xsd:boolean']
        most_specific = send('QUERY', 'CLASS', 'IND', ['robot1', 'True']).queried_objects
        every = send('QUERY', 'CLASS', 'IND', ['robot1', '']).queried_objects
        assert set(most_specific) < set(every)
        assert send('UNMOUNT', '', '', ['']).success
        assert send('DROP', '', '', ['']).success
    finally:
        node.destroy_node()


@pytest.mark.parametrize('flag', ['True', 'true', 'TRUE', 'False', 'false', ''])
def test_flags_in_any_case_or_empty(call, flag):
    reference = 'idiom_flag_' + (flag.lower() or 'empty') + str(len(flag))
    try:
        loaded = call(reference, 'LOAD FILE', ROBOTICS, '', flag, '', flag)
        assert loaded.success, loaded.error_description
        assert call(reference, 'ADD IND CLASS', 'bob', 'Person').success
        buffered = flag.lower() == 'true'
        people = call(reference, 'QUERY IND CLASS', 'Person').queried_objects
        assert people == (iris('alice') if buffered else iris('alice', 'bob'))
    finally:
        call(reference, 'DROP')


def test_armors_reasoner_names(call):
    for name in ('FACT', 'SNOROCKET'):
        reference = f'idiom_reasoner_{name.lower()}'
        try:
            assert call(reference, 'LOAD FILE', ROBOTICS, '', 'false', name, 'false').success
            occupied = call(reference, 'QUERY IND CLASS', 'OccupiedRoom').queried_objects
            # JFact uses the inverse property the definition needs; ELK (for Snorocket) does not.
            assert occupied == (iris('kitchen') if name == 'FACT' else [])
        finally:
            call(reference, 'DROP')
