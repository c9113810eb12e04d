# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""examples/surveillance_demo.py as a user runs it: a separate process, a few steps."""

import subprocess
import sys

from armor_client import Armor
from conftest import REPO


def test_the_demo_prints_beliefs_and_decisions(armor):
    result = subprocess.run(
        [sys.executable, str(REPO / 'examples' / 'surveillance_demo.py'), '--steps', '3',
         '--reference', 'examples_test'], capture_output=True, text=True, timeout=180)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0].startswith('Loading surveillance.owl as "examples_test"')
    assert [line.split()[:6] for line in lines[1:4]] == [
        ['t=100s', 'in', 'E', 'battery', '100%', 'urgent:'],
        ['t=110s', 'in', 'C1', 'battery', '90%', 'urgent:'],
        ['t=120s', 'in', 'R1', 'battery', '80%', 'urgent:']]
    assert lines[2].endswith('-> R1 (urgent, unvisited for 80 s)')
    assert lines[4] == 'Done. Inspect what the robot left behind: armor shell examples_test'
    Armor('examples_test', transport=armor).reference('examples_test').drop()
