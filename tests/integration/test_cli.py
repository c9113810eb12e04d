# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""`armor call` from another process prints the answer and reports failure in its status."""

import json
import shutil
import signal
import subprocess
import sys

from armor_client import Armor
from conftest import iri, REPO
import pytest


def armor_cli(*words):
    return subprocess.run([sys.executable, '-m', 'armor_client.cli', *words],
                          capture_output=True, text=True, timeout=120)


def test_call_prints_the_answer(armor):
    result = armor_cli('call', 'robotics', 'QUERY', 'IND', 'CLASS', '--', 'Robot')
    assert result.returncode == 0, result.stderr
    assert iri('robot1') in result.stdout.splitlines()


def test_call_fails_with_the_code_on_stderr(armor):
    result = armor_cli('call', 'nowhere', 'QUERY', 'IND', 'CLASS', '--', 'Robot')
    assert result.returncode == 1
    assert 'error 206' in result.stderr


def test_call_without_reference_and_json_output(armor):
    result = armor_cli('call', '--json', '-', 'GET', 'ALL', 'REFS')
    assert result.returncode == 0, result.stderr
    assert '"robotics"' in result.stdout


def test_serve_is_a_verb_registered_by_the_service_package(tmp_path):
    import importlib.metadata
    import signal
    from conftest import ONTOLOGIES
    owners = {point.name: point.value for point in
              importlib.metadata.entry_points(group='armor.verbs')}
    assert owners['serve'].startswith('armor_service.') and owners['call'].startswith('armor_client.')
    node = subprocess.Popen(
        [sys.executable, '-m', 'armor_client.cli', 'serve', '--ros-args',
         '-p', f'preload_file:={ONTOLOGIES / "robotics.owl"}', '-p', 'preload_reference:=served',
         '-p', f'allowed_dirs:={ONTOLOGIES}', '-p', f'state_dir:={tmp_path / "state"}',
         '-r', '__ns:=/served'], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        result = armor_cli('call', '--namespace', '/served', '--wait', '90', '-', 'GET', 'ALL', 'REFS')
        assert result.returncode == 0, result.stderr
        assert result.stdout.splitlines()[-1] == 'served'
    finally:
        node.send_signal(signal.SIGINT)
        node.wait(timeout=30)


# ------------------------------------------------------------------ issue 35, items 2, 3 and 7

@pytest.fixture
def mapping(armor_node):
    """The robotics mapping of the planner bridge, where the session's node may read it."""
    return shutil.copy(REPO / 'examples' / 'pddl' / 'robotics-mapping.yaml', armor_node.scratch)


def test_output_cut_short_by_its_reader_ends_without_a_traceback(armor):
    # The reader is gone before anything is written: as `armor call ... | head` at its end.
    process = subprocess.Popen([sys.executable, '-m', 'armor_client.cli', 'call', '-', 'GET',
                                'CATALOGUE'], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    process.stdout.close()
    _, errors = process.communicate(timeout=120)
    assert process.returncode == 128 + signal.SIGPIPE, errors.decode()
    assert errors.decode() == ''


def test_raw_output_is_the_answer_alone_and_a_document_is_printed_as_text(armor, mapping):
    problem = Armor('cli_test', transport=armor).reference('robotics').pddl_problem(mapping)
    raw = armor_cli('call', 'robotics', 'QUERY', 'PDDL', 'PROBLEM', '--raw', '--', mapping)
    assert raw.returncode == 0, raw.stderr
    assert raw.stdout == problem  # saved as a file, it is the problem as answered
    shown = armor_cli('query', 'robotics', 'PDDL', 'PROBLEM', mapping)
    assert shown.returncode == 0, shown.stderr
    assert shown.stdout == problem.rstrip('\n') + '\n'  # no table, no rule under it
    catalogue = armor_cli('call', '-', 'GET', 'CATALOGUE')
    header, *indented = catalogue.stdout.splitlines()
    assert header.startswith('# exit_code 0')
    assert len(indented) > 100 and indented[1].startswith('  "')
    assert 'QUERY PDDL PROBLEM' in {entry['key'].replace(' -', '') for entry in
                                    json.loads('\n'.join(indented))['commands']}


def test_exit_statuses_tell_a_usage_error_from_no_service(armor):
    assert armor_cli('call').returncode == 2
    assert armor_cli('query', 'robotics', 'ADD', 'IND', 'CLASS', 'x', 'Robot').returncode == 2
    nobody = armor_cli('refs', '--namespace', '/nobody_here', '--wait', '2')
    assert nobody.returncode == 3, nobody.stderr


def test_a_misspelt_spec_is_answered_with_the_closest_commands(armor):
    for words in (['query', 'robotics', 'IND', 'CLAS', 'Room'],
                  ['call', 'robotics', 'QUERY', 'IND', 'CLAS', '--', 'Room']):
        answer = armor_cli(*words)
        assert answer.returncode == 1, answer.stdout
        assert 'error 205' in answer.stderr and 'closest: QUERY IND CLASS (class)' in answer.stderr
    shell = subprocess.run([sys.executable, '-m', 'armor_client.cli', 'shell', 'robotics'],
                           input='QUERY IND CLAS Room\n', capture_output=True, text=True,
                           timeout=120)
    assert shell.stdout.startswith("error 205: unknown command 'QUERY IND CLAS'"), shell.stdout
    assert 'closest: QUERY IND CLASS (class)' in shell.stdout


def test_a_class_expression_names_the_words_the_reference_does_not_know(armor):
    typo = armor_cli('query', 'robotics', 'IND', 'DL', 'Agent and (isIn some Rom)')
    assert typo.returncode == 0, typo.stderr
    assert "note: new to the reference: class 'Rom' (did you mean Room?)" in typo.stderr
    assert '(0 rows)' in typo.stdout
    unknown = armor_cli('query', 'robotics', 'IND', 'DL', 'Agent and (isInn some Room)')
    assert unknown.returncode == 1
    assert "does not know object property 'isInn' (did you mean isIn?)" in unknown.stderr
