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
