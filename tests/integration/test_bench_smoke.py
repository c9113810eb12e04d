# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The benchmark suite still runs: `bench/suite.py --scale smoke` writes a complete report.

Tiny sizes and few calls, so it proves that every benchmark, the in-process Java harness, the
profiler and the report writer work, not that any target is met (`make bench` measures). It
does prove the answers behind the figures right: the suite fails on a wrong one (bench/answers.py),
including a room the reasoning cycle's agents left that is still answered as occupied.
Without owlready2 (make bench installs it, make setup does not) its rows say so.
"""

import json
import os
import pathlib
import re
import subprocess
import sys

from conftest import release_domain, reserve_domain
import pytest

pytestmark = pytest.mark.runs_for_minutes(6)

REPO = pathlib.Path(__file__).resolve().parents[2]
SECTIONS = ('## Summary', '## Machine and versions', '## 1. Transport overhead',
            '## 2. Batch throughput', '## 3. Reasoning under updates', '## 4. Memory',
            '## 5. Profile', '## 6. SPARQL on LUBM', '## 7. Reasoning at robot speed (issue 15)',
            '## 9. The ontologies robots really use (issue 28)')
FIGURE = re.compile(r'\|\s*[\d,]+(\.\d+)?\s*(ms|s|/s|MiB|%|x)?\s*\|')


def _sections(report: str) -> dict:
    """Section heading -> its text, for the headings in SECTIONS."""
    positions = sorted((report.index(heading), heading) for heading in SECTIONS)
    ends = [start for start, _ in positions[1:]] + [len(report)]
    return {heading: report[start:end] for (start, heading), end in zip(positions, ends)}


def test_smoke_run_writes_every_section_with_figures(tmp_path):
    report_path = tmp_path / 'REPORT.md'
    # A DDS domain of its own (reserved as the session's is), so that the suite's nodes never
    # meet this run's nodes, another run's or a user's.
    domain = reserve_domain()
    env = {**os.environ, 'ROS_DOMAIN_ID': domain}
    completed = subprocess.run(
        [sys.executable, str(REPO / 'bench' / 'suite.py'), '--scale', 'smoke', '--report',
         str(report_path)], env=env, capture_output=True, text=True, timeout=840)
    release_domain(domain)
    assert completed.returncode == 0, completed.stderr[-4000:]
    assert 'every checked answer was right' in completed.stderr
    report = report_path.read_text()
    for heading in SECTIONS:
        assert heading in report, f'{heading} missing from the report'
    for heading, text in _sections(report).items():
        assert FIGURE.search(text), f'no figure in section {heading}:\n{text[:1500]}'
    summary = _sections(report)['## Summary']
    for benchmark in ('1. transport', '2. batch', '3. reasoning cycle', '4. peak memory',
                      '6. LUBM 14-query mean over ROS 2',
                      '6. first query after a one-fact change'):
        assert benchmark in summary, f'{benchmark} missing from the summary'
    assert '**Slowest part of the service:**' in summary
    shapes = _sections(report)['## 9. The ontologies robots really use (issue 28)']
    assert 'wrong**' not in shapes, f'a wrong answer in the real shapes:\n{shapes}'
    for shape in ('(a) robotics', '(b) part-of map', '(d) part-of map, functional, hasValue'):
        assert any(line.startswith(f'| {shape} |') and '| yes |' in line
                   for line in shapes.splitlines()), f'{shape} has no checked cycles:\n{shapes}'
    assert '**Default for the robot\'s cycle:**' in summary


def test_the_pddl_bridge_bench_runs(tmp_path):
    """bench/pddl_bridge.py on a small building: every figure there, the plan valid."""
    domain = reserve_domain()
    env = {**os.environ, 'ROS_DOMAIN_ID': domain}
    completed = subprocess.run(
        [sys.executable, str(REPO / 'bench' / 'pddl_bridge.py'), '--objects', '60', '--runs', '1',
         '--json'], env=env, capture_output=True, text=True, timeout=600)
    release_domain(domain)
    assert completed.returncode == 0, completed.stderr[-4000:]
    result = json.loads(completed.stdout)
    assert result['problem']['objects'] == result['building']['objects'] == 52
    assert result['problem']['goal facts'] == 1 + result['building']['alarmed rooms']
    assert result['generation']['median_s'] > 0 and result['by_hand']['calls'] > 100
    assert result['planner']['valid'] and result['planner']['plan_length'] > 2


def test_the_scenes_bench_runs():
    """bench/scenes.py --smoke: the plugin in the core and the service over ROS 2, side by side."""
    domain = reserve_domain()
    env = {**os.environ, 'ROS_DOMAIN_ID': domain}
    completed = subprocess.run(
        [sys.executable, str(REPO / 'bench' / 'scenes.py'), '--smoke', '--json'], env=env,
        capture_output=True, text=True, timeout=900, cwd=REPO / 'bench')
    release_domain(domain)
    assert completed.returncode == 0, completed.stderr[-4000:]
    results = json.loads(completed.stdout)
    [core], [ros] = results['core'], results['ros']
    for row in (core, ros):
        assert 'failed' not in row, row
        assert row['recognition']['p50_ms'] > 0 and row['learning']['p50_ms'] > 0, row
