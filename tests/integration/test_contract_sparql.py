# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Contract section 5.3, QUERY SPARQL [-/FORMATTED] over ROS 2: SELECT and ASK over asserted
and inferred knowledge, one string per row, FORMATTED rows with separators, ARMOR's split form,
the timeout argument (timeout=true with the rows found so far) and malformed queries (208 with
the parser's message).
"""

import re
import time

from conftest import iri, iris
from ontology_factory import write_abox
import pytest
from test_contract_support import EXPRESSIVE_REASONERS, answer, failure, literal, succeeded
from test_contract_support import load  # noqa: F401 (fixture)

ROBOTICS_PREFIX = 'PREFIX r: <http://www.example.org/robotics#>'


@pytest.fixture(params=EXPRESSIVE_REASONERS)
def ref(request, load):
    """A fresh robotics reference, nothing buffered, for each reasoner."""
    return load(request.param)


def test_select_one_variable_answers_inferred_members(call, ref):
    # Nobody asserted that the kitchen is an OccupiedRoom: the reasoner concluded it.
    assert answer(call, ref, 'QUERY SPARQL', 'SELECT ?r WHERE { ?r a :OccupiedRoom }') == iris(
        'kitchen')
    assert sorted(answer(call, ref, 'QUERY SPARQL', 'SELECT ?l WHERE { ?l a :Location }')) == iris(
        'bedroom', 'corridor1', 'kitchen')
    # An inferred property value: contains is the inverse of isIn.
    assert answer(call, ref, 'QUERY SPARQL', 'SELECT ?a WHERE { :kitchen :contains ?a }') == iris(
        'robot1')


def test_select_sees_changes_made_through_armor(call, ref):
    succeeded(call, ref, 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom')
    query = 'SELECT ?r WHERE { ?r a :OccupiedRoom } ORDER BY ?r'
    assert answer(call, ref, 'QUERY SPARQL', query) == iris('bedroom', 'kitchen')


def test_select_of_a_literal_renders_it_typed(call, ref):
    assert answer(call, ref, 'QUERY SPARQL',
                  'SELECT ?b WHERE { :robot1 :batteryLevel ?b }') == [literal('80', 'integer')]


def test_select_several_variables_gives_one_string_per_row(call, ref):
    rows = answer(call, ref, 'QUERY SPARQL', 'SELECT ?a ?l WHERE { ?a :isIn ?l } ORDER BY ?a')
    assert rows == [f'a={iri("alice")}; l={iri("corridor1")}',
                    f'a={iri("robot1")}; l={iri("kitchen")}']


def test_select_with_no_match_is_an_empty_success(call, ref):
    query = 'SELECT ?x WHERE { ?x a :Corridor . ?x a :Room }'
    assert answer(call, ref, 'QUERY SPARQL', query) == []


def test_ask_answers_true_or_false_from_inferences(call, ref):
    assert answer(call, ref, 'QUERY SPARQL', 'ASK { :kitchen a :Location }') == ['true']
    assert answer(call, ref, 'QUERY SPARQL', 'ASK { :corridor1 a :Room }') == ['false']


def test_formatted_rows_are_key_value_items_separated_by_an_empty_key(call, ref):
    response = succeeded(call, ref, 'QUERY SPARQL FORMATTED',
                         'SELECT ?a ?l WHERE { ?a :isIn ?l } ORDER BY ?a')
    items = [(item.key, item.value) for item in response.sparql_queried_objects]
    assert items == [('a', iri('alice')), ('l', iri('corridor1')),
                     ('', ''),
                     ('a', iri('robot1')), ('l', iri('kitchen'))]


def test_formatted_single_row_has_no_separator(call, ref):
    response = succeeded(call, ref, 'QUERY SPARQL FORMATTED',
                         'SELECT ?b WHERE { :robot1 :batteryLevel ?b }')
    items = [(item.key, item.value) for item in response.sparql_queried_objects]
    assert items == [('b', literal('80', 'integer'))]


def test_formatted_ask_answers_its_boolean(call, ref):
    response = succeeded(call, ref, 'QUERY SPARQL FORMATTED', 'ASK { :robot1 a :Agent }')
    assert [item.value for item in response.sparql_queried_objects] == ['true']


def test_split_form_prefix_select_where(call, ref):
    assert answer(call, ref, 'QUERY SPARQL', ROBOTICS_PREFIX, 'SELECT ?r',
                  '?r a r:OccupiedRoom') == iris('kitchen')
    assert answer(call, ref, 'QUERY SPARQL', ROBOTICS_PREFIX, 'SELECT ?a',
                  '{ ?a r:isIn r:corridor1 }') == iris('alice')


def test_split_form_formatted(call, ref):
    response = succeeded(call, ref, 'QUERY SPARQL FORMATTED', ROBOTICS_PREFIX, 'SELECT ?a ?l',
                         '?a r:isIn ?l . ?l a r:Room')
    items = [(item.key, item.value) for item in response.sparql_queried_objects]
    assert items == [('a', iri('robot1')), ('l', iri('kitchen'))]


def test_timeout_argument_that_is_not_reached_changes_nothing(call, ref):
    response = succeeded(call, ref, 'QUERY SPARQL', 'SELECT ?r WHERE { ?r a :OccupiedRoom }',
                         '10000')
    assert not response.timeout
    assert list(response.queried_objects) == iris('kitchen')
    response = succeeded(call, ref, 'QUERY SPARQL', ROBOTICS_PREFIX, 'SELECT ?r',
                         '?r a r:OccupiedRoom', '10000')
    assert not response.timeout
    assert list(response.queried_objects) == iris('kitchen')


@pytest.mark.parametrize('reasoner', ['HERMIT', 'PELLET'])
def test_a_query_past_its_timeout_answers_timeout_with_the_rows_found_so_far(
        call, load, armor_node, reasoner):
    rooms, robots = 10, 150
    path = write_abox(armor_node.scratch / f'sparql-timeout-{reasoner}.owl', rooms, robots)
    big = load(reasoner, path=path)
    # The first branch (the rooms) is answered at once; the second is a cartesian product of
    # ~150^4 robot tuples whose filter is never true: hours of work.
    query = ('SELECT ?x WHERE { { ?x a :Room } UNION { ?x a :Robot . ?b a :Robot . '
             '?c a :Robot . ?d a :Robot . '
             'FILTER(STR(?x) = CONCAT(STR(?b), STR(?c), STR(?d))) } }')
    started = time.monotonic()
    response = call(big, 'QUERY SPARQL', query, '1500', timeout_s=120)
    elapsed = time.monotonic() - started
    assert response.timeout, f'no timeout after {elapsed:.1f} s: {response.error_description}'
    assert elapsed < 60
    expected_rooms = iris('bedroom', 'kitchen', *(f'room{i}' for i in range(rooms)))
    assert sorted(response.queried_objects) == expected_rooms
    # The reference still answers.
    assert answer(call, big, 'QUERY SPARQL', 'ASK { :bot0 a :RobotInRoom }') == ['true']


def test_formatted_query_past_its_timeout_sets_timeout(call, load, armor_node):
    path = write_abox(armor_node.scratch / 'sparql-timeout-formatted.owl', 5, 150)
    big = load('PELLET', path=path)
    query = ('SELECT (COUNT(*) AS ?n) WHERE { ?a a :Robot . ?b a :Robot . ?c a :Robot . '
             '?d a :Robot . ?e a :Robot }')
    started = time.monotonic()
    response = call(big, 'QUERY SPARQL FORMATTED', query, '1000', timeout_s=120)
    assert response.timeout, response.error_description
    assert time.monotonic() - started < 60
    assert list(response.sparql_queried_objects) == []


@pytest.mark.parametrize('query', [
    'SELECT ?r WHERE { ?r a }',
    'SELECT ?r WHERE { ?r a :Room',
    'SELEKT ?r WHERE { ?r a :Room }',
])
def test_malformed_sparql_is_208_with_the_parser_message(call, ref, query):
    response = failure(call, ref, 'QUERY SPARQL', query, code=208)
    assert re.search(r'line \d+, column \d+', response.error_description), (
        response.error_description)
    assert answer(call, ref, 'QUERY SPARQL', 'SELECT ?r WHERE { ?r a :OccupiedRoom }') == iris(
        'kitchen')


def test_malformed_split_form_is_208(call, ref):
    response = failure(call, ref, 'QUERY SPARQL FORMATTED', ROBOTICS_PREFIX, 'SELECT ?r',
                       '?r a', code=208)
    assert re.search(r'line \d+, column \d+', response.error_description)


def test_unknown_prefix_in_sparql_is_208(call, ref):
    response = failure(call, ref, 'QUERY SPARQL', 'SELECT ?r WHERE { ?r a nope:Room }', code=208)
    assert 'nope' in response.error_description
