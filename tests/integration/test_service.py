# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The node answers ARMOR directives over ROS 2 with the contract's fields and codes."""

from armor_client import directive
from conftest import iri, iris, ONTOLOGIES
import pytest

ALL_REASONERS = ['HERMIT', 'PELLET', 'JFACT', 'ELK']
# ELK is OWL 2 EL only: it cannot use the inverse property that defines OccupiedRoom.
EXPRESSIVE_REASONERS = ['HERMIT', 'PELLET', 'JFACT']


def test_preloaded_reference_is_served(call):
    refs = call('', 'GET ALL REFS')
    assert refs.success and refs.exit_code == 0
    assert 'robotics' in refs.queried_objects
    assert call('robotics', 'QUERY IND CLASS', 'Robot').queried_objects == iris('robot1')


@pytest.mark.parametrize('reasoner', ALL_REASONERS)
def test_load_query_and_update_with_each_reasoner(call, reasoner):
    ref = f'map_{reasoner.lower()}'
    loaded = call(ref, 'LOAD FILE', str(ONTOLOGIES / 'robotics.owl'),
                  'http://www.example.org/robotics', 'false', reasoner, 'true')
    assert loaded.success, loaded.error_description
    assert loaded.is_consistent
    assert call(ref, 'QUERY IND CLASS', 'RobotInRoom').queried_objects == iris('robot1')

    assert call(ref, 'ADD IND CLASS', 'robot2', 'Robot').success
    assert call(ref, 'ADD OBJECTPROP IND', 'isIn', 'robot2', 'bedroom').success
    assert call(ref, 'ADD DATAPROP IND', 'batteryLevel', 'robot2', 'INT', '42').success
    assert call(ref, 'REASON').success
    assert call(ref, 'QUERY IND CLASS', 'RobotInRoom').queried_objects == iris('robot1', 'robot2')
    assert call(ref, 'QUERY OBJECTPROP IND', 'isIn', 'robot2').queried_objects == iris('bedroom')
    values = call(ref, 'QUERY DATAPROP IND', 'batteryLevel', 'robot2')
    assert values.queried_objects == ['"42"^^xsd:integer']
    if reasoner in EXPRESSIVE_REASONERS:
        occupied = call(ref, 'QUERY IND CLASS', 'OccupiedRoom')
        assert occupied.queried_objects == iris('bedroom', 'kitchen')

    assert call(ref, 'DROP').success
    assert ref not in call('', 'GET ALL REFS').queried_objects
    assert call(ref, 'QUERY IND CLASS', 'Robot').exit_code == 206


def test_create_builds_an_ontology_from_nothing(call):
    ns = 'http://www.example.org/scratch'
    assert call('scratch', 'CREATE', ns, 'false', 'PELLET', 'false').success
    assert call('scratch', 'ADD CLASS CLASS', 'Drone', 'Robot').success
    assert call('scratch', 'ADD IND CLASS', 'uav1', 'Drone').success
    assert call('scratch', 'QUERY IND CLASS', 'Robot').queried_objects == [f'<{ns}#uav1>']
    assert call('scratch', 'DROP').success


@pytest.mark.parametrize('reference, words, args, code', [
    ('', 'QUERY IND CLASS', ['Robot'], 201),
    ('robotics', '', [], 202),
    ('robotics', 'QUERY NONSENSE CLASS', ['Robot'], 205),
    ('no_such_ref', 'QUERY IND CLASS', ['Robot'], 206),
    ('robotics', 'ADD IND CLASS', ['robot9'], 207),
    ('robotics', 'ADD DATAPROP IND', ['batteryLevel', 'robot1', 'INT', 'full'], 101),
    ('robotics', 'ADD DATAPROP IND', ['batteryLevel', 'robot1', 'KELVIN', '3'], 101),
])
def test_bad_directives_get_their_exit_codes(call, reference, words, args, code):
    response = call(reference, words, *args)
    assert not response.success
    assert response.exit_code == code, response.error_description
    assert response.error_description
    # Nothing changed: the preloaded ontology still answers as loaded.
    assert call('robotics', 'QUERY DATAPROP IND', 'batteryLevel', 'robot1').queried_objects == [
        '"80"^^xsd:integer']


def test_serialized_service_answers_each_directive_and_rolls_back(armor, call):
    ok = armor.call_list([
        directive('test', 'robotics', 'ADD', 'IND', 'CLASS', ['listbot', 'Robot']),
        directive('test', 'robotics', 'QUERY', 'IND', 'CLASS', ['Robot']),
    ])
    assert ok.success
    assert [r.exit_code for r in ok.armor_responses] == [0, 0]
    assert iri('listbot') in ok.armor_responses[1].queried_objects

    failed = armor.call_list([
        directive('test', 'robotics', 'REMOVE', 'IND', 'CLASS', ['listbot', 'Robot']),
        directive('test', 'robotics', 'ADD', 'IND', 'CLASS', ['x']),
        directive('test', 'robotics', 'ADD', 'IND', 'CLASS', ['other', 'Robot']),
    ])
    assert not failed.success
    assert [r.exit_code for r in failed.armor_responses] == [212, 207, 212]
    robots = call('robotics', 'QUERY IND CLASS', 'Robot').queried_objects
    assert iri('listbot') in robots and iri('other') not in robots
    assert call('robotics', 'REMOVE IND', 'listbot').success
