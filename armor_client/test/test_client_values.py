# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ARMOR's answer strings to Python values and back, and errors by exit code."""

import math

from armor_client import errors
from armor_client.answers import Answers
from armor_client.values import (answer_value, literal_value, short_name, split_literal,
                                 typed_argument)
from armor_msgs.msg import ArmorDirectiveRes, QueryItem
import pytest


@pytest.mark.parametrize('answer, value', [
    ('"80"^^xsd:integer', 80), ('"1700000000"^^xsd:long', 1700000000),
    ('"-3"^^xsd:int', -3), ('"0.5"^^xsd:double', 0.5), ('"2.5"^^xsd:float', 2.5),
    ('"1.25"^^xsd:decimal', 1.25), ('"true"^^xsd:boolean', True), ('"0"^^xsd:boolean', False),
    ('"hi"^^xsd:string', 'hi'), ('"ciao"@it', 'ciao'), ('"plain"', 'plain'),
    ('"say "hi""^^xsd:string', 'say "hi"'),
    ('"2026-01-01T00:00:00Z"^^xsd:dateTime', '2026-01-01T00:00:00Z'),
    ('"7"^^<http://www.w3.org/2001/XMLSchema#integer>', 7),
])
def test_literals_become_python_values(answer, value):
    assert literal_value(answer) == value
    assert type(literal_value(answer)) is type(value)


def test_special_reals_and_bad_literals():
    assert literal_value('"INF"^^xsd:double') == math.inf
    assert math.isnan(literal_value('"NaN"^^xsd:float'))
    with pytest.raises(ValueError):
        literal_value('"maybe"^^xsd:boolean')
    with pytest.raises(ValueError):
        split_literal('<http://x.org/o#a>')


def test_entities_become_short_names_or_iris():
    assert short_name('<http://x.org/o#Robot>') == 'Robot'
    assert short_name('<http://x.org/onto/Robot>') == 'Robot'
    assert short_name('Robot') == 'Robot'
    assert answer_value('<http://x.org/o#Robot>', iris=True) == 'http://x.org/o#Robot'
    assert answer_value('kitchen') == 'kitchen'


@pytest.mark.parametrize('value, datatype, expected', [
    (True, '', ('BOOLEAN', 'true')), (False, '', ('BOOLEAN', 'false')),
    (80, '', ('INTEGER', '80')), (80, 'LONG', ('LONG', '80')), (0.1, '', ('DOUBLE', '0.1')),
    ('hi', '', ('STRING', 'hi')), ('2026-01-01', 'xsd:date', ('xsd:date', '2026-01-01')),
])
def test_python_values_become_typed_arguments(value, datatype, expected):
    assert typed_argument(value, datatype) == expected


def test_infinite_floats_need_an_explicit_type():
    with pytest.raises(ValueError):
        typed_argument(math.inf)
    assert typed_argument(math.inf, 'FLOAT') == ('FLOAT', 'inf')


def test_formatted_sparql_rows_restrictions_and_timeouts():
    response = ArmorDirectiveRes(timeout=True, sparql_queried_objects=[
        QueryItem(key='who', value='<http://x.org/o#alice>'),
        QueryItem(key='level', value='"80"^^xsd:integer'), QueryItem(key='', value=''),
        QueryItem(key='who', value='<http://x.org/o#bob>'), QueryItem(key='level', value='')])
    rows = Answers(iris=False).rows(response)
    assert rows == [{'who': 'alice', 'level': 80}, {'who': 'bob', 'level': None}]
    assert rows.timed_out
    restrictions = ArmorDirectiveRes(queried_objects=[
        '<http://x.org/o#contains> some <http://x.org/o#Agent>'])
    assert Answers(iris=False).expressions(restrictions) == ['contains some Agent']


@pytest.mark.parametrize('code, error_class', [
    (102, errors.ArmorMountError), (203, errors.ArmorMountError),
    (101, errors.ArmorArgumentError), (208, errors.ArmorArgumentError),
    (206, errors.ArmorUnknownReferenceError), (213, errors.ArmorFileError),
    (221, errors.ArmorArgumentError), (222, errors.ArmorFileError),
    (223, errors.ArmorArgumentError),
    (210, errors.ArmorReasonerError), (211, errors.ArmorTimeLimitError),
    (212, errors.ArmorRolledBackError), (216, errors.ArmorCoreUnavailableError),
    (299, errors.ArmorServiceInternalError)])
def test_errors_by_exit_code_keep_code_and_description(code, error_class):
    error = errors.error_for(ArmorDirectiveRes(exit_code=code, error_description='why'))
    assert type(error) is error_class
    assert isinstance(error, errors.ArmorServiceInternalError)
    assert (error.exit_code, error.code) == (code, code)
    assert (error.description, error.msg) == ('why', 'why')
    assert str(error) == f'{code}: why'


def test_timeouts_are_timeout_errors():
    assert isinstance(errors.ArmorCallTimeout('late'), TimeoutError)
    assert isinstance(errors.ArmorCallTimeout('late'), errors.ArmorServiceCallError)
    assert errors.ArmorCallTimeout('late').exit_code is None
