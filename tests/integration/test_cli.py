# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""`armor call` from another process prints the answer and reports failure in its status."""

import subprocess
import sys

from conftest import iri


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
