# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Issue 35 item 1: a relative path is the caller's, made absolute before any directive leaves."""

import os

from armor_client.commands import find
from armor_client.paths import absolute, absolute_args
from armor_client.planning import mapping_argument
from armor_client.transport import directive


def test_relative_paths_are_joined_to_the_caller_directory_and_the_rest_left_alone():
    assert absolute('maps/home.owl', '/work') == '/work/maps/home.owl'
    assert absolute('../x.owl', '/work/a') == '/work/a/../x.owl'  # ".." is the node's to apply
    assert absolute('/abs/x.owl', '/work') == '/abs/x.owl'
    assert absolute('', '/work') == ''
    assert absolute('domain: d\ntypes: {}', '/work') == 'domain: d\ntypes: {}'
    assert absolute('{"domain": "d"}', '/work') == '{"domain": "d"}'


def test_the_catalogue_says_which_arguments_are_paths():
    assert find('LOAD', 'FILE').path_positions == (0,)
    assert find('SAVE').path_positions == (0,)
    assert find('LOG', 'FILE', 'ON').path_positions == (0,)
    assert find('QUERY', 'IND', 'CLASS').path_positions == ()
    save = find('SAVE', 'INFERENCE')
    assert absolute_args(save, ['out.owl', 'turtle'], '/w') == ['/w/out.owl', 'turtle']
    assert absolute_args(None, ['out.owl'], '/w') == ['out.owl']


def test_every_directive_built_here_sends_absolute_paths(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    load = directive('c', 'r', 'LOAD', 'FILE', '', ['home.owl', '', 'false', '', 'false'])
    assert load.args[0] == os.path.join(str(tmp_path), 'home.owl')
    assert load.args[1:] == ['', 'false', '', 'false']
    assert directive('c', 'r', 'save', '-', '', ['x.ttl']).args == [str(tmp_path / 'x.ttl')]
    assert directive('c', 'r', 'SAVE', '', '', ['x.ttl'], cwd='/elsewhere').args == [
        '/elsewhere/x.ttl']
    query = directive('c', 'r', 'QUERY', 'IND', 'CLASS', ['home.owl'])
    assert query.args == ['home.owl']
    assert mapping_argument('mapping.yaml') == str(tmp_path / 'mapping.yaml')
    assert mapping_argument({'domain': 'd'}) == '{"domain": "d"}'
