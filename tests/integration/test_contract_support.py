# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Shared helpers of the contract tests (test_contract_*.py); it holds no tests itself.

- `load`: a fixture that LOADs ontologies/robotics.owl (or another file) under a fresh,
  unique reference name and DROPs every reference it made when the test ends;
- `answer`: send a directive that must succeed and return its queried_objects;
- `failure`: send a directive that must fail with a given code and a description;
- `snapshot`: what a reference answers to a fixed set of questions, to show that a failed
  directive changed nothing;
- what robotics.owl declares, read from the file itself, for answers that list everything.
"""

import uuid
import xml.etree.ElementTree as ElementTree

from conftest import NS, ONTOLOGIES, TEST_ONTOLOGIES
import pytest

ROBOTICS = ONTOLOGIES / 'robotics.owl'
MIXED = TEST_ONTOLOGIES / 'mixed-namespaces.ttl'
ROBOTICS_IRI = 'http://www.example.org/robotics'

# The contract asks for HermiT and Openllet at least; JFact answers the same questions cheaply.
MAIN_REASONERS = ['HERMIT', 'PELLET']
EXPRESSIVE_REASONERS = ['HERMIT', 'PELLET', 'JFACT']

_RDF = '{http://www.w3.org/1999/02/22-rdf-syntax-ns#}'
_OWL = '{http://www.w3.org/2002/07/owl#}'


def unique_name(prefix: str) -> str:
    return f'{prefix}_{uuid.uuid4().hex[:10]}'


def literal(lexical: str, xsd_type: str) -> str:
    """A literal as the contract renders it: "lexical"^^xsd:type."""
    return f'"{lexical}"^^xsd:{xsd_type}'


def describe(response) -> str:
    return (f'exit_code={response.exit_code} success={response.success} '
            f'error_description={response.error_description!r} '
            f'queried_objects={list(response.queried_objects)}')


def succeeded(call, reference, words, *args, **kwargs):
    """Send a directive that must succeed; return the whole response."""
    response = call(reference, words, *args, **kwargs)
    assert response.success and response.exit_code == 0, (
        f'{words} {list(args)} on {reference!r}: {describe(response)}')
    return response


def answer(call, reference, words, *args, **kwargs) -> list:
    """Send a directive that must succeed; return its queried_objects as a list."""
    return list(succeeded(call, reference, words, *args, **kwargs).queried_objects)


def failure(call, reference, words, *args, code: int, **kwargs):
    """Send a directive that must fail with `code` and a description; return the response."""
    response = call(reference, words, *args, **kwargs)
    what = f'{words} {list(args)}'
    assert not response.success, f'{what} should fail with {code}: {describe(response)}'
    assert response.exit_code == code, f'{what}: {describe(response)}'
    assert response.error_description.strip(), f'{what}: failure without a description'
    return response


def snapshot(call, reference: str) -> dict:
    """The answers of a robotics reference to questions every manipulation would disturb."""
    questions = [
        ('QUERY IND CLASS', 'Robot'),
        ('QUERY IND CLASS', 'Agent'),
        ('QUERY IND CLASS', 'OccupiedRoom'),
        ('QUERY CLASS CLASS', 'Location'),
        ('QUERY CLASS SUPER', 'Robot'),
        ('QUERY OBJECTPROP IND', 'isIn', 'robot1'),
        ('QUERY DATAPROP IND', 'batteryLevel', 'robot1'),
        ('QUERY IND', 'robot1'),
        ('QUERY IND SAME', 'robot1'),
        ('QUERY CONSISTENCY',),
    ]
    state = {}
    for words, *args in questions:
        response = call(reference, words, *args)
        state[(words, *args)] = (response.success, response.is_consistent,
                                 list(response.queried_objects))
    refs = call('', 'GET ALL REFS')
    state['GET ALL REFS'] = sorted(refs.queried_objects)
    return state


@pytest.fixture
def load(call):
    """load(reasoner, buffered_manipulation, buffered_reasoner, path, ontology_iri) -> name.

    Loads a file (robotics.owl by default) under a new unique reference name with LOAD FILE;
    every reference loaded this way is dropped when the test ends.
    """
    loaded = []

    def load_file(reasoner='HERMIT', buffered_manipulation=False, buffered_reasoner=False,
                  path=ROBOTICS, ontology_iri='', prefix='contract', client='test'):
        name = unique_name(prefix)
        succeeded(call, name, 'LOAD FILE', str(path), ontology_iri,
                  str(buffered_manipulation).lower(), reasoner,
                  str(buffered_reasoner).lower(), client=client)
        loaded.append((name, client))
        return name

    yield load_file
    for name, client in loaded:
        call(name, 'DROP', client=client)


def robotics_declarations():
    """(classes, individuals) that robotics.owl declares, as short names, read from the file."""
    root = ElementTree.parse(ROBOTICS).getroot()
    classes = sorted(element.get(f'{_RDF}about')[len(NS):]
                     for element in root.findall(f'{_OWL}Class'))
    individuals = sorted(element.get(f'{_RDF}about')[len(NS):]
                         for element in root.findall(f'{_OWL}NamedIndividual'))
    return classes, individuals
