# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Contract sections 3 and 4 over ROS 2: how an argument names its entity (plain name,
<full IRI>, bare http IRI, prefix:Name, a plain name found in another namespace, ambiguity,
unknown prefix, creation) and what queries return (full IRIs, typed literals, sorted answers,
no owl:Thing or owl:Nothing, empty answers as successes, short names with
full_entity_iri:=false on a node of its own).

tests/ontologies/mixed-namespaces.ttl has its default namespace http://www.example.org/home#,
device entities under http://www.example.org/devices/ (prefix dev:), and a class Sensor both
there and in http://www.example.org/other#.
"""

from armor_client import ArmorTransport, directive
from conftest import NS, iri, iris, start_node
import pytest
from test_contract_support import (MAIN_REASONERS, MIXED, ROBOTICS, answer, failure, literal,
                                   robotics_declarations, succeeded, unique_name)
from test_contract_support import load  # noqa: F401 (fixture)

HOME = 'http://www.example.org/home#'
DEV = 'http://www.example.org/devices/'
OTHER = 'http://www.example.org/other#'


def home(name):
    return f'<{HOME}{name}>'


def dev(name):
    return f'<{DEV}{name}>'


@pytest.fixture(params=MAIN_REASONERS)
def robotics(request, load):
    return load(request.param)


@pytest.fixture(params=MAIN_REASONERS)
def mixed(request, load):
    return load(request.param, path=MIXED)


# --- section 3: naming ------------------------------------------------------------------------

@pytest.mark.parametrize('spelling', [
    'Robot',
    f'<{NS}Robot>',
    f'{NS}Robot',
    ':Robot',  # robotics.owl declares its namespace as the default prefix
])
def test_a_class_may_be_named_plainly_by_iri_or_by_prefix(call, robotics, spelling):
    assert answer(call, robotics, 'QUERY IND CLASS', spelling) == iris('robot1')
    assert answer(call, robotics, 'QUERY CLASS SUPER', spelling) == iris('Agent')


@pytest.mark.parametrize('individual', ['robot1', f'<{NS}robot1>', f'{NS}robot1', ':robot1'])
@pytest.mark.parametrize('prop', ['isIn', f'<{NS}isIn>', f'{NS}isIn', ':isIn'])
def test_properties_and_individuals_take_the_same_spellings(call, robotics, individual, prop):
    assert answer(call, robotics, 'QUERY OBJECTPROP IND', prop, individual) == iris('kitchen')


def test_a_declared_standard_prefix_names_owl_thing(call, robotics):
    _, individuals = robotics_declarations()
    assert answer(call, robotics, 'QUERY IND CLASS', 'owl:Thing') == iris(*individuals)


def test_a_full_iri_in_a_manipulation_creates_the_entity_in_its_own_namespace(call, robotics):
    elsewhere = 'http://www.example.org/elsewhere#'
    succeeded(call, robotics, 'ADD IND CLASS', f'<{elsewhere}r5>', 'Robot')
    succeeded(call, robotics, 'ADD IND CLASS', f'{elsewhere}r6', f'<{NS}Robot>')
    assert answer(call, robotics, 'QUERY IND CLASS', 'Robot') == sorted(
        [f'<{elsewhere}r5>', f'<{elsewhere}r6>', iri('robot1')])


def test_a_new_plain_name_lands_in_the_namespace_of_the_iri_given_at_load(call, load):
    site = 'http://www.example.org/site'
    ref = load('HERMIT', ontology_iri=site)
    # Robot exists once, in the file's namespace: the plain name finds it ...
    assert answer(call, ref, 'QUERY IND CLASS', 'Robot') == iris('robot1')
    # ... and names that do not exist yet are created in the namespace given at LOAD.
    succeeded(call, ref, 'ADD IND CLASS', 'r9', 'Robot')
    succeeded(call, ref, 'ADD IND CLASS', 'newbie', 'Newcomer')
    assert answer(call, ref, 'QUERY IND CLASS', 'Robot') == sorted([f'<{site}#r9>',
                                                                    iri('robot1')])
    assert answer(call, ref, 'QUERY IND CLASS', f'<{site}#Newcomer>') == [f'<{site}#newbie>']


def test_without_an_iri_at_load_new_names_take_the_file_s_namespace(call, robotics):
    succeeded(call, robotics, 'ADD IND CLASS', 'newbie', 'Newcomer')
    assert answer(call, robotics, 'QUERY IND CLASS', f'<{NS}Newcomer>') == iris('newbie')


def test_plain_names_find_entities_in_another_namespace(call, mixed):
    assert answer(call, mixed, 'QUERY IND CLASS', 'Charger') == [dev('dock1')]
    assert answer(call, mixed, 'QUERY IND CLASS', 'Device') == [dev('dock1')]
    assert answer(call, mixed, 'QUERY OBJECTPROP IND', 'installedIn', 'dock1') == [home('hall')]
    assert answer(call, mixed, 'QUERY DATAPROP IND', 'powerWatts', 'dock1') == [
        literal('65', 'integer')]
    assert answer(call, mixed, 'QUERY CLASS CLASS', 'Device') == sorted(
        [dev('Charger'), dev('Lamp'), dev('Sensor')])


def test_plain_names_in_class_expressions_follow_the_same_rules(call, mixed):
    assert answer(call, mixed, 'QUERY IND DL', 'Charger and installedIn value hall') == [
        dev('dock1')]
    assert answer(call, mixed, 'QUERY IND DL', 'dev:Charger and dev:installedIn some Room') == [
        dev('dock1')]


def test_a_manipulation_with_plain_names_uses_the_entities_found(call, mixed):
    succeeded(call, mixed, 'ADD IND CLASS', 'lamp1', 'Lamp')
    succeeded(call, mixed, 'ADD OBJECTPROP IND', 'installedIn', 'lamp1', 'hall')
    # lamp1 is new: it is created in the default namespace, as a member of dev:Lamp.
    assert answer(call, mixed, 'QUERY IND CLASS', 'dev:Lamp') == [home('lamp1')]
    assert answer(call, mixed, 'QUERY OBJECTPROP IND', f'<{DEV}installedIn>', 'lamp1') == [
        home('hall')]
    assert answer(call, mixed, 'QUERY IND CLASS', 'Device') == sorted([dev('dock1'),
                                                                      home('lamp1')])


def test_prefixed_names_use_the_prefixes_the_document_declares(call, mixed):
    assert answer(call, mixed, 'QUERY IND CLASS', 'dev:Charger') == [dev('dock1')]
    assert answer(call, mixed, 'QUERY OBJECTPROP IND', 'dev:installedIn', 'dev:dock1') == [
        home('hall')]
    assert answer(call, mixed, 'QUERY IND CLASS', ':Room') == [home('hall')]


def test_the_default_namespace_wins_over_another_namespace(call, mixed):
    # Reading chosen where the contract is ambiguous: ARMOR's rule (default namespace) first,
    # the search in other namespaces only when the default one has no such entity.
    succeeded(call, mixed, 'ADD CLASS', f'<{OTHER}Room>')
    assert answer(call, mixed, 'QUERY IND CLASS', 'Room') == [home('hall')]


def test_an_ambiguous_plain_name_is_an_error_listing_the_candidates(call, mixed):
    before = answer(call, mixed, 'QUERY IND CLASS', 'owl:Thing')
    response = failure(call, mixed, 'QUERY IND CLASS', 'Sensor', code=215)
    assert f'{DEV}Sensor' in response.error_description
    assert f'{OTHER}Sensor' in response.error_description

    response = failure(call, mixed, 'ADD IND CLASS', 'sensor1', 'Sensor', code=215)
    assert f'{DEV}Sensor' in response.error_description
    assert f'{OTHER}Sensor' in response.error_description
    assert answer(call, mixed, 'QUERY IND CLASS', 'owl:Thing') == before
    # Either candidate is reachable by a name that is not ambiguous.
    assert answer(call, mixed, 'QUERY IND CLASS', 'dev:Sensor') == []
    assert answer(call, mixed, 'QUERY CLASS SUPER', f'<{OTHER}Sensor>') == []
    assert answer(call, mixed, 'QUERY CLASS SUPER', 'dev:Sensor') == [home('Device')]


def test_an_unknown_prefix_is_an_error_naming_it(call, mixed):
    before = answer(call, mixed, 'QUERY IND CLASS', 'owl:Thing')
    response = failure(call, mixed, 'QUERY IND CLASS', 'nope:Lamp', code=208)
    assert 'nope' in response.error_description
    response = failure(call, mixed, 'ADD IND CLASS', 'lamp2', 'nope:Lamp', code=208)
    assert 'nope' in response.error_description
    assert answer(call, mixed, 'QUERY IND CLASS', 'owl:Thing') == before


# --- section 4: what queries return -----------------------------------------------------------

def test_answers_are_sorted_whatever_the_order_of_creation(call, robotics):
    for name in ['zeta', 'alpha', 'mu', 'Beta', 'robot10', 'robot2']:
        succeeded(call, robotics, 'ADD IND CLASS', name, 'Robot')
    robots = answer(call, robotics, 'QUERY IND CLASS', 'Robot')
    assert robots == sorted(robots)
    assert robots == iris('zeta', 'alpha', 'mu', 'Beta', 'robot10', 'robot2', 'robot1')


def test_owl_thing_and_owl_nothing_are_never_answers(call, robotics):
    classes, _ = robotics_declarations()
    # Every class is below owl:Thing and above owl:Nothing; neither of the two is listed.
    assert answer(call, robotics, 'QUERY CLASS CLASS', 'owl:Thing') == iris(*classes)
    assert answer(call, robotics, 'QUERY CLASS SUPER', 'owl:Nothing') == iris(*classes)
    assert answer(call, robotics, 'QUERY CLASS SUPER', 'Location') == []
    assert answer(call, robotics, 'QUERY CLASS CLASS', 'Corridor') == []
    assert answer(call, robotics, 'QUERY IND', 'alice') == iris('Agent', 'Person')
    assert answer(call, robotics, 'QUERY CLASS IND', 'corridor1') == iris('Corridor', 'Location')


def test_an_empty_answer_is_a_success_with_an_empty_list(call, robotics):
    for words, args in [('QUERY IND CLASS', ['NeverUsed']),
                        ('QUERY OBJECTPROP IND', ['isIn', 'kitchen']),
                        ('QUERY DATAPROP IND', ['batteryLevel', 'alice']),
                        ('QUERY CLASS CLASS', ['Corridor']),
                        ('QUERY IND', ['nobody'])]:
        response = call(robotics, words, *args)
        assert response.success and response.exit_code == 0, (words, response.error_description)
        assert list(response.queried_objects) == [], words


# --- full_entity_iri:=false -------------------------------------------------------------------

@pytest.fixture(scope='module')
def short_names(tmp_path_factory):
    """A node of its own, in its own namespace, answering short names."""
    node = start_node(tmp_path_factory.mktemp('short'), '-r', '__ns:=/short',
                      '-p', 'full_entity_iri:=false')
    transport = ArmorTransport(namespace='/short', service_wait_s=90.0)

    def send(reference, words, *args):
        command, primary, secondary = (words.split() + ['', '', ''])[:3]
        return transport.call(directive('test', reference, command, primary, secondary, args),
                              timeout_s=120)

    try:
        assert send('', 'GET ALL REFS').success, node.log()
        yield send
    finally:
        transport.close()
        node.stop()


def test_short_names_for_entities_with_full_entity_iri_false(short_names):
    ref = unique_name('short')
    succeeded(short_names, ref, 'LOAD FILE', str(ROBOTICS), '', 'false', 'PELLET', 'false')
    try:
        assert answer(short_names, ref, 'QUERY IND CLASS', 'OccupiedRoom') == ['kitchen']
        assert answer(short_names, ref, 'QUERY IND', 'robot1') == ['Agent', 'Robot',
                                                                   'RobotInRoom']
        assert answer(short_names, ref, 'QUERY CLASS SUPER', 'RobotInRoom') == ['Agent', 'Robot']
        assert answer(short_names, ref, 'QUERY IND OBJECTPROP', 'kitchen') == ['connectedTo',
                                                                               'contains']
        assert answer(short_names, ref, 'QUERY CLASS RESTRICTIONS', 'OccupiedRoom') == [
            'contains some Agent']
        # Literals keep their form.
        assert answer(short_names, ref, 'QUERY DATAPROP IND', 'batteryLevel', 'robot1') == [
            literal('80', 'integer')]
        # Full IRIs are still accepted as arguments.
        assert answer(short_names, ref, 'QUERY IND CLASS', f'<{NS}Robot>') == ['robot1']
    finally:
        short_names(ref, 'DROP')


def test_short_names_in_sparql_answers(short_names):
    assert answer(short_names, 'robotics', 'QUERY SPARQL',
                  'SELECT ?r WHERE { ?r a :OccupiedRoom }') == ['kitchen']
    assert answer(short_names, 'robotics', 'QUERY SPARQL',
                  'SELECT ?a ?l WHERE { ?a :isIn ?l } ORDER BY ?a') == [
        'a=alice; l=corridor1', 'a=robot1; l=kitchen']
    response = succeeded(short_names, 'robotics', 'QUERY SPARQL FORMATTED',
                         'SELECT ?b WHERE { :robot1 :batteryLevel ?b }')
    assert [(i.key, i.value) for i in response.sparql_queried_objects] == [
        ('b', literal('80', 'integer'))]


def test_short_names_across_namespaces(short_names):
    ref = unique_name('short_mixed')
    succeeded(short_names, ref, 'LOAD FILE', str(MIXED), '', 'false', 'HERMIT', 'false')
    try:
        assert answer(short_names, ref, 'QUERY IND CLASS', 'Device') == ['dock1']
        assert answer(short_names, ref, 'QUERY CLASS CLASS', 'Device') == ['Charger', 'Lamp',
                                                                          'Sensor']
    finally:
        short_names(ref, 'DROP')
