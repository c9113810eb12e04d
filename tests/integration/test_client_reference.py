# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The Python client (Armor, Reference, Batch) against the live node: every method.

Each test works on its own copy of robotics.owl, loaded under the test's name and dropped
afterwards, so tests neither see nor disturb each other or the preloaded "robotics".
"""

import pathlib
import re
import shutil
import time

from armor_client import (Armor, ArmorArgumentError, ArmorCallTimeout, ArmorFileError,
                          ArmorMountError, ArmorServiceCallError, ArmorUnknownReferenceError,
                          Characteristic, Reasoner)
from conftest import NS, ONTOLOGIES, REPO
import pytest

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')
LUBM_DEPARTMENT = REPO / 'bench' / 'data' / 'lubm' / 'university0-department0.owl'
OWL_THING = '<http://www.w3.org/2002/07/owl#Thing>'


@pytest.fixture
def session(armor):
    """An Armor session over the test run's transport."""
    return Armor('client_test', transport=armor, timeout_s=120)


@pytest.fixture
def ref(session, request):
    """A fresh copy of robotics.owl (HermiT), dropped after the test."""
    name = 'py_' + re.sub(r'\W', '_', request.node.name)
    reference = session.load_file(name, ROBOTICS)
    yield reference
    if name in session.references():
        reference.drop()


@pytest.fixture
def scratch(session, request):
    """An empty ontology with Pellet, dropped after the test."""
    name = 'scratch_' + re.sub(r'\W', '_', request.node.name)
    reference = session.create(name, 'http://example.org/scratch', reasoner=Reasoner.PELLET)
    yield reference
    reference.drop()


def test_queries_answer_python_values(ref):
    assert ref.types_of('robot1') == ['Agent', 'Robot', 'RobotInRoom']
    assert ref.classes_of('robot1') == ['Agent', 'Robot', 'RobotInRoom']
    assert ref.classes_of('robot1', most_specific=True) == ['RobotInRoom']
    assert ref.instances('Room') == ['bedroom', 'kitchen']
    assert ref.instances('OccupiedRoom') == ['kitchen']
    assert ref.dl_instances('Agent and isIn some Room') == ['robot1']
    assert ref.data_properties_of('robot1') == ['batteryLevel']
    assert ref.object_properties_of('robot1') == ['isIn']
    assert ref.data_values('batteryLevel', 'robot1') == [80]
    assert ref.data_values('visitedAt', 'bedroom') == [1700000000]
    assert ref.object_values('isIn', 'robot1') == ['kitchen']
    assert ref.object_values('connectedTo', 'corridor1') == ['bedroom', 'kitchen']


def test_class_and_property_queries(ref):
    assert ref.subclasses('Agent') == ['Person', 'Robot', 'RobotInRoom']
    assert ref.dl_subclasses('Agent and isIn some Room') == ['RobotInRoom']
    assert ref.superclasses('RobotInRoom') == ['Agent', 'Robot']
    assert ref.disjoint_classes('Room') == ['Corridor']
    assert ref.restrictions('OccupiedRoom') == ['contains some Agent']
    assert ref.equivalent_classes('OccupiedRoom') == []
    assert ref.same_individuals('robot1') == []
    assert ref.object_subproperties('isIn') == []
    assert ref.data_subproperties('visitedAt') == []


def test_sparql_ask_and_consistency(ref):
    rows = ref.sparql('SELECT ?who ?where WHERE { ?who :isIn ?where } ORDER BY ?who')
    assert rows == [{'who': 'alice', 'where': 'corridor1'}, {'who': 'robot1', 'where': 'kitchen'}]
    assert not rows.timed_out
    assert ref.sparql('SELECT ?v WHERE { :robot1 :batteryLevel ?v }', timeout_ms=60000) == [
        {'v': 80}]
    assert ref.sparql_lines('SELECT ?r WHERE { ?r a :OccupiedRoom }') == [f'<{NS}kitchen>']
    assert ref.sparql_lines('SELECT ?r WHERE { ?r a :Robot }', timeout_ms=60000) == [
        f'<{NS}robot1>']
    assert ref.ask('ASK { :robot1 :isIn :kitchen }') is True
    assert ref.ask('ASK { :robot1 :isIn :bedroom }') is False
    consistency = ref.check_consistency()
    assert consistency and consistency.explanation == []


def test_answers_as_iris_on_request(session, ref):
    with_iris = session.reference(ref.name, iris=True)
    assert with_iris.instances('Room') == [f'{NS}bedroom', f'{NS}kitchen']
    assert with_iris.restrictions('OccupiedRoom') == [f'<{NS}contains> some <{NS}Agent>']
    assert with_iris.sparql('SELECT ?r WHERE { ?r a :OccupiedRoom }') == [{'r': f'{NS}kitchen'}]


def test_individuals_are_added_classified_renamed_and_removed(ref):
    ref.add_individual('box1')
    assert 'box1' in ref.instances(OWL_THING)
    ref.add_individual_to_class('bob', 'Person')
    assert ref.instances('Person') == ['alice', 'bob']
    ref.rename_individual('bob', 'robert')
    assert ref.instances('Person') == ['alice', 'robert']
    ref.remove_individual_from_class('robert', 'Person')
    assert ref.instances('Person') == ['alice']
    ref.remove_individual('box1')
    assert 'box1' not in ref.instances(OWL_THING)
    assert ref.consistent is True


def test_same_and_different_individuals(scratch):
    scratch.add_same_individuals('robot1', 'turtlebot')
    assert scratch.same_individuals('robot1') == ['turtlebot']
    scratch.remove_same_individuals('robot1', 'turtlebot')
    assert scratch.same_individuals('robot1') == []
    scratch.make_individuals_different('kitchen', 'bedroom')
    scratch.add_same_individuals('kitchen', 'bedroom')
    assert not scratch.check_consistency()
    scratch.remove_same_individuals('kitchen', 'bedroom')
    scratch.add_individual_to_class('r1', 'Room')
    scratch.add_individual_to_class('r2', 'Room')
    scratch.make_instances_different('Room')
    scratch.add_same_individuals('r1', 'r2')
    inconsistent = scratch.check_consistency()
    assert not inconsistent.consistent and inconsistent.explanation
    assert scratch.consistent is False


def test_classes_are_declared_related_and_removed(ref):
    ref.add_class('Charger')
    assert ref.ask('ASK { :Charger a owl:Class }')
    ref.add_subclass('Charger', 'Location')
    assert 'Charger' in ref.subclasses('Location')
    ref.make_subclasses_disjoint('Location')
    assert ref.disjoint_classes('Charger') == ['Corridor', 'OccupiedRoom', 'Room']
    ref.remove_subclass('Charger', 'Location')
    assert 'Charger' not in ref.subclasses('Location')
    ref.rename_class('Charger', 'Dock')
    assert ref.ask('ASK { :Dock a owl:Class }')
    ref.remove_class('Dock')
    assert not ref.ask('ASK { :Dock a owl:Class }')
    ref.make_classes_disjoint('Robot', 'Person')
    assert ref.disjoint_classes('Robot') == ['Person']


def test_class_definitions_and_restrictions(ref):
    ref.add_equivalent_class('Busy', 'Room and (contains some Robot)')
    assert ref.instances('Busy') == ['kitchen']
    ref.remove_equivalent_class('Busy', 'Room and (contains some Robot)')
    assert ref.instances('Busy') == []
    ref.add_subclass('Dog', 'Agent')
    ref.make_equivalent_to_superclasses('Dog')
    assert ref.equivalent_classes('Dog') == ['Agent']
    ref.add_min_cardinality('Robot', 'isIn', 1, 'Location')
    assert ref.restrictions('Robot') == ['isIn min 1 Location']
    ref.add_axiom('Robot SubClassOf isIn max 1 Location')
    assert ref.restrictions('Robot') == ['isIn max 1 Location', 'isIn min 1 Location']
    ref.remove_axiom('Robot SubClassOf isIn max 1 Location')
    assert ref.restrictions('Robot') == ['isIn min 1 Location']


def test_data_values_keep_their_python_types(ref):
    ref.add_data_value('charging', 'robot1', True)
    ref.add_data_value('load', 'robot1', 0.5)
    ref.add_data_value('label', 'robot1', 'turtle')
    ref.add_data_value('visitedAt', 'kitchen', 1700000100, 'LONG')
    assert ref.data_values('charging', 'robot1') == [True]
    assert ref.data_values('load', 'robot1') == [0.5]
    assert ref.data_values('label', 'robot1') == ['turtle']
    ref.replace_data_value('visitedAt', 'kitchen', 1700000200, 1700000100, 'LONG')
    assert ref.data_values('visitedAt', 'kitchen') == [1700000200]
    ref.remove_data_value('visitedAt', 'kitchen', 1700000200, 'LONG')
    assert ref.data_values('visitedAt', 'kitchen') == []
    with pytest.raises(ArmorArgumentError) as bad:
        ref.add_data_value('batteryLevel', 'robot1', 'full', 'INTEGER')
    assert bad.value.exit_code == 101 and 'full' in bad.value.description


def test_object_values_drive_defined_classes(ref):
    ref.add_object_value('isIn', 'bob', 'bedroom')
    ref.add_individual_to_class('bob', 'Person')
    assert ref.instances('OccupiedRoom') == ['bedroom', 'kitchen']
    ref.replace_object_value('isIn', 'robot1', 'bedroom', 'kitchen')
    assert ref.instances('OccupiedRoom') == ['bedroom']
    ref.remove_object_value('isIn', 'bob', 'bedroom')
    assert ref.object_values('isIn', 'bob') == []


def test_property_axioms(ref):
    ref.add_object_subproperty('isDockedAt', 'isIn')
    assert ref.object_subproperties('isIn') == ['isDockedAt']
    ref.remove_object_subproperty('isDockedAt', 'isIn')
    assert ref.object_subproperties('isIn') == []
    ref.add_data_subproperty('lastVisit', 'visitedAt')
    assert ref.data_subproperties('visitedAt') == ['lastVisit']
    ref.remove_data_subproperty('lastVisit', 'visitedAt')
    assert ref.data_subproperties('visitedAt') == []
    ref.add_inverse_property('isIn', 'hosts')
    assert ref.object_values('hosts', 'kitchen') == ['robot1']
    ref.remove_inverse_property('isIn', 'hosts')
    assert ref.object_values('hosts', 'kitchen') == []
    ref.add_object_characteristic('connectedTo', Characteristic.TRANSITIVE)
    assert ref.object_values('connectedTo', 'kitchen') == ['bedroom', 'corridor1', 'kitchen']
    ref.remove_object_characteristic('connectedTo', 'TRANSITIVE')
    assert ref.object_values('connectedTo', 'kitchen') == ['corridor1']
    ref.rename_object_property('connectedTo', 'linkedTo')
    assert ref.object_values('linkedTo', 'kitchen') == ['corridor1']
    ref.rename_data_property('batteryLevel', 'charge')
    assert ref.data_values('charge', 'robot1') == [80]


def test_domains_and_ranges(ref):
    ref.add_object_domain('owns', 'Person')
    ref.add_object_range('owns', 'Gadget')
    ref.add_object_value('owns', 'carol', 'box')
    assert 'Person' in ref.types_of('carol') and ref.types_of('box') == ['Gadget']
    ref.remove_object_domain('owns', 'Person')
    ref.remove_object_range('owns', 'Gadget')
    assert ref.types_of('carol') == [] and ref.types_of('box') == []
    ref.add_data_domain('age', 'Person')
    ref.add_data_value('age', 'dave', 30)
    assert 'Person' in ref.types_of('dave')
    ref.remove_data_domain('age', 'Person')
    assert ref.types_of('dave') == []
    ref.add_data_range('age', 'INTEGER')
    assert ref.ask('ASK { :age rdfs:range xsd:integer }')
    ref.remove_data_range('age', 'INTEGER')
    assert not ref.ask('ASK { :age rdfs:range xsd:integer }')


def test_functional_data_property_and_rules(scratch):
    scratch.add_data_value('level', 'bot', 10)
    scratch.add_data_characteristic('level')
    scratch.add_data_value('level', 'bot', 20)
    assert not scratch.check_consistency()
    scratch.remove_data_characteristic('level')
    assert scratch.check_consistency()
    scratch.add_individual_to_class('bot', 'Robot')
    scratch.add_object_value('isIn', 'bot', 'lab')
    scratch.add_rule('visited', 'Robot(?r), isIn(?r, ?l) -> Visited(?l)')
    assert scratch.instances('Visited') == ['lab']
    scratch.remove_rule('visited', 'Robot(?r), isIn(?r, ?l) -> Visited(?l)')
    assert scratch.instances('Visited') == []


def test_buffered_changes_wait_for_apply_and_reason(session):
    buffered = session.load_file('py_buffered', ROBOTICS, reasoner=Reasoner.PELLET,
                                 buffered_manipulation=True, buffered_reasoner=True)
    try:
        buffered.add_individual_to_class('bob', 'Person')
        assert buffered.instances('Person') == ['alice']
        buffered.apply()
        buffered.add_object_value('isIn', 'bob', 'bedroom')
        assert 'bedroom' not in buffered.instances('OccupiedRoom')
        buffered.reason()
        assert buffered.instances('OccupiedRoom') == ['bedroom', 'kitchen']
    finally:
        buffered.drop()


def test_batch_is_atomic(ref):
    with ref.batch() as batch:
        batch.add_individual_to_class('bob', 'Person')
        batch.add_object_value('isIn', 'bob', 'bedroom')
        assert len(batch) == 2
    assert batch.consistent is True and len(batch) == 0
    assert ref.instances('OccupiedRoom') == ['bedroom', 'kitchen']
    with pytest.raises(ArmorArgumentError) as failed:
        with ref.batch() as batch:
            batch.remove_object_value('isIn', 'bob', 'bedroom')
            batch.add_data_value('batteryLevel', 'robot1', 'x', 'INTEGER')
            batch.remove_individual('robot1')
    assert failed.value.exit_code == 101 and failed.value.index == 1
    assert [r.exit_code for r in failed.value.responses] == [212, 101, 212]
    assert ref.instances('OccupiedRoom') == ['bedroom', 'kitchen']


def test_batch_is_not_sent_when_its_block_fails(ref):
    with pytest.raises(KeyError):
        with ref.batch() as batch:
            batch.add_individual_to_class('bob', 'Person')
            raise KeyError('changed my mind')
    assert ref.instances('Person') == ['alice']


def test_mounts_exclude_other_clients(session, armor, ref):
    other = Armor('other_client', transport=armor).reference(ref.name)
    with ref.mounted():
        assert ref.mounted_by() == 'client_test'
        with pytest.raises(ArmorMountError) as refused:
            other.add_individual_to_class('eve', 'Person')
        assert refused.value.exit_code == 102
        assert other.instances('Person') == ['alice']
        with pytest.raises(ArmorMountError):
            other.mount()
    assert ref.mounted_by() is None
    with pytest.raises(ArmorMountError) as not_held:
        ref.unmount()
    assert not_held.value.exit_code == 203
    with pytest.raises(RuntimeError):
        with ref.mounted():
            raise RuntimeError('crash while mounted')
    assert session.mounted_by(ref.name) is None
    ref.mount()
    assert session.mounted_by(ref.name) == 'client_test'
    ref.unmount()


def test_references_load_create_and_drop(session, armor_node):
    mounted = session.load_file('py_mounted', ROBOTICS, mount=True)
    assert mounted.consistent is True
    assert session.mounted_by('py_mounted') == 'client_test'
    assert {'py_mounted', 'robotics'} <= set(session.references())
    mounted.unmount()
    mounted.drop()
    assert 'py_mounted' not in session.references()
    with pytest.raises(ArmorUnknownReferenceError) as gone:
        mounted.instances('Room')
    assert gone.value.exit_code == 206
    with pytest.raises(ArmorFileError) as no_web:
        session.load_web('py_web', 'https://example.org/onto.owl')
    assert no_web.value.exit_code == 218
    empty = session.create('py_created', 'http://example.org/created', reasoner='HERMIT')
    assert empty.instances(OWL_THING) == []
    empty.drop()


def test_save_writes_files_on_the_node(ref, armor_node):
    scratch = pathlib.Path(armor_node.scratch)
    ref.add_individual_to_class('bob', 'Person')
    ref.save(str(scratch / 'py_saved.owl'))
    ref.save(str(scratch / 'py_saved.ttl'), 'turtle')
    ref.save(str(scratch / 'py_inferred.owl'), inferences=True)
    assert 'bob' in (scratch / 'py_saved.owl').read_text()
    assert '@prefix' in (scratch / 'py_saved.ttl').read_text()

    def kitchen_in(file_name):
        text = (scratch / file_name).read_text()
        return text.split('robotics#kitchen">', 1)[1].split('</', 1)[0]
    assert 'robotics#OccupiedRoom' in kitchen_in('py_inferred.owl')
    assert 'robotics#OccupiedRoom' not in kitchen_in('py_saved.owl')
    with pytest.raises(ArmorFileError) as outside:
        ref.save('/proc/py_saved.owl')
    assert outside.value.exit_code == 213


def _logged_line(client: str) -> str:
    """The directive log's line for a client's QUERY IND CLASS Robot on robotics, answered 0."""
    return rf'\[{client}\] robotics: QUERY IND CLASS \[Robot\] -> 0$'


def _ask_robots_as(armor, client: str) -> None:
    assert Armor(client, transport=armor).reference('robotics').instances('Robot') == ['robot1']


def test_logging_to_a_file_logs_while_on_and_appends(session, armor, armor_node):
    log = pathlib.Path(armor_node.scratch) / 'py_directives.log'
    session.log_to_file(str(log))
    _ask_robots_as(armor, 'logged_to_file')
    session.log_to_file(None)  # its lines are in the file when it returns
    _ask_robots_as(armor, 'not_logged_to_file')
    session.log_to_file(str(log))
    _ask_robots_as(armor, 'logged_again')
    session.log_to_file(None)
    text = log.read_text()
    assert re.search(_logged_line('logged_to_file'), text, re.MULTILINE), text
    assert re.search(_logged_line('logged_again'), text, re.MULTILINE), text
    assert '[not_logged_to_file]' not in text


def test_logging_to_the_screen_logs_while_on(session, armor, armor_node):
    session.log_to_screen(True)
    _ask_robots_as(armor, 'logged_on_screen')
    session.log_to_screen(False)
    _ask_robots_as(armor, 'not_logged_on_screen')
    session.log_to_screen(True)
    _ask_robots_as(armor, 'logged_on_screen_again')
    session.log_to_screen(False)
    # Lines reach the node's log in order: once the last is there, the others would be too.
    deadline = time.monotonic() + 60
    while not re.search(_logged_line('logged_on_screen_again'), armor_node.log(), re.MULTILINE):
        assert time.monotonic() < deadline, armor_node.log()[-3000:]
        time.sleep(0.2)
    text = armor_node.log()
    assert re.search(_logged_line('logged_on_screen'), text, re.MULTILINE)
    assert '[not_logged_on_screen]' not in text


def test_raw_calls_and_time_limits(session, armor, armor_node):
    response = session.call('robotics', 'QUERY', 'IND', 'CLASS', ['Robot'])
    assert response.success and list(response.queried_objects) == [f'<{NS}robot1>']
    assert not session.call('nowhere', 'QUERY', 'IND', 'CLASS', ['Robot']).success
    # A LOAD that parses 700 KB cannot answer within 50 ms; a quick query could, since the
    # spinner thread may take the answer in before the caller even starts waiting.
    department = armor_node.scratch / 'impatient-department.owl'
    shutil.copy2(LUBM_DEPARTMENT, department)
    impatient = Armor('impatient', transport=armor, timeout_s=0.05)
    with pytest.raises(ArmorCallTimeout):
        impatient.load_file('impatient_load', department)
    deadline = time.monotonic() + 120
    while 'impatient_load' not in session.references():
        assert time.monotonic() < deadline, 'the LOAD whose answer was not awaited never ended'
        time.sleep(0.2)
    session.reference('impatient_load').drop()


def test_no_service_is_a_call_error():
    with Armor('lonely', namespace='/nobody_here', service_wait_s=1.0) as lonely:
        with pytest.raises(ArmorServiceCallError) as missing:
            lonely.references()
    assert missing.value.exit_code is None and 'armor serve' in str(missing.value)
