# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""examples/surveillance_demo.py as a user runs it: a separate process, a few steps."""

import re
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


def test_the_demo_plans_with_a_real_planner(armor):
    result = subprocess.run(
        [sys.executable, str(REPO / 'examples' / 'surveillance_demo.py'), '--steps', '2',
         '--plan', '--reference', 'examples_plan_test'], capture_output=True, text=True,
        timeout=300)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[1] == ('Planning: surveillance-mapping.yaml for surveillance-domain.pddl; each '
                        'step follows the first action of a new plan.')
    # From E the shortest plans to R1 and R3 and back go either way round.
    assert lines[2].split('-> ')[1] in (
        'C1 (plan: C1 R1 C1 C2 R3 C2 E recharge)  | rules: C1 (no urgent room in reach: '
        'corridor visited longest ago)',
        'C2 (plan: C2 R3 C2 C1 R1 C1 E recharge)  | rules: C1 (no urgent room in reach: '
        'corridor visited longest ago)'), lines[2]
    assert lines[3].startswith('t=110s  in C')
    Armor('examples_test', transport=armor).reference('examples_plan_test').drop()


def test_the_python_guide_example_prints_what_its_comments_say_on_every_run(armor, armor_node):
    """Issue 35 item 5: run twice, as a user re-running it does; the reference it left behind
    must not change what the second run prints."""
    text = (REPO / 'docs' / 'python-client.md').read_text()
    example = re.search(r'## A complete example\n\n```python\n(.*?)```', text, re.DOTALL).group(1)
    # Each print whose comment is a whole answer ('...' marks an answer shown in part).
    promised = [comment.strip() for comment in re.findall(r'^\s*print\(.*\)\s+# (.*)$', example,
                                                          re.MULTILINE) if '...' not in comment]
    assert len(promised) >= 5, promised
    # The session's node writes only in its scratch folder.
    saved = "os.path.expanduser('~/armor_files/home.ttl')"
    assert saved in example, 'the guide saves into the default write_dirs'
    example = example.replace(saved, repr(str(armor_node.scratch / 'home.ttl')))
    for run in (1, 2):
        result = subprocess.run([sys.executable, '-c', example], cwd=REPO, capture_output=True,
                                text=True, timeout=300)
        assert result.returncode == 0, (run, result.stderr)
        printed = result.stdout.splitlines()
        shown = [line for line in printed if line in promised]
        assert shown == promised, (run, printed)
    Armor('examples_test', transport=armor).reference('home').drop()
