# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Contract section 5.1, SAVE [-/INFERENCE] over ROS 2: every format writes a document that
loads back into a fresh reference with the same answers; SAVE without a path writes the file
the reference was loaded from; SAVE INFERENCE writes the inferred class assertions, property
assertions and class hierarchy into the file only, never into the live ontology.

The inferred files are read back with ELK, which cannot derive OccupiedRoom's members (they
need the inverse of isIn): when ELK answers them, the file states them.
"""

import shutil

from conftest import iri, iris
import pytest
from test_contract_support import (MAIN_REASONERS, ROBOTICS, ROBOTICS_IRI, answer, literal,
                                   succeeded, unique_name)
from test_contract_support import load  # noqa: F401 (fixture)

FORMATS = ['rdfxml', 'owlxml', 'turtle', 'functional', 'manchester']
# How each format's document begins, once comments and blank lines are skipped.
FORMAT_SIGNS = {
    'rdfxml': '<rdf:RDF',
    'owlxml': '<Ontology',
    'turtle': '@',  # @prefix or @base
    'functional': 'Prefix(',
    'manchester': 'Prefix:',
}


def _first_statement(text: str) -> str:
    for line in text.splitlines():
        stripped = line.strip()
        if stripped and not stripped.startswith(('<?xml', '<!', '#', '//')):
            return stripped
    return ''


def _extend(call, ref):
    """Changes that only the saved file can carry to a new reference."""
    succeeded(call, ref, 'ADD IND CLASS', 'bob', 'Person')
    succeeded(call, ref, 'ADD OBJECTPROP IND', 'isIn', 'bob', 'bedroom')
    succeeded(call, ref, 'REPLACE DATAPROP IND', 'batteryLevel', 'robot1', 'INT', '55', '80')
    succeeded(call, ref, 'ADD CLASS CLASS', 'Charger', 'Location')
    succeeded(call, ref, 'REASON')


def _answers(call, ref) -> dict:
    return {
        'OccupiedRoom': answer(call, ref, 'QUERY IND CLASS', 'OccupiedRoom'),
        'Agent': answer(call, ref, 'QUERY IND CLASS', 'Agent'),
        'Location subclasses': answer(call, ref, 'QUERY CLASS CLASS', 'Location'),
        'batteryLevel': answer(call, ref, 'QUERY DATAPROP IND', 'batteryLevel', 'robot1'),
        'isIn bob': answer(call, ref, 'QUERY OBJECTPROP IND', 'isIn', 'bob'),
        'visitedAt': answer(call, ref, 'QUERY DATAPROP IND', 'visitedAt', 'bedroom'),
    }


EXTENDED_ANSWERS = {
    'OccupiedRoom': iris('bedroom', 'kitchen'),
    'Agent': iris('alice', 'bob', 'robot1'),
    'Location subclasses': iris('Charger', 'Corridor', 'OccupiedRoom', 'Room'),
    'batteryLevel': [literal('55', 'integer')],
    'isIn bob': iris('bedroom'),
    'visitedAt': [literal('1700000000', 'long')],
}


@pytest.mark.parametrize('reasoner', MAIN_REASONERS)
@pytest.mark.parametrize('file_format', FORMATS)
def test_save_in_each_format_loads_back_with_the_same_answers(call, load, armor_node, reasoner,
                                                              file_format):
    ref = load(reasoner)
    _extend(call, ref)
    assert _answers(call, ref) == EXTENDED_ANSWERS
    path = armor_node.scratch / f'{unique_name("saved")}.{file_format}'
    succeeded(call, ref, 'SAVE', str(path), file_format)
    assert _first_statement(path.read_text()).startswith(FORMAT_SIGNS[file_format])

    copy = load(reasoner, path=path, ontology_iri=ROBOTICS_IRI)
    assert _answers(call, copy) == EXTENDED_ANSWERS


def test_save_without_a_path_writes_the_loaded_file(call, load, armor_node):
    path = armor_node.scratch / f'{unique_name("own")}.owl'
    shutil.copy(ROBOTICS, path)
    ref = load('HERMIT', path=path)
    _extend(call, ref)
    succeeded(call, ref, 'SAVE')
    assert _answers(call, load('PELLET', path=path)) == EXTENDED_ANSWERS

    succeeded(call, ref, 'REMOVE IND', 'bob')
    succeeded(call, ref, 'SAVE', '')  # an empty path also means the loaded file
    assert answer(call, load('PELLET', path=path), 'QUERY IND CLASS', 'Agent') == iris(
        'alice', 'robot1')


def test_save_in_the_loaded_format_by_default(call, load, armor_node):
    source = armor_node.scratch / f'{unique_name("turtle")}.ttl'
    ref = load('HERMIT')
    succeeded(call, ref, 'SAVE', str(source), 'turtle')
    turtle_ref = load('HERMIT', path=source)
    copy = armor_node.scratch / f'{unique_name("copy")}.ttl'
    succeeded(call, turtle_ref, 'SAVE', str(copy))
    assert _first_statement(copy.read_text()).startswith(FORMAT_SIGNS['turtle'])
    assert answer(call, load('HERMIT', path=copy), 'QUERY IND CLASS', 'OccupiedRoom') == iris(
        'kitchen')


@pytest.mark.parametrize('reasoner', MAIN_REASONERS)
@pytest.mark.parametrize('file_format', FORMATS)
def test_save_inference_writes_inferences_to_the_file_only(call, load, armor_node, reasoner,
                                                           file_format):
    ref = load(reasoner, buffered_reasoner=True)
    _extend(call, ref)
    path = armor_node.scratch / f'{unique_name("inferred")}.{file_format}'
    succeeded(call, ref, 'SAVE INFERENCE', str(path), file_format)
    assert _first_statement(path.read_text()).startswith(FORMAT_SIGNS[file_format])

    # ELK cannot infer these: the file states them (class and property assertions).
    elk = load('ELK', path=path, ontology_iri=ROBOTICS_IRI)
    assert answer(call, elk, 'QUERY IND CLASS', 'OccupiedRoom') == iris('bedroom', 'kitchen')
    assert answer(call, elk, 'QUERY OBJECTPROP IND', 'contains', 'bedroom') == iris('bob')
    assert answer(call, elk, 'QUERY OBJECTPROP IND', 'connectedTo', 'corridor1') == iris(
        'bedroom', 'kitchen')
    # ... and the loaded file answers as the live reference did.
    assert _answers(call, load(reasoner, path=path, ontology_iri=ROBOTICS_IRI)) == (
        EXTENDED_ANSWERS)

    # The live ontology did not take the inferences in: a plain SAVE of it states none of them.
    plain = armor_node.scratch / f'{unique_name("plain")}.{file_format}'
    succeeded(call, ref, 'SAVE', str(plain), file_format)
    elk_plain = load('ELK', path=plain, ontology_iri=ROBOTICS_IRI)
    assert answer(call, elk_plain, 'QUERY IND CLASS', 'OccupiedRoom') == []
    assert answer(call, elk_plain, 'QUERY OBJECTPROP IND', 'contains', 'bedroom') == []
    assert answer(call, elk_plain, 'QUERY OBJECTPROP IND', 'connectedTo', 'corridor1') == []
    assert _answers(call, ref) == EXTENDED_ANSWERS


def test_save_inference_writes_the_inferred_class_hierarchy(call, load, armor_node):
    ref = load('HERMIT')
    # Only a reasoner that handles negation sees that a Corridor is never a Room.
    succeeded(call, ref, 'ADD CLASS EQUIVALENT', 'NotRoom', 'not Room')
    assert answer(call, ref, 'QUERY CLASS CLASS', 'NotRoom') == iris('Corridor')
    path = armor_node.scratch / f'{unique_name("hierarchy")}.owl'
    succeeded(call, ref, 'SAVE INFERENCE', str(path))
    elk = load('ELK', path=path, ontology_iri=ROBOTICS_IRI)
    assert iri('Corridor') in answer(call, elk, 'QUERY CLASS CLASS', 'NotRoom')
    assert answer(call, elk, 'QUERY CLASS SUPER', 'OccupiedRoom') == iris('Location', 'Room')

    # The live ontology keeps only what was asserted: a plain SAVE has no inferred axiom.
    plain = armor_node.scratch / f'{unique_name("plain")}.owl'
    succeeded(call, ref, 'SAVE', str(plain))
    elk_plain = load('ELK', path=plain, ontology_iri=ROBOTICS_IRI)
    assert answer(call, elk_plain, 'QUERY IND CLASS', 'OccupiedRoom') == []
    assert answer(call, elk_plain, 'QUERY CLASS CLASS', 'NotRoom') == []
