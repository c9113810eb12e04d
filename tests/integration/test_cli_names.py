# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Typos at the command line (issue 11 items 6 and 7): a misspelt spec answers 205 with the
combinations meant, a name new to the reference is noted, and strict_names makes a query of
an unknown name an error."""

import subprocess
import sys

from conftest import start_node


def armor_cli(*words, namespace=''):
    extra = ['--namespace', namespace] if namespace else []
    return subprocess.run([sys.executable, '-m', 'armor_client.cli', words[0], *extra, *words[1:]],
                          capture_output=True, text=True, timeout=120)


def test_a_misspelt_spec_with_arguments_answers_205_with_the_closest(armor):
    result = armor_cli('call', 'robotics', 'QUERY', 'IND', 'CLASSS', '--', 'Room')
    assert result.returncode == 1, result.stdout + result.stderr
    assert 'error 205' in result.stderr and 'closest: QUERY IND CLASS (class)' in result.stderr, \
        result.stderr


def test_a_name_new_to_the_reference_is_noted_on_stderr(armor):
    result = armor_cli('call', 'robotics', 'QUERY', 'IND', 'CLASS', '--', 'Rooom')
    assert result.returncode == 0, result.stderr
    assert "note: new to the reference: class 'Rooom' (did you mean Room?)" in result.stderr, \
        result.stderr
    query = armor_cli('query', 'robotics', 'IND', 'CLASS', 'Rooom')
    assert query.returncode == 0 and '(0 rows)' in query.stdout, query.stdout + query.stderr
    assert "did you mean Room?" in query.stderr, query.stderr


def test_strict_names_makes_a_query_of_an_unknown_name_an_error(tmp_path):
    node = start_node(tmp_path, '-p', 'strict_names:=true', namespace='/strict')
    try:
        refused = armor_cli('call', 'robotics', 'QUERY', 'IND', 'CLASS', '--wait', '120', '--',
                            'Rooom', namespace='/strict')
        created = armor_cli('call', 'robotics', 'ADD', 'IND', 'CLASS', '--', 'dave', 'Person',
                            namespace='/strict')
    finally:
        node.stop()
    assert refused.returncode == 1, refused.stdout + refused.stderr + node.log()
    assert 'error 224' in refused.stderr and 'did you mean Room?' in refused.stderr, refused.stderr
    assert created.returncode == 0, created.stderr
    assert "individual 'dave'" in created.stderr, created.stderr
