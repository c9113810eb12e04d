# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ROS 1 armor_api's ArmorClient against the live node: every method, old names, old answers.

Answers are ARMOR's strings, as armor_api returned them; the bugs armor_api had are fixed
(docs/porting-from-ros1.md lists them).
"""

import pathlib
import re

from armor_client.armor_api import ArmorClient
from armor_client.armor_api.armor_exceptions import (ArmorPyException, ArmorServiceCallError,
                                                     ArmorServiceInternalError)
from conftest import iri, iris, NS, ONTOLOGIES
import pytest

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')


@pytest.fixture
def client(armor, request):
    """An ArmorClient on a fresh copy of robotics.owl (Pellet, armor_api's default)."""
    name = 'compat_' + re.sub(r'\W', '_', request.node.name)
    old = ArmorClient('compat_test', name, timeout=90, call_timeout=120)
    old.utils.load_ref_from_file(ROBOTICS, '')
    yield old
    old.call('DROP', '', '', [])
    old.close()


def test_queries_return_armors_strings(client):
    assert client.query.ind_b2_class('Room') == iris('bedroom', 'kitchen')
    assert client.query.dataprop_b2_ind('batteryLevel', 'robot1') == ['"80"^^xsd:integer']
    assert client.query.objectprop_b2_ind('isIn', 'robot1') == [iri('kitchen')]


def test_check_ind_exists_whatever_the_individuals_classes(client):
    # armor_api answered False for these two: it wanted more than one class.
    assert client.call('ADD', 'IND', '', ['lonely']).success
    client.manipulation.add_ind_to_class('spot', 'Location')
    assert client.query.check_ind_exists('lonely')
    assert client.query.check_ind_exists('spot')
    assert client.query.check_ind_exists(iri('robot1'))
    assert client.query.check_ind_exists(f'{NS}robot1')
    assert not client.query.check_ind_exists('ghost')


def test_manipulations_return_consistency(client):
    manipulation = client.manipulation
    assert manipulation.add_ind_to_class('bob', 'Person') is True
    assert manipulation.add_objectprop_to_ind('isIn', 'bob', 'bedroom') is True
    assert client.query.ind_b2_class('OccupiedRoom') == iris('bedroom', 'kitchen')
    assert manipulation.replace_objectprop_b2_ind('isIn', 'bob', 'kitchen', 'bedroom')
    assert client.query.objectprop_b2_ind('isIn', 'bob') == [iri('kitchen')]
    assert manipulation.remove_objectprop_from_ind('isIn', 'bob', 'kitchen')
    assert client.query.objectprop_b2_ind('isIn', 'bob') == []
    assert manipulation.add_dataprop_to_ind('batteryLevel', 'robot1', 'INTEGER', 80) is True
    assert manipulation.replace_dataprop_b2_ind('batteryLevel', 'robot1', 'INTEGER', 60, 80)
    assert client.query.dataprop_b2_ind('batteryLevel', 'robot1') == ['"60"^^xsd:integer']
    assert manipulation.remove_dataprop_from_ind('batteryLevel', 'robot1', 'INTEGER', '60')
    assert client.query.dataprop_b2_ind('batteryLevel', 'robot1') == []
    assert manipulation.remove_ind_from_class('bob', 'Person')
    assert client.query.ind_b2_class('Person') == [iri('alice')]


def test_replace_one_sets_single_values(client):
    manipulation = client.manipulation
    assert manipulation.replace_one_dataprop_b2_ind('batteryLevel', 'robot1', 'INTEGER', '55')
    assert client.query.dataprop_b2_ind('batteryLevel', 'robot1') == ['"55"^^xsd:integer']
    assert manipulation.replace_one_dataprop_b2_ind('visitedAt', 'kitchen', 'LONG', '17')
    assert client.query.dataprop_b2_ind('visitedAt', 'kitchen') == ['"17"^^xsd:long']
    assert manipulation.replace_one_objectprop_b2_ind('isIn', 'robot1', 'bedroom')
    assert client.query.objectprop_b2_ind('isIn', 'robot1') == [iri('bedroom')]
    assert manipulation.replace_one_objectprop_b2_ind('isIn', 'carl', 'kitchen')
    assert client.query.objectprop_b2_ind('isIn', 'carl') == [iri('kitchen')]
    manipulation.add_objectprop_to_ind('isIn', 'carl', 'bedroom')
    with pytest.raises(ArmorServiceInternalError) as several:
        manipulation.replace_one_objectprop_b2_ind('isIn', 'carl', 'corridor1')
    assert several.value.code is None and '2 values' in several.value.msg


def test_batches_are_atomic_and_in_the_right_order(client):
    manipulation = client.manipulation
    assert manipulation.add_batch_dataprop_to_ind(
        'robot1', [['batteryLevel', 'INTEGER', '70'], ['visitedAt', 'LONG', '5']])
    assert client.query.dataprop_b2_ind('batteryLevel', 'robot1') == [
        '"70"^^xsd:integer', '"80"^^xsd:integer']
    with pytest.raises(ArmorServiceInternalError) as refused:
        manipulation.add_batch_dataprop_to_ind(
            'robot1', [['batteryLevel', 'INTEGER', '90'], ['batteryLevel', 'INTEGER', 'high']])
    assert refused.value.code == 101
    assert '"90"^^xsd:integer' not in client.query.dataprop_b2_ind('batteryLevel', 'robot1')
    assert manipulation.remove_batch_dataprop_to_ind(
        'robot1', [['batteryLevel', 'INTEGER', '70'], ['visitedAt', 'LONG', '5']])
    assert client.query.dataprop_b2_ind('batteryLevel', 'robot1') == ['"80"^^xsd:integer']
    assert client.query.dataprop_b2_ind('visitedAt', 'robot1') == []


def test_disjoint_individuals(client):
    manipulation = client.manipulation
    assert manipulation.disj_inds(['kitchen', 'bedroom'])
    manipulation.add_ind_to_class('r1', 'Room')
    assert manipulation.disj_inds_of_class('Room')
    response = client.call('ADD', 'IND', 'SAME', ['r1', 'kitchen'])
    assert response.success and not response.is_consistent


def test_mounts_buffers_and_errors(client):
    other = ArmorClient('someone_else', client.reference_name, timeout=90)
    try:
        client.utils.mount_on_ref()
        with pytest.raises(ArmorServiceInternalError) as busy:
            other.manipulation.add_ind_to_class('eve', 'Person')
        assert busy.value.code == 102 and isinstance(busy.value, ArmorPyException)
        client.utils.unmount_from_ref()
        with pytest.raises(ArmorServiceInternalError) as not_held:
            other.utils.unmount_from_ref()
        assert not_held.value.code == 203
    finally:
        other.close()
    assert client.utils.apply_buffered_changes() is True
    assert client.utils.sync_buffered_reasoner() is True


def test_load_mounted_buffered(armor):
    old = ArmorClient('compat_test', 'compat_buffered', timeout=90)
    try:
        old.utils.load_ref_from_file(ROBOTICS, 'http://www.example.org/robotics', True,
                                     'HERMIT', True, mounted=True)
        assert old.call('GET', 'REF', 'CLIENT', ['compat_buffered']).queried_objects == [
            'compat_test']
        old.manipulation.add_ind_to_class('bob', 'Person')
        assert old.query.ind_b2_class('Person') == [iri('alice')]
        old.utils.sync_buffered_reasoner()
        assert old.query.ind_b2_class('Person') == iris('alice', 'bob')
        old.utils.unmount_from_ref()
    finally:
        old.call('DROP', '', '', [])
        old.close()


def test_save_and_logs(client, armor_node):
    scratch = pathlib.Path(armor_node.scratch)
    client.manipulation.add_ind_to_class('bob', 'Person')
    client.utils.save(str(scratch / 'compat.owl'))
    client.utils.save_ref_with_inferences(str(scratch / 'compat_inferred.owl'))
    assert 'robotics#bob' in (scratch / 'compat.owl').read_text()
    assert 'RobotInRoom' in (scratch / 'compat_inferred.owl').read_text().split(
        'robotics#robot1">', 1)[1]
    client.utils.set_log_to_file(True, str(scratch / 'compat.log'))
    client.query.ind_b2_class('Room')
    client.utils.set_log_to_file(False)
    assert 'QUERY' in (scratch / 'compat.log').read_text()
    with pytest.raises(ArmorServiceCallError):
        client.utils.set_log_to_file(True)
    client.utils.set_log_to_terminal(True)
    client.utils.set_log_to_terminal(False)
    with pytest.raises(ArmorServiceInternalError) as bad_path:
        client.utils.save('/proc/compat.owl')
    assert bad_path.value.code == 213


def test_service_names_and_unreachable_services(armor):
    namespaced = ArmorClient('compat_test', 'robotics', '/robot9/armor_interface_srv',
                             '/robot9/armor_interface_serialized_srv', timeout=1)
    try:
        with pytest.raises(ArmorServiceCallError):
            namespaced.query.ind_b2_class('Room')
    finally:
        namespaced.close()
    with pytest.raises(ValueError):
        ArmorClient('compat_test', 'robotics', '/my_armor_srv')
    raw = ArmorClient('compat_test', 'nowhere', timeout=90)
    try:
        response = raw.call('QUERY', 'IND', 'CLASS', ['Room'])
        assert not response.success and response.exit_code == 206
        with pytest.raises(ArmorServiceInternalError) as unknown:
            raw.query.ind_b2_class('Room')
        assert unknown.value.code == 206 and 'nowhere' in unknown.value.msg
    finally:
        raw.close()
