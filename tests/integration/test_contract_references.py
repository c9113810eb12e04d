# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Contract section 5.1 over ROS 2: references and utilities (LOAD FILE, CREATE, DROP, MOUNT,
GET ALL REFS, GET REF CLIENT, LOG) and the APPLY/REASON semantics of the buffering modes.

SAVE has its own file (test_contract_save.py); the error rows of LOAD (209, 210, 213, 214,
218) are in test_contract_errors.py.
"""

import time

from conftest import iri, iris
import pytest
from test_contract_support import (EXPRESSIVE_REASONERS, MAIN_REASONERS, MIXED, ROBOTICS,
                                   answer, failure, succeeded, unique_name)
from test_contract_support import load  # noqa: F401 (fixture)


@pytest.mark.parametrize('reasoner', EXPRESSIVE_REASONERS + ['ELK'])
def test_load_file_creates_a_reference_answering_with_that_reasoner(call, load, reasoner):
    name = load(reasoner)
    assert name in answer(call, '', 'GET ALL REFS')
    assert answer(call, name, 'QUERY IND CLASS', 'Robot') == iris('robot1')
    # RobotInRoom is an OWL 2 EL definition: every reasoner, ELK included, finds robot1.
    assert answer(call, name, 'QUERY IND CLASS', 'RobotInRoom') == iris('robot1')


@pytest.mark.parametrize('spelling', ['hermit', 'Pellet', 'OPENLLET', 'jFact',
                                      'org.semanticweb.HermiT.ReasonerFactory', ''])
def test_reasoner_names_are_case_insensitive_and_may_be_a_factory_class(call, load, spelling):
    # '' is the node's default reasoner (HERMIT). Each of these reasoners finds OccupiedRoom's
    # member through the inverse of isIn, which only an expressive reasoner does.
    name = load(spelling)
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('kitchen')


def test_load_file_mounted_mounts_the_caller(call, load):
    name = load('HERMIT', client='planner')  # without MOUNTED, the loader holds no mount
    assert answer(call, '', 'GET REF CLIENT', name) == []

    mounted = unique_name('mounted')
    response = succeeded(call, mounted, 'LOAD FILE MOUNTED', str(ROBOTICS), '', 'false',
                         'HERMIT', 'false', client='planner')
    assert response.is_consistent
    try:
        assert answer(call, '', 'GET REF CLIENT', mounted) == ['planner']
        failure(call, mounted, 'ADD IND CLASS', 'robot2', 'Robot', client='intruder', code=102)
        assert answer(call, mounted, 'QUERY IND CLASS', 'Robot',
                      client='intruder') == iris('robot1')
        succeeded(call, mounted, 'UNMOUNT', client='planner')
    finally:
        call(mounted, 'DROP', client='planner')


def test_loading_the_same_file_again_reuses_the_reference(call, load):
    name = load('PELLET')
    succeeded(call, name, 'ADD IND CLASS', 'robot2', 'Robot')
    # Same name, same file: the loaded reference is reused as it is, not read again.
    succeeded(call, name, 'LOAD FILE', str(ROBOTICS), '', 'false', 'PELLET', 'false')
    assert answer(call, name, 'QUERY IND CLASS', 'Robot') == iris('robot1', 'robot2')
    assert answer(call, '', 'GET ALL REFS').count(name) == 1


@pytest.mark.parametrize('reasoner', MAIN_REASONERS)
def test_create_builds_an_empty_ontology_in_the_given_namespace(call, reasoner):
    name = unique_name('created')
    ns = f'http://www.example.org/{name}'
    response = succeeded(call, name, 'CREATE', ns, 'false', reasoner, 'false')
    assert response.is_consistent
    try:
        assert name in answer(call, '', 'GET ALL REFS')
        assert answer(call, name, 'QUERY CLASS CLASS', 'owl:Thing') == []
        assert answer(call, name, 'QUERY IND CLASS', 'owl:Thing') == []
        succeeded(call, name, 'ADD CLASS CLASS', 'Drone', 'Robot')
        succeeded(call, name, 'ADD IND CLASS', 'uav1', 'Drone')
        assert answer(call, name, 'QUERY IND CLASS', 'Robot') == [f'<{ns}#uav1>']
        assert answer(call, name, 'QUERY CLASS CLASS', 'owl:Thing') == sorted(
            [f'<{ns}#Drone>', f'<{ns}#Robot>'])
    finally:
        call(name, 'DROP')


def test_create_with_buffered_manipulation_waits_for_apply(call):
    name = unique_name('created')
    ns = f'http://www.example.org/{name}'
    succeeded(call, name, 'CREATE', ns, 'true', 'HERMIT', 'false')
    try:
        succeeded(call, name, 'ADD IND CLASS', 'uav1', 'Drone')
        assert answer(call, name, 'QUERY IND CLASS', 'Drone') == []
        succeeded(call, name, 'APPLY')
        assert answer(call, name, 'QUERY IND CLASS', 'Drone') == [f'<{ns}#uav1>']
    finally:
        call(name, 'DROP')


def test_drop_unloads_the_reference_and_frees_its_name(call):
    name = unique_name('dropped')
    succeeded(call, name, 'LOAD FILE', str(ROBOTICS), '', 'false', 'HERMIT', 'false')
    succeeded(call, name, 'DROP')
    assert name not in answer(call, '', 'GET ALL REFS')
    failure(call, name, 'QUERY IND CLASS', 'Robot', code=206)
    # The name is free again, even for another file.
    succeeded(call, name, 'LOAD FILE', str(MIXED), '', 'false', 'HERMIT', 'false')
    try:
        assert answer(call, name, 'QUERY IND CLASS', 'Charger') == [
            '<http://www.example.org/devices/dock1>']
    finally:
        succeeded(call, name, 'DROP')


def test_get_all_refs_lists_exactly_the_loaded_references(call, load):
    before = set(answer(call, '', 'GET ALL REFS'))
    assert 'robotics' in before
    first, second = load('HERMIT'), load('PELLET')
    assert set(answer(call, '', 'GET ALL REFS')) == before | {first, second}
    succeeded(call, first, 'DROP')
    assert set(answer(call, '', 'GET ALL REFS')) == before | {second}


def test_mount_and_unmount_are_seen_by_get_ref_client(call, load):
    name = load('HERMIT')
    assert answer(call, name, 'GET REF CLIENT') == []  # no argument: the directive's reference
    succeeded(call, name, 'MOUNT', client='planner')
    assert answer(call, '', 'GET REF CLIENT', name) == ['planner']
    assert answer(call, name, 'GET REF CLIENT', client='someone') == ['planner']
    failure(call, name, 'ADD IND CLASS', 'robot2', 'Robot', client='someone', code=102)
    assert answer(call, name, 'QUERY IND CLASS', 'Robot', client='someone') == iris('robot1')
    succeeded(call, name, 'ADD IND CLASS', 'robot3', 'Robot', client='planner')
    succeeded(call, name, 'UNMOUNT', client='planner')
    assert answer(call, '', 'GET REF CLIENT', name) == []
    succeeded(call, name, 'ADD IND CLASS', 'robot2', 'Robot', client='someone')
    assert answer(call, name, 'QUERY IND CLASS', 'Robot') == iris('robot1', 'robot2', 'robot3')


def _wait_for_log(armor_node, marker: str, present: bool, wait_s: float = 5.0) -> bool:
    deadline = time.monotonic() + wait_s
    while time.monotonic() < deadline:
        if (marker in armor_node.log()) == present:
            return True
        time.sleep(0.1)
    return (marker in armor_node.log()) == present


def test_log_screen_on_and_off_need_no_reference(call, armor_node):
    on_marker, off_marker = unique_name('LogScreenOn'), unique_name('LogScreenOff')
    succeeded(call, '', 'LOG SCREEN ON')
    try:
        answer(call, 'robotics', 'QUERY IND CLASS', on_marker)
        assert _wait_for_log(armor_node, on_marker, present=True), (
            'with LOG SCREEN ON the directive does not appear in the node output')
    finally:
        succeeded(call, '', 'LOG SCREEN OFF')
    answer(call, 'robotics', 'QUERY IND CLASS', off_marker)
    time.sleep(1.0)
    assert off_marker not in armor_node.log()


def test_log_file_on_writes_each_directive_until_off(call, armor_node):
    path = armor_node.scratch / f'{unique_name("directives")}.log'
    on_marker, off_marker = unique_name('LogFileOn'), unique_name('LogFileOff')
    succeeded(call, '', 'LOG FILE ON', str(path))
    try:
        answer(call, 'robotics', 'QUERY IND CLASS', on_marker)
    finally:
        succeeded(call, '', 'LOG FILE OFF')
    answer(call, 'robotics', 'QUERY IND CLASS', off_marker)
    text = path.read_text()
    assert on_marker in text and 'QUERY IND CLASS' in text
    assert off_marker not in text


# --- APPLY / REASON and the buffering modes -------------------------------------------------

@pytest.mark.parametrize('reasoner', EXPRESSIVE_REASONERS)
def test_buffered_manipulation_is_invisible_until_apply(call, load, reasoner):
    name = load(reasoner, buffered_manipulation=True, buffered_reasoner=False)
    succeeded(call, name, 'ADD IND CLASS', 'robot2', 'Robot')
    succeeded(call, name, 'REMOVE DATAPROP IND', 'batteryLevel', 'robot1', 'INT', '80')
    succeeded(call, name, 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom')
    # Queries do not see buffered changes, asserted or inferred.
    assert answer(call, name, 'QUERY IND CLASS', 'Robot') == iris('robot1')
    assert answer(call, name, 'QUERY DATAPROP IND', 'batteryLevel', 'robot1') == [
        '"80"^^xsd:integer']
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'isIn', 'alice') == iris('corridor1')
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('kitchen')

    succeeded(call, name, 'APPLY')
    assert answer(call, name, 'QUERY IND CLASS', 'Robot') == iris('robot1', 'robot2')
    assert answer(call, name, 'QUERY DATAPROP IND', 'batteryLevel', 'robot1') == []
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'isIn', 'alice') == iris('bedroom',
                                                                               'corridor1')
    # A non-buffered reasoner sees the applied changes at once.
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('bedroom', 'kitchen')


@pytest.mark.parametrize('reasoner', EXPRESSIVE_REASONERS)
def test_apply_reaches_a_buffered_reasoner_only_at_reason(call, load, reasoner):
    name = load(reasoner, buffered_manipulation=True, buffered_reasoner=True)
    succeeded(call, name, 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom')
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'isIn', 'alice') == iris('corridor1')

    succeeded(call, name, 'APPLY')
    # Applied: the assertion is in the ontology; the buffered reasoner has not seen it yet.
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'isIn', 'alice') == iris('bedroom',
                                                                               'corridor1')
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('kitchen')

    succeeded(call, name, 'REASON')
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('bedroom', 'kitchen')


@pytest.mark.parametrize('reasoner', EXPRESSIVE_REASONERS)
def test_reason_applies_the_buffer_and_updates_the_reasoner(call, load, reasoner):
    name = load(reasoner, buffered_manipulation=True, buffered_reasoner=True)
    succeeded(call, name, 'REPLACE OBJECTPROP IND', 'isIn', 'robot1', 'bedroom', 'kitchen')
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'isIn', 'robot1') == iris('kitchen')
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('kitchen')
    response = succeeded(call, name, 'REASON')
    assert response.is_consistent
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'isIn', 'robot1') == iris('bedroom')
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('bedroom')


@pytest.mark.parametrize('reasoner', EXPRESSIVE_REASONERS)
def test_buffered_reasoner_sees_direct_changes_only_at_reason(call, load, reasoner):
    name = load(reasoner, buffered_manipulation=False, buffered_reasoner=True)
    succeeded(call, name, 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom')
    # Not buffered: the assertion itself answers at once (asserted half of the answer) ...
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'isIn', 'alice') == iris('bedroom',
                                                                               'corridor1')
    # ... but what only the reasoner can conclude waits for REASON.
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('kitchen')
    succeeded(call, name, 'REASON')
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('bedroom', 'kitchen')


@pytest.mark.parametrize('reasoner', EXPRESSIVE_REASONERS)
def test_nothing_buffered_means_inferences_follow_at_once(call, load, reasoner):
    name = load(reasoner, buffered_manipulation=False, buffered_reasoner=False)
    succeeded(call, name, 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom')
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('bedroom', 'kitchen')
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'contains', 'bedroom') == iris('alice')


@pytest.mark.parametrize('reasoner', MAIN_REASONERS)
def test_reason_flushes_the_buffer_also_after_an_inconsistency(call, load, reasoner):
    name = load(reasoner, buffered_manipulation=True, buffered_reasoner=True)
    # corridor1's class Corridor is disjoint with Room: a kitchen that is a Corridor is absurd.
    succeeded(call, name, 'ADD IND CLASS', 'kitchen', 'Corridor')
    succeeded(call, name, 'ADD IND CLASS', 'robot2', 'Robot')
    response = succeeded(call, name, 'REASON')
    assert not response.is_consistent
    assert not succeeded(call, name, 'QUERY CONSISTENCY').is_consistent

    # Already inconsistent: REASON still applies what is queued and reasons again.
    succeeded(call, name, 'REMOVE IND CLASS', 'kitchen', 'Corridor')
    response = succeeded(call, name, 'REASON')
    assert response.is_consistent
    assert answer(call, name, 'QUERY IND CLASS', 'Corridor') == iris('corridor1')
    assert answer(call, name, 'QUERY IND CLASS', 'Robot') == iris('robot1', 'robot2')


@pytest.mark.parametrize('reasoner', EXPRESSIVE_REASONERS)
def test_reason_retracts_what_several_removed_assertions_implied(call, load, reasoner):
    name = load(reasoner, buffered_manipulation=False, buffered_reasoner=True)
    succeeded(call, name, 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom')
    succeeded(call, name, 'REASON')
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('bedroom', 'kitchen')
    # Both rooms lose their only occupant within one REASON.
    succeeded(call, name, 'REMOVE OBJECTPROP IND', 'isIn', 'alice', 'bedroom')
    succeeded(call, name, 'REMOVE OBJECTPROP IND', 'isIn', 'robot1', 'kitchen')
    succeeded(call, name, 'REASON')
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'contains', 'kitchen') == []
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == []


@pytest.mark.parametrize('reasoner', EXPRESSIVE_REASONERS)
def test_reason_accepts_assertions_with_properties_new_to_the_ontology(call, load, reasoner):
    name = load(reasoner, buffered_manipulation=False, buffered_reasoner=True)
    succeeded(call, name, 'ADD OBJECTPROP IND', 'near', 'kitchen', 'bedroom')
    succeeded(call, name, 'ADD DATAPROP IND', 'reading', 'robot1', 'INT', '7')
    assert succeeded(call, name, 'REASON').is_consistent
    succeeded(call, name, 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom')
    succeeded(call, name, 'REASON')
    assert answer(call, name, 'QUERY IND CLASS', 'OccupiedRoom') == iris('bedroom', 'kitchen')
    assert answer(call, name, 'QUERY OBJECTPROP IND', 'near', 'kitchen') == iris('bedroom')


def test_apply_and_reason_without_a_buffer_change_nothing(call, load):
    name = load('HERMIT')
    assert answer(call, name, 'APPLY') == []
    assert succeeded(call, name, 'REASON').is_consistent
    assert answer(call, name, 'QUERY IND CLASS', 'Robot') == iris('robot1')
    assert iri('robot1') in answer(call, name, 'QUERY IND CLASS', 'Agent')
