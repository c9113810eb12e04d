# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The armor verbs beyond call, run as separate processes against the live node."""

import subprocess
import sys

from conftest import ONTOLOGIES


def armor_cli(*words, stdin=None, cwd=None):
    return subprocess.run([sys.executable, '-m', 'armor_client.cli', *words], input=stdin,
                          capture_output=True, text=True, timeout=120, cwd=cwd)


def test_load_query_save_and_refs(armor, armor_node):
    loaded = armor_cli('load', 'cli_map', 'robotics.owl', '--reasoner', 'PELLET',
                       cwd=ONTOLOGIES)
    assert loaded.returncode == 0, loaded.stderr
    assert loaded.stdout.strip() == 'loaded robotics.owl as cli_map (consistent)'
    instances = armor_cli('query', 'cli_map', 'IND', 'CLASS', 'Room')
    assert instances.stdout.splitlines() == ['individual', '----------', 'bedroom', 'kitchen',
                                             '(2 rows)']
    values = armor_cli('query', 'cli_map', 'DATAPROP', 'IND', '--', 'batteryLevel', 'robot1')
    assert values.stdout.splitlines()[2].split() == ['80', 'xsd:integer']
    saved = armor_cli('save', 'cli_map', 'cli_map.ttl', '--format', 'turtle',
                      cwd=armor_node.scratch)
    assert saved.returncode == 0, saved.stderr
    assert '@prefix' in (armor_node.scratch / 'cli_map.ttl').read_text()
    refs = armor_cli('refs')
    assert ['cli_map', '-'] in [line.split() for line in refs.stdout.splitlines()]
    assert armor_cli('call', 'cli_map', 'DROP').returncode == 0


def test_sparql_tables_and_failures(armor):
    rows = armor_cli('sparql', 'robotics', '-',
                     stdin='SELECT ?who ?where WHERE { ?who :isIn ?where } ORDER BY ?who')
    assert rows.returncode == 0, rows.stderr
    assert [line.split() for line in rows.stdout.splitlines()] == [
        ['who', 'where'], ['------', '---------'], ['alice', 'corridor1'],
        ['robot1', 'kitchen'], ['(2', 'rows)']]
    as_iris = armor_cli('query', 'robotics', 'IND', 'CLASS', 'Robot', '--iri')
    assert '<http://www.example.org/robotics#robot1>' not in as_iris.stdout
    assert 'http://www.example.org/robotics#robot1' in as_iris.stdout
    unknown = armor_cli('query', 'nowhere', 'IND', 'CLASS', 'Room')
    assert unknown.returncode == 1 and unknown.stderr.startswith('error 206:')
    malformed = armor_cli('sparql', 'robotics', 'SELECT ?x WHERE {')
    assert malformed.returncode == 1 and 'error 208' in malformed.stderr


def test_shell_runs_a_script_from_stdin(armor):
    script = '\n'.join([
        'help QUERY IND CLASS',
        'QUERY IND CLASS OccupiedRoom',
        'ADD OBJECTPROP IND isIn carol bedroom',
        'ADD IND CLASS carol Person',
        'query ind class OccupiedRoom',
        'REMOVE IND carol',
        'names',
        'use nowhere',
        'QUERY IND CLASS Room',
        'FLY AWAY',
        'quit',
        'QUERY IND CLASS Room',
    ]) + '\n'
    shell = armor_cli('shell', 'robotics', stdin=script)
    assert shell.returncode == 0, shell.stderr
    lines = shell.stdout.splitlines()
    assert lines[0].split()[:3] == ['QUERY', 'IND', 'CLASS']
    assert lines[1:5] == ['individual', '----------', 'kitchen', '(1 row)']
    # carol is new to the reference: said once, when she first appears (issue 11 item 7).
    assert lines[5:8] == ["note: new to the reference: individual 'carol'", 'ok (consistent)',
                          'ok (consistent)']
    assert lines[8:13] == ['individual', '----------', 'bedroom', 'kitchen', '(2 rows)']
    assert lines[13] == 'ok (consistent)' and lines[14].endswith(' names')
    # use of a reference that is not loaded fails at once and keeps the current one (item 13).
    assert lines[15].startswith("error: no reference named 'nowhere' is loaded")
    assert lines[16:21] == ['individual', '----------', 'bedroom', 'kitchen', '(2 rows)']
    # The node names what it does not know, with the closest commands (issue 35 item 3).
    assert lines[21].startswith("error 205: unknown command 'FLY AWAY'") and len(lines) == 22
