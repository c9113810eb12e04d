# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The default reasoner loads what users bring, and a refusal names one that accepts it
(issue 11 item 4): the repository's own surveillance.owl uses SWRL built-ins."""

from conftest import ONTOLOGIES

SURVEILLANCE = str(ONTOLOGIES / 'surveillance.owl')


def test_the_default_reasoner_loads_the_surveillance_ontology(call):
    loaded = call('default_loads', 'LOAD FILE', SURVEILLANCE, '', 'false', '', 'false')
    try:
        assert loaded.success, f'{loaded.exit_code} {loaded.error_description}'
        rooms = call('default_loads', 'QUERY IND CLASS', 'Room')
        assert rooms.success and len(rooms.queried_objects) == 4, rooms.queried_objects
    finally:
        call('default_loads', 'DROP')


def test_a_refusing_reasoner_names_one_that_accepts_the_ontology(call):
    refused = call('hermit_refuses', 'LOAD FILE', SURVEILLANCE, '', 'false', 'HERMIT', 'false')
    assert not refused.success and refused.exit_code == 210, refused.error_description
    assert 'built-in atom' in refused.error_description
    assert 'PELLET accepts this ontology' in refused.error_description, refused.error_description
    assert call('hermit_refuses', 'QUERY IND CLASS', 'Room').exit_code == 206
