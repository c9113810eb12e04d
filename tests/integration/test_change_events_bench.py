# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""bench/change_events.py still runs (`--smoke`: tiny sizes), and its invariants hold there.

Timings at this size prove nothing (the full run measures them); the counts do: no revision
lost or duplicated, the subscription's answer equal to the query's, no answer topic left.
"""

import json
import os
import pathlib
import subprocess
import sys

from conftest import release_domain, reserve_domain
import pytest

pytestmark = pytest.mark.runs_for_minutes(2)

REPO = pathlib.Path(__file__).resolve().parents[2]


def test_the_smoke_run_prints_every_figure_and_loses_nothing(tmp_path):
    figures = tmp_path / 'figures.json'
    domain = reserve_domain()
    try:
        completed = subprocess.run(
            [sys.executable, str(REPO / 'bench' / 'change_events.py'), '--smoke', '--json',
             str(figures)], env={**os.environ, 'ROS_DOMAIN_ID': domain}, capture_output=True,
            text=True, timeout=900)
    finally:
        release_domain(domain)
    assert completed.returncode == 0, completed.stderr[-4000:]
    for heading in ('1. change acknowledged -> notification received', '2. over',
                    '3. change round trip', '4. resident memory'):
        assert heading in completed.stdout, completed.stdout
    results = json.loads(figures.read_text())
    assert {row['reasoner'] for row in results['latency']} == {'ELK', 'HERMIT'}
    assert all(row['inferred_answer']['p50_ms'] > 0 for row in results['latency'])
    counts = results['completeness']
    assert counts['acknowledged_changes'] > 150 and counts['failed_lists'] > 0, counts
    assert (counts['lost'], counts['duplicated'], counts['unexpected']) == (0, 0, 0), counts
    assert counts['subscription_answer_agrees'], counts
    assert results['leaks']['answer_topics_left'] == 0, results['leaks']
