# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""EXPLAIN over ROS 2: the Python client's explain_* methods and `armor explain`, on the live node.

Each test works on its own copy of robotics.owl (HermiT), dropped afterwards.
"""

import re
import subprocess
import sys

from armor_client import Armor, ArmorNotEntailedError
from armor_client.explanations import ExplainedAxiom
from conftest import ONTOLOGIES
import pytest

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')
LABEL = '<http://www.w3.org/2000/01/rdf-schema#label>'
NS = 'http://www.example.org/robotics#'


@pytest.fixture
def ref(armor, request):
    session = Armor('explain_test', transport=armor, timeout_s=120)
    name = 'why_' + re.sub(r'\W', '_', request.node.name)
    reference = session.load_file(name, ROBOTICS)
    yield reference
    reference.drop()


def test_an_inferred_type_is_explained_by_its_justification(ref):
    why = ref.explain_instance('robot1', 'RobotInRoom')
    assert not why.asserted
    assert why == [[ExplainedAxiom('asserted', 'kitchen Type Room'),
                    ExplainedAxiom('asserted', 'robot1 Type Robot'),
                    ExplainedAxiom('asserted', 'robot1 isIn kitchen'),
                    ExplainedAxiom('axiom', 'RobotInRoom EquivalentTo Robot and (isIn some Room)')]]


def test_several_justifications_of_a_property_value(ref):
    why = ref.explain_object_property('contains', 'corridor1', 'alice', justifications=3)
    assert [[a.text for a in j] for j in why] == [['alice isIn corridor1',
                                                  'contains InverseOf isIn']]
    # robot1 is an Agent as a Robot, as what isIn's domain says, and as what has a batteryLevel.
    agent = ref.explain_instance('robot1', 'Agent', justifications=5)
    assert {tuple(a.text for a in j) for j in agent} == {
        ('robot1 Type Robot', 'Robot SubClassOf Agent'),
        ('robot1 isIn kitchen', 'isIn Domain Agent'),
        ('robot1 batteryLevel 80', 'Robot SubClassOf Agent', 'batteryLevel Domain Robot')}
    assert [len(j) for j in agent] == [2, 2, 3]  # smallest first


def test_asserted_facts_subclasses_and_what_does_not_hold(ref):
    value = ref.explain_data_property('batteryLevel', 'robot1', 80)
    assert value.asserted and [[a.kind for a in j] for j in value] == [['asserted']]
    sub = ref.explain_subclass('RobotInRoom', 'Agent', justifications=2)
    assert {tuple(a.text for a in j) for j in sub} == {
        ('Robot SubClassOf Agent', 'RobotInRoom EquivalentTo Robot and (isIn some Room)'),
        ('RobotInRoom EquivalentTo Robot and (isIn some Room)', 'isIn Domain Agent')}
    assert all(a.kind == 'axiom' for j in sub for a in j)
    with pytest.raises(ArmorNotEntailedError) as refused:
        ref.explain_instance('bedroom', 'OccupiedRoom')
    assert refused.value.exit_code == 227 and 'does not hold' in refused.value.msg
    with pytest.raises(ArmorNotEntailedError):
        ref.explain_inconsistency()


def test_read_aloud_uses_the_labels(ref):
    ref.add_axiom(f'AnnotationAssertion({LABEL} <{NS}robot1> "the robot")')
    ref.add_axiom(f'AnnotationAssertion({LABEL} <{NS}RobotInRoom> "robot in a room")')
    why = ref.explain_instance('robot1', 'RobotInRoom')
    labels = ref.labels(*why.names())
    assert labels == {'robot1': 'the robot', 'RobotInRoom': 'robot in a room'}
    assert why.read_aloud(labels) == (
        'the robot is a robot in a room because kitchen is a Room, the robot is a Robot, '
        'the robot isIn kitchen and a robot in a room is exactly a Robot and (isIn some Room).')


def test_the_command_line_prints_an_indented_list(armor, ref):
    run = subprocess.run([sys.executable, '-m', 'armor_client.cli', 'explain', ref.name,
                          'instance', 'robot1', 'RobotInRoom'],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.splitlines() == [
        'robot1 Type RobotInRoom',
        '  justification 1:',
        '    [asserted] kitchen Type Room',
        '    [asserted] robot1 Type Robot',
        '    [asserted] robot1 isIn kitchen',
        '    [axiom] RobotInRoom EquivalentTo Robot and (isIn some Room)']
    missing = subprocess.run([sys.executable, '-m', 'armor_client.cli', 'explain', ref.name,
                              'instance', 'bedroom', 'OccupiedRoom'],
                             capture_output=True, text=True, timeout=120)
    assert missing.returncode == 1 and '227' in missing.stderr
