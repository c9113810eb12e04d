# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Contract section 5.3 over ROS 2: every query of ARMOR's table and of "Beyond ARMOR", with
HermiT, Openllet and JFact, each answer compared in full with what ontologies/robotics.owl
asserts and implies. QUERY SPARQL has its own file (test_contract_sparql.py).

What robotics.owl implies, in short: robot1 is a Robot in the kitchen, alice a Person in
corridor1; Room and Corridor are Locations and disjoint; isIn has domain Agent and range
Location, contains is its inverse, connectedTo is symmetric; OccupiedRoom = Room and contains
some Agent (so: kitchen), RobotInRoom = Robot and isIn some Room (so: robot1).
"""

import re

from conftest import iri, iris, TEST_ONTOLOGIES
import pytest
from test_contract_support import EXPRESSIVE_REASONERS, answer, literal, succeeded
from test_contract_support import load  # noqa: F401 (fixture)


@pytest.fixture(params=EXPRESSIVE_REASONERS)
def ref(request, load):
    """A fresh robotics reference, nothing buffered, for each reasoner."""
    return load(request.param)


def test_query_ind_answers_asserted_and_inferred_classes(call, ref):
    assert answer(call, ref, 'QUERY IND', 'robot1') == iris('Agent', 'Robot', 'RobotInRoom')
    assert answer(call, ref, 'QUERY IND', 'kitchen') == iris('Location', 'OccupiedRoom', 'Room')
    assert answer(call, ref, 'QUERY IND', 'corridor1') == iris('Corridor', 'Location')
    assert answer(call, ref, 'QUERY IND', 'alice') == iris('Agent', 'Person')


def test_query_ind_of_an_individual_with_no_class_is_an_empty_success(call, ref):
    succeeded(call, ref, 'ADD IND', 'box1')
    response = succeeded(call, ref, 'QUERY IND', 'box1')
    assert list(response.queried_objects) == []


def test_query_ind_class_answers_instances(call, ref):
    assert answer(call, ref, 'QUERY IND CLASS', 'Agent') == iris('alice', 'robot1')
    assert answer(call, ref, 'QUERY IND CLASS', 'Location') == iris('bedroom', 'corridor1',
                                                                    'kitchen')
    assert answer(call, ref, 'QUERY IND CLASS', 'OccupiedRoom') == iris('kitchen')
    assert answer(call, ref, 'QUERY IND CLASS', 'RobotInRoom') == iris('robot1')


def test_query_dataprop_ind_answers_typed_literals(call, ref):
    assert answer(call, ref, 'QUERY DATAPROP IND', 'batteryLevel', 'robot1') == [
        literal('80', 'integer')]
    assert answer(call, ref, 'QUERY DATAPROP IND', 'visitedAt', 'bedroom') == [
        literal('1700000000', 'long')]
    assert answer(call, ref, 'QUERY DATAPROP IND', 'batteryLevel', 'alice') == []


def test_query_objectprop_ind_answers_asserted_and_inferred_values(call, ref):
    assert answer(call, ref, 'QUERY OBJECTPROP IND', 'isIn', 'robot1') == iris('kitchen')
    # contains is the inverse of isIn; connectedTo is symmetric.
    assert answer(call, ref, 'QUERY OBJECTPROP IND', 'contains', 'kitchen') == iris('robot1')
    assert answer(call, ref, 'QUERY OBJECTPROP IND', 'contains', 'corridor1') == iris('alice')
    assert answer(call, ref, 'QUERY OBJECTPROP IND', 'connectedTo', 'corridor1') == iris(
        'bedroom', 'kitchen')
    assert answer(call, ref, 'QUERY OBJECTPROP IND', 'isIn', 'kitchen') == []


def test_query_class_ind_answers_all_or_most_specific_classes(call, ref):
    assert answer(call, ref, 'QUERY CLASS IND', 'robot1') == iris('Agent', 'Robot', 'RobotInRoom')
    assert answer(call, ref, 'QUERY CLASS IND', 'robot1', 'false') == iris('Agent', 'Robot',
                                                                           'RobotInRoom')
    assert answer(call, ref, 'QUERY CLASS IND', 'robot1', 'true') == iris('RobotInRoom')
    assert answer(call, ref, 'QUERY CLASS IND', 'kitchen', 'true') == iris('OccupiedRoom')
    assert answer(call, ref, 'QUERY CLASS IND', 'alice', 'true') == iris('Person')


def test_query_class_class_answers_subclasses_of_all_levels(call, ref):
    assert answer(call, ref, 'QUERY CLASS CLASS', 'Location') == iris('Corridor', 'OccupiedRoom',
                                                                      'Room')
    assert answer(call, ref, 'QUERY CLASS CLASS', 'Agent') == iris('Person', 'Robot',
                                                                   'RobotInRoom')
    assert answer(call, ref, 'QUERY CLASS CLASS', 'Corridor') == []


def test_query_class_restrictions_answers_manchester_syntax(call, ref):
    assert answer(call, ref, 'QUERY CLASS RESTRICTIONS', 'OccupiedRoom') == [
        f'{iri("contains")} some {iri("Agent")}']
    assert answer(call, ref, 'QUERY CLASS RESTRICTIONS', 'RobotInRoom') == [
        f'{iri("isIn")} some {iri("Room")}']
    assert answer(call, ref, 'QUERY CLASS RESTRICTIONS', 'Room') == []
    succeeded(call, ref, 'ADD CARDINALITY MIN', 'Robot', 'isIn', '1', 'Location')
    succeeded(call, ref, 'ADD AXIOM', 'Robot SubClassOf batteryLevel some xsd:integer')
    # A datatype is an entity too: its full IRI (section 4) and xsd:integer are both fine.
    restrictions = answer(call, ref, 'QUERY CLASS RESTRICTIONS', 'Robot')
    assert restrictions in [
        sorted([f'{iri("batteryLevel")} some {datatype}', f'{iri("isIn")} min 1 {iri("Location")}'])
        for datatype in ['xsd:integer', '<http://www.w3.org/2001/XMLSchema#integer>']]


def test_query_ind_dataprop_answers_properties_with_values(call, ref):
    assert answer(call, ref, 'QUERY IND DATAPROP', 'robot1') == iris('batteryLevel')
    assert answer(call, ref, 'QUERY IND DATAPROP', 'bedroom') == iris('visitedAt')
    assert answer(call, ref, 'QUERY IND DATAPROP', 'alice') == []


def test_query_ind_objectprop_answers_properties_with_values(call, ref):
    assert answer(call, ref, 'QUERY IND OBJECTPROP', 'robot1') == iris('isIn')
    # kitchen: connectedTo corridor1 (asserted), contains robot1 (inverse of isIn).
    assert answer(call, ref, 'QUERY IND OBJECTPROP', 'kitchen') == iris('connectedTo', 'contains')
    assert answer(call, ref, 'QUERY IND OBJECTPROP', 'bedroom') == iris('connectedTo')


# --- Beyond ARMOR -----------------------------------------------------------------------------

def test_query_class_super_answers_superclasses(call, ref):
    assert answer(call, ref, 'QUERY CLASS SUPER', 'RobotInRoom') == iris('Agent', 'Robot')
    assert answer(call, ref, 'QUERY CLASS SUPER', 'OccupiedRoom') == iris('Location', 'Room')
    assert answer(call, ref, 'QUERY CLASS SUPER', 'Location') == []


def test_query_class_equivalent_answers_equivalent_named_classes(call, ref):
    assert answer(call, ref, 'QUERY CLASS EQUIVALENT', 'OccupiedRoom') == []
    succeeded(call, ref, 'ADD CLASS EQUIVALENT', 'BusyRoom', 'Room and contains some Agent')
    assert answer(call, ref, 'QUERY CLASS EQUIVALENT', 'OccupiedRoom') == iris('BusyRoom')
    assert answer(call, ref, 'QUERY CLASS EQUIVALENT', 'BusyRoom') == iris('OccupiedRoom')


def test_query_class_disjoint_answers_asserted_and_inferred_disjoint_classes(call, ref):
    assert answer(call, ref, 'QUERY CLASS DISJOINT', 'Room') == iris('Corridor')
    # OccupiedRoom is a Room, hence disjoint with Corridor too.
    assert answer(call, ref, 'QUERY CLASS DISJOINT', 'Corridor') == iris('OccupiedRoom', 'Room')
    assert answer(call, ref, 'QUERY CLASS DISJOINT', 'Agent') == []


def test_query_objectprop_objectprop_answers_sub_properties_of_all_levels(call, ref):
    assert answer(call, ref, 'QUERY OBJECTPROP OBJECTPROP', 'isIn') == []
    succeeded(call, ref, 'ADD OBJECTPROP OBJECTPROP', 'isDockedAt', 'isIn')
    succeeded(call, ref, 'ADD OBJECTPROP OBJECTPROP', 'isChargingAt', 'isDockedAt')
    assert answer(call, ref, 'QUERY OBJECTPROP OBJECTPROP', 'isIn') == iris('isChargingAt',
                                                                            'isDockedAt')
    assert answer(call, ref, 'QUERY OBJECTPROP OBJECTPROP', 'isDockedAt') == iris('isChargingAt')


def test_query_dataprop_dataprop_answers_sub_properties_of_all_levels(call, ref):
    assert answer(call, ref, 'QUERY DATAPROP DATAPROP', 'visitedAt') == []
    succeeded(call, ref, 'ADD DATAPROP DATAPROP', 'lastVisit', 'visitedAt')
    succeeded(call, ref, 'ADD DATAPROP DATAPROP', 'lastDocking', 'lastVisit')
    assert answer(call, ref, 'QUERY DATAPROP DATAPROP', 'visitedAt') == iris('lastDocking',
                                                                             'lastVisit')


def test_query_ind_dl_answers_instances_of_a_class_expression(call, ref):
    assert answer(call, ref, 'QUERY IND DL', 'Agent and isIn some Room') == iris('robot1')
    assert answer(call, ref, 'QUERY IND DL', 'Agent and (isIn some Location)') == iris('alice',
                                                                                      'robot1')
    assert answer(call, ref, 'QUERY IND DL', 'Location and not Room') == iris('corridor1')
    assert answer(call, ref, 'QUERY IND DL', 'connectedTo value corridor1') == iris('bedroom',
                                                                                   'kitchen')
    assert answer(call, ref, 'QUERY IND DL', 'Person and Robot') == []


def test_query_class_dl_answers_subclasses_of_a_class_expression(call, ref):
    assert answer(call, ref, 'QUERY CLASS DL', 'Location and not Corridor') == iris(
        'OccupiedRoom', 'Room')
    assert answer(call, ref, 'QUERY CLASS DL', 'Agent') == iris('Person', 'Robot', 'RobotInRoom')
    assert answer(call, ref, 'QUERY CLASS DL', 'contains some Agent') == iris('OccupiedRoom')


def test_query_ind_same_answers_individuals_equal_to_it(call, ref):
    assert answer(call, ref, 'QUERY IND SAME', 'robot1') == []
    succeeded(call, ref, 'ADD IND SAME', 'robot1', 'turtlebot')
    assert answer(call, ref, 'QUERY IND SAME', 'robot1') == iris('turtlebot')
    assert answer(call, ref, 'QUERY IND SAME', 'turtlebot') == iris('robot1')


def test_query_consistency_of_a_consistent_ontology(call, ref):
    response = succeeded(call, ref, 'QUERY CONSISTENCY')
    assert response.is_consistent
    assert list(response.queried_objects) == []


def test_query_consistency_explains_an_inconsistency(call, ref):
    # kitchen is a Room; Room and Corridor are disjoint; so kitchen cannot be a Corridor.
    succeeded(call, ref, 'ADD IND CLASS', 'kitchen', 'Corridor')
    response = succeeded(call, ref, 'QUERY CONSISTENCY')
    assert not response.is_consistent
    explanation = list(response.queried_objects)
    # The one minimal cause: the two class assertions and the disjointness, in Manchester syntax.
    assert len(explanation) == 3, explanation
    k, corridor, room = iri('kitchen'), iri('Corridor'), iri('Room')
    patterns = [
        rf'^{re.escape(k)} Type {re.escape(corridor)}$',
        rf'^{re.escape(k)} Type {re.escape(room)}$',
        rf'^({re.escape(corridor)} DisjointWith {re.escape(room)}'
        rf'|{re.escape(room)} DisjointWith {re.escape(corridor)}'
        rf'|DisjointClasses: .*)$',
    ]
    for pattern in patterns:
        assert any(re.match(pattern, line) for line in explanation), (pattern, explanation)
    disjointness = next(line for line in explanation if 'Disjoint' in line)
    assert corridor in disjointness and room in disjointness


@pytest.mark.parametrize('reasoner', EXPRESSIVE_REASONERS)
def test_an_inconsistent_file_loads_and_its_inconsistency_is_explained(call, load, reasoner):
    ns = 'http://www.example.org/inconsistent-robot#'
    name = load(reasoner, path=TEST_ONTOLOGIES / 'inconsistent-robot.ttl')
    response = succeeded(call, name, 'QUERY CONSISTENCY')
    assert not response.is_consistent
    robot7, robot, person = f'<{ns}robot7>', f'<{ns}Robot>', f'<{ns}Person>'
    explanation = list(response.queried_objects)
    assert len(explanation) == 3, explanation
    assert f'{robot7} Type {robot}' in explanation, explanation
    assert f'{robot7} Type {person}' in explanation, explanation
    disjointness = [line for line in explanation if 'Disjoint' in line]
    assert len(disjointness) == 1 and robot in disjointness[0] and person in disjointness[0]

    # Taking one of the three axioms away makes it consistent again.
    assert succeeded(call, name, 'REMOVE IND CLASS', 'robot7', 'Person').is_consistent
    assert succeeded(call, name, 'QUERY CONSISTENCY').is_consistent
    assert answer(call, name, 'QUERY IND CLASS', 'Agent') == sorted([f'<{ns}alice>', robot7])
