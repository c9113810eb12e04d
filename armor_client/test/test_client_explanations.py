# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Reading EXPLAIN answers: justifications told apart, rules and bindings, the read-aloud text."""

import pytest

from armor_client.cli.explain import render
from armor_client.explanations import parse

NS = 'http://www.example.org/robotics#'

LINES = [
    f'1 asserted <{NS}alice> <{NS}isIn> <{NS}bedroom>',
    f'1 asserted <{NS}bedroom> Type <{NS}Room>',
    f'1 asserted <{NS}alice> Type <{NS}Person>',
    f'1 axiom <{NS}Person> SubClassOf <{NS}Agent>',
    f'1 axiom <{NS}contains> InverseOf <{NS}isIn>',
    f'1 axiom <{NS}OccupiedRoom> EquivalentTo <{NS}Room> and (<{NS}contains> some <{NS}Agent>)',
    f'2 asserted <{NS}robot1> <{NS}isIn> <{NS}bedroom>',
    f'2 rule occupied: <{NS}Robot>(?r), <{NS}isIn>(?r, ?l) -> <{NS}OccupiedRoom>(?l)'
    f' | ?l=<{NS}bedroom>, ?r=<{NS}robot1>',
]


def test_lines_are_grouped_by_justification_and_shortened():
    explanation = parse(LINES, 'bedroom Type OccupiedRoom', False, iris=False)
    assert [len(j) for j in explanation] == [6, 2]
    assert explanation[0][0].kind == 'asserted' and explanation[0][0].asserted
    assert explanation[0][0].text == 'alice isIn bedroom'
    assert explanation[0][3].kind == 'axiom' and not explanation[0][3].asserted
    rule = explanation[1][1]
    assert (rule.kind, rule.rule) == ('rule', 'occupied')
    assert rule.text == 'Robot(?r), isIn(?r, ?l) -> OccupiedRoom(?l)'
    assert rule.bindings == {'?l': 'bedroom', '?r': 'robot1'}
    assert explanation.names() == ['Agent', 'OccupiedRoom', 'Person', 'Robot', 'Room', 'alice',
                                   'bedroom', 'contains', 'isIn', 'robot1']


def test_iris_are_kept_when_asked():
    explanation = parse(LINES[:1], 'x', False, iris=True)
    assert explanation[0][0].text == f'<{NS}alice> <{NS}isIn> <{NS}bedroom>'


def test_a_line_of_another_shape_is_refused():
    with pytest.raises(ValueError):
        parse(['alice isIn bedroom'], 'x', False, iris=False)


def test_read_aloud_is_a_sentence_built_from_the_axioms_and_the_labels():
    explanation = parse(LINES, 'bedroom Type OccupiedRoom', False, iris=False)
    labels = {'bedroom': 'the bedroom', 'OccupiedRoom': 'occupied room'}
    text = explanation.read_aloud(labels)
    assert text == (
        'the bedroom is an occupied room because alice isIn the bedroom, the bedroom is a Room, '
        'alice is a Person, every Person is an Agent, contains is the inverse of isIn and '
        'an occupied room is exactly a Room and (contains some Agent); or because robot1 isIn '
        'the bedroom and the rule occupied applies where ?l is the bedroom, ?r is robot1.')
    assert explanation.read_aloud(labels) == text  # deterministic


def test_an_asserted_fact_reads_as_asserted():
    explanation = parse([f'1 asserted <{NS}robot1> <{NS}isIn> <{NS}kitchen>'],
                        'robot1 isIn kitchen', True, iris=False)
    assert explanation.asserted
    assert explanation.read_aloud() == 'robot1 isIn kitchen because it was asserted.'


def test_the_cli_prints_an_indented_list():
    explanation = parse(LINES[6:], 'bedroom Type OccupiedRoom', False, iris=False)
    assert render(explanation) == [
        'bedroom Type OccupiedRoom',
        '  justification 1:',
        '    [asserted] robot1 isIn bedroom',
        '    [rule] occupied: Robot(?r), isIn(?r, ?l) -> OccupiedRoom(?l)'
        '  (?l=bedroom, ?r=robot1)',
    ]


def test_read_aloud_says_a_property_characteristic():
    explanation = parse([f'1 asserted <{NS}kitchen> <{NS}connectedTo> <{NS}corridor1>',
                         f'1 axiom Symmetric: <{NS}connectedTo>'],
                        'corridor1 connectedTo kitchen', False, iris=False)
    assert explanation.read_aloud() == (
        'corridor1 connectedTo kitchen because kitchen connectedTo corridor1 and connectedTo is '
        'symmetric.')
