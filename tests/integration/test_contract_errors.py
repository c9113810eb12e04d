# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Contract sections 2 and 7 over ROS 2: dispatch and the error rows. Each bad directive gets
its code (201, 202, 205, 206, 207, 101, 208, 209, 210, 213, 214, 218) with a description that
says what is wrong, and afterwards the reference answers exactly as before: nothing changed
and the service is alive.
"""

import os
import re

from armor_client import directive
from conftest import iris
import pytest
from test_contract_support import (MIXED, ROBOTICS, answer, failure, snapshot, succeeded,
                                   unique_name)
from test_contract_support import load  # noqa: F401 (fixture)

# A position in the text the client sent: "line 1 column 11", "line 1, column 23".
POSITION = re.compile(r'line 1,? column \d+')


@pytest.fixture
def ref(load):
    """A fresh robotics reference (HermiT, nothing buffered)."""
    return load('HERMIT')


@pytest.fixture
def unchanged(call, ref):
    """Yields the reference; at the end checks that it answers exactly as at the start."""
    before = snapshot(call, ref)
    yield ref
    assert snapshot(call, ref) == before, 'a failed directive changed the reference'


# --- section 2: dispatch ----------------------------------------------------------------------

@pytest.mark.parametrize('words, args', [
    ('QUERY IND CLASS', ['Robot']),
    ('ADD IND CLASS', ['robot9', 'Robot']),
    ('DROP', []),
])
def test_no_reference_name_is_201(call, unchanged, words, args):
    failure(call, '', words, *args, code=201)


def test_utilities_need_no_reference_name(call, unchanged):
    assert unchanged in answer(call, '', 'GET ALL REFS')
    assert answer(call, '', 'GET REF CLIENT', unchanged) == []
    assert answer(call, '', 'LOG SCREEN OFF') == []


def test_no_command_is_202(call, unchanged):
    failure(call, unchanged, '', code=202)
    failure(call, unchanged, '', 'robot9', 'Robot', code=202)


@pytest.mark.parametrize('words', ['QUERY NONSENSE CLASS', 'FLY', 'ADD IND DL',
                                   'query ind nonsense', 'REMOVE CARDINALITY MIN'])
def test_unknown_combination_is_205_naming_it(call, unchanged, words):
    response = failure(call, unchanged, words, 'Robot', code=205)
    assert words.upper() in response.error_description.upper()


def test_commands_are_case_insensitive_and_args_are_not(call, unchanged):
    assert answer(call, unchanged, 'query ind class', 'Robot') == iris('robot1')
    assert answer(call, unchanged, 'Query Ind Class', 'Robot') == iris('robot1')
    # "robot" is another class than "Robot": nobody is in it.
    assert answer(call, unchanged, 'QUERY IND CLASS', 'robot') == []


def test_an_empty_spec_may_be_written_as_a_dash(call, unchanged, armor):
    dashed = armor.call(directive('test', unchanged, 'QUERY', 'IND', '-', ['robot1']),
                        timeout_s=120)
    assert dashed.success, dashed.error_description
    assert list(dashed.queried_objects) == iris('Agent', 'Robot', 'RobotInRoom')
    assert answer(call, unchanged, 'QUERY IND', 'robot1') == list(dashed.queried_objects)
    both = armor.call(directive('test', unchanged, 'QUERY', 'CONSISTENCY', '-', []),
                      timeout_s=120)
    assert both.success and both.is_consistent, both.error_description


@pytest.mark.parametrize('words, args', [
    ('QUERY IND CLASS', ['Robot']),
    ('ADD IND CLASS', ['robot9', 'Robot']),
    ('APPLY', []),
    ('REASON', []),
    ('SAVE', []),
    ('DROP', []),
    ('MOUNT', []),
    ('QUERY SPARQL', ['ASK { ?s ?p ?o }']),
])
def test_a_reference_that_is_not_loaded_is_206(call, unchanged, words, args):
    missing = unique_name('missing')
    response = failure(call, missing, words, *args, code=206)
    assert missing in response.error_description


@pytest.mark.parametrize('words, args, expected', [
    ('ADD IND CLASS', ['robot9'], ['ind', 'class']),
    ('ADD DATAPROP IND', ['batteryLevel', 'robot1', 'INT'], ['prop', 'ind', 'type', 'value']),
    ('REPLACE OBJECTPROP IND', ['isIn', 'robot1', 'bedroom'],
     ['prop', 'ind', 'new value', 'old value']),
    ('QUERY IND CLASS', ['Robot', 'Person'], ['class']),
    ('QUERY OBJECTPROP IND', ['isIn'], ['prop', 'ind']),
    ('ADD CARDINALITY MIN', ['Robot', 'isIn', '1'], ['class', 'prop', 'n', 'value class']),
    ('DISJOINT CLASS', ['Robot'], ['class']),
    ('QUERY SPARQL', [], ['query']),
])
def test_wrong_number_of_arguments_is_207_naming_what_is_expected(call, unchanged, words, args,
                                                                   expected):
    response = failure(call, unchanged, words, *args, code=207)
    for name in expected:
        assert name in response.error_description, (name, response.error_description)


def test_load_with_wrong_arguments_is_207_and_loads_nothing(call, unchanged):
    name = unique_name('bad_args')
    failure(call, name, 'LOAD FILE', str(ROBOTICS), '', code=207)
    response = call(name, 'LOAD FILE', str(ROBOTICS), '', 'maybe', 'HERMIT', 'false')
    assert not response.success and response.exit_code in (101, 207), response.error_description
    assert 'maybe' in response.error_description
    assert name not in answer(call, '', 'GET ALL REFS')


# --- 101: bad numbers, unknown datatypes, bad booleans ----------------------------------------

@pytest.mark.parametrize('words, args, bad', [
    ('ADD DATAPROP IND', ['batteryLevel', 'robot1', 'INT', 'eighty'], 'eighty'),
    ('ADD DATAPROP IND', ['batteryLevel', 'robot1', 'INTEGER', '7.5'], '7.5'),
    ('ADD DATAPROP IND', ['visitedAt', 'robot1', 'LONG', '1.5e3'], '1.5e3'),
    ('ADD DATAPROP IND', ['batteryLevel', 'robot1', 'FLOAT', 'half'], 'half'),
    ('ADD DATAPROP IND', ['batteryLevel', 'robot1', 'DOUBLE', '1,5'], '1,5'),
    ('ADD DATAPROP IND', ['batteryLevel', 'robot1', 'INT', ''], "''"),
    ('REPLACE DATAPROP IND', ['batteryLevel', 'robot1', 'INT', 'full', '80'], 'full'),
    ('ADD CARDINALITY MIN', ['Robot', 'isIn', 'one', 'Location'], 'one'),
    ('ADD CARDINALITY MIN', ['Robot', 'isIn', '-1', 'Location'], '-1'),
    ('ADD MIN CARDINALITY', ['Robot', 'isIn', '1.5', 'Location'], '1.5'),
    ('QUERY SPARQL', ['SELECT ?r WHERE { ?r a :Room }', 'soon'], 'soon'),
    ('QUERY SPARQL', ['SELECT ?r WHERE { ?r a :Room }', '-5'], '-5'),
])
def test_a_bad_number_is_101_naming_it(call, unchanged, words, args, bad):
    response = failure(call, unchanged, words, *args, code=101)
    assert bad in response.error_description


@pytest.mark.parametrize('datatype', ['KELVIN', 'xsd:notAType', 'rdfs:Literal'])
def test_an_unknown_datatype_is_101(call, unchanged, datatype):
    response = failure(call, unchanged, 'ADD DATAPROP IND', 'batteryLevel', 'robot1', datatype,
                       '3', code=101)
    assert datatype in response.error_description


@pytest.mark.parametrize('value', ['yes', '1', '0', 'on'])
def test_a_boolean_is_only_true_or_false(call, unchanged, value):
    response = failure(call, unchanged, 'ADD DATAPROP IND', 'charging', 'robot1', 'BOOL', value,
                       code=101)
    assert value in response.error_description
    failure(call, unchanged, 'ADD DATAPROP IND', 'charging', 'robot1', 'BOOLEAN', value, code=101)


# --- 208: malformed names, IRIs, class expressions, axioms, rules -----------------------------

@pytest.mark.parametrize('words, args, bad', [
    ('ADD IND CLASS', ['robot1', '<not an iri>'], '<not an iri>'),
    ('ADD IND CLASS', ['robot1', '<http://www.example.org/robotics#Robot'],
     '<http://www.example.org/robotics#Robot'),
    ('ADD IND CLASS', ['robot 1', 'Robot'], 'robot 1'),
    ('ADD OBJECTPROP IND', ['isIn', 'robot1', 'http://exa mple.org/x'], 'http://exa mple.org/x'),
    ('QUERY IND CLASS', ['<>'], '<>'),
    ('QUERY IND CLASS', [''], 'class'),
])
def test_a_malformed_name_or_iri_is_208_naming_it(call, unchanged, words, args, bad):
    response = failure(call, unchanged, words, *args, code=208)
    assert bad in response.error_description


@pytest.mark.parametrize('words, args', [
    ('QUERY IND DL', ['Robot and and']),
    ('QUERY CLASS DL', ['Location and not']),
    ('ADD CLASS EQUIVALENT', ['EmptyRoom', 'Room and (contains some']),
    ('ADD CLASS EQUIVALENT', ['EmptyRoom', 'Room and not']),
    ('ADD AXIOM', ['Robot SubClassOf isIn exactly']),
    ('ADD AXIOM', ['Robot SubClassOf isIn exactly 1 Location Location']),
    ('ADD SWRL', ['visited', 'Robot(?r), isIn(?r ?l) -> Visited(?l)']),
    ('ADD SWRL', ['visited', 'Robot(?r) ->']),
])
def test_a_malformed_expression_axiom_or_rule_is_208_saying_where(call, unchanged, words, args):
    response = failure(call, unchanged, words, *args, code=208)
    assert POSITION.search(response.error_description), response.error_description


@pytest.mark.parametrize('axiom, token', [
    ('SubClassOf(:Robot :Agent :Person)', ':Person'),
    ('SubClassOf(:Robot', ''),
])
def test_a_malformed_functional_syntax_axiom_is_208_saying_where_in_it(call, unchanged, axiom,
                                                                        token):
    response = failure(call, unchanged, 'ADD AXIOM', axiom, code=208)
    # The position must be one in the axiom the client sent (a single line).
    assert POSITION.search(response.error_description), response.error_description
    assert token in response.error_description


# --- LOAD errors: 209, 210, 213, 214, 218 -----------------------------------------------------

def _assert_not_loaded(call, name):
    assert name not in answer(call, '', 'GET ALL REFS')
    failure(call, name, 'QUERY IND CLASS', 'Robot', code=206)


@pytest.mark.parametrize('reasoner', ['NOSUCHREASONER', 'com.example.NoSuchReasonerFactory',
                                      'java.lang.String'])
def test_an_unknown_reasoner_is_210_and_loads_nothing(call, unchanged, reasoner):
    name = unique_name('bad_reasoner')
    response = failure(call, name, 'LOAD FILE', str(ROBOTICS), '', 'false', reasoner, 'false',
                       code=210)
    assert reasoner in response.error_description
    _assert_not_loaded(call, name)
    failure(call, name, 'CREATE', 'http://www.example.org/x', 'false', reasoner, 'false', code=210)
    _assert_not_loaded(call, name)


def test_an_unparsable_file_is_209_and_loads_nothing(call, unchanged, armor_node):
    broken = armor_node.scratch / f'{unique_name("broken")}.owl'
    broken.write_text('<rdf:RDF this is not xml')
    name = unique_name('broken')
    response = failure(call, name, 'LOAD FILE', str(broken), '', 'false', 'HERMIT', 'false',
                       code=209)
    assert broken.name in response.error_description
    _assert_not_loaded(call, name)


def test_a_file_that_is_no_ontology_is_209(call, unchanged, armor_node):
    text = armor_node.scratch / f'{unique_name("notes")}.txt'
    text.write_text('shopping list: milk, bread\n')
    name = unique_name('notes')
    failure(call, name, 'LOAD FILE', str(text), '', 'false', 'HERMIT', 'false', code=209)
    _assert_not_loaded(call, name)


def test_a_missing_file_is_209_and_loads_nothing(call, unchanged, armor_node):
    missing = armor_node.scratch / f'{unique_name("missing")}.owl'
    name = unique_name('missing')
    response = failure(call, name, 'LOAD FILE', str(missing), '', 'false', 'HERMIT', 'false',
                       code=209)
    assert missing.name in response.error_description
    _assert_not_loaded(call, name)


def test_paths_outside_allowed_dirs_are_213(call, unchanged, armor_node):
    name = unique_name('outside')
    failure(call, name, 'LOAD FILE', '/etc/hostname', '', 'false', 'HERMIT', 'false', code=213)
    escaping = str(armor_node.scratch / '..' / '..' / '..' / 'etc' / 'hostname')
    failure(call, name, 'LOAD FILE', escaping, '', 'false', 'HERMIT', 'false', code=213)
    link = armor_node.scratch / f'{unique_name("link")}.owl'
    os.symlink('/etc/hostname', link)
    failure(call, name, 'LOAD FILE', str(link), '', 'false', 'HERMIT', 'false', code=213)
    _assert_not_loaded(call, name)

    outside = armor_node.scratch.parent / f'{unique_name("outside")}.owl'
    response = failure(call, unchanged, 'SAVE', str(outside), code=213)
    assert 'write_dirs' in response.error_description
    failure(call, unchanged, 'SAVE INFERENCE', str(outside), code=213)
    failure(call, '', 'LOG FILE ON', str(outside.with_suffix('.log')), code=213)
    assert not outside.exists() and not outside.with_suffix('.log').exists()


def test_loading_another_file_under_a_loaded_name_is_214(call, unchanged):
    succeeded(call, unchanged, 'ADD IND CLASS', 'robot2', 'Robot')
    before = snapshot(call, unchanged)
    response = failure(call, unchanged, 'LOAD FILE', str(MIXED), '', 'false', 'HERMIT', 'false',
                       code=214)
    assert unchanged in response.error_description
    failure(call, unchanged, 'CREATE', 'http://www.example.org/x', 'false', 'HERMIT', 'false',
            code=214)
    assert snapshot(call, unchanged) == before
    # The same file under the same name is reused as it is.
    succeeded(call, unchanged, 'LOAD FILE', str(ROBOTICS), '', 'false', 'HERMIT', 'false')
    assert snapshot(call, unchanged) == before
    succeeded(call, unchanged, 'REMOVE IND CLASS', 'robot2', 'Robot')


@pytest.mark.parametrize('words', ['LOAD WEB', 'LOAD WEB MOUNTED'])
def test_load_web_is_218_while_web_loading_is_off(call, unchanged, words):
    name = unique_name('web')
    response = failure(call, name, words, 'https://www.example.org/robotics.owl', '', 'false',
                       'HERMIT', 'false', code=218)
    assert 'web_loading' in response.error_description
    _assert_not_loaded(call, name)


# --- other wrong arguments --------------------------------------------------------------------

@pytest.mark.parametrize('words, args, bad', [
    ('SAVE', ['{scratch}/klingon.owl', 'klingon'], 'klingon'),
    ('ADD OBJECTPROP CHARACTERISTIC', ['isIn', 'STICKY'], 'STICKY'),
    ('ADD DATAPROP CHARACTERISTIC', ['batteryLevel', 'TRANSITIVE'], 'TRANSITIVE'),
])
def test_an_argument_outside_its_choices_is_207_naming_it(call, unchanged, armor_node, words,
                                                          args, bad):
    args = [a.replace('{scratch}', str(armor_node.scratch)) for a in args]
    response = failure(call, unchanged, words, *args, code=207)
    assert bad in response.error_description
    assert not (armor_node.scratch / 'klingon.owl').exists()
