# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""bench/web_view.py still runs: a few changes, a short soak and short phases, every figure.

It proves the benchmark works end to end (a node, a real browser, the in-page stamps, the
heap sampling), not that a target is met: the full run measures (docs/web-view.md).
"""

import json
import os
import subprocess
import sys

from conftest import release_domain, REPO, reserve_domain
import pytest

pytestmark = pytest.mark.runs_for_minutes(1)


def test_the_web_view_benchmark_runs_and_reports_every_figure(tmp_path):
    figures = tmp_path / 'web_view.json'
    # A DDS domain of its own: the benchmark's node must meet no other node.
    domain = reserve_domain()
    completed = subprocess.run(
        [sys.executable, str(REPO / 'bench' / 'web_view.py'), '--changes', '5',
         '--soak-minutes', '0.2', '--pages', '2', '--phase-seconds', '3', '--json', str(figures)],
        env={**os.environ, 'ROS_DOMAIN_ID': domain}, capture_output=True, text=True, timeout=600)
    release_domain(domain)
    assert completed.returncode == 0, completed.stdout[-3000:] + completed.stderr[-3000:]
    results = json.loads(figures.read_text())
    assert results['latency']['from_send']['n'] == 5
    latency = results['latency']
    # The page may show a change before its answer is back at the client (the change event
    # and the answer travel separately): after the answer may be below 0 ms, after the send not.
    assert latency['from_ack']['p50_ms'] <= latency['from_send']['p50_ms']
    assert latency['from_send']['p50_ms'] > 0
    for command in ('QUERY', 'REPLACE'):
        assert results['cost'][command]['with']['calls'] > 0
        assert results['cost'][command]['p50_ratio'] > 0
    samples = results['soak']['samples']
    assert samples and samples[-1]['pages']['graph']['js_heap_mib'] > 0
    assert results['soak']['moves'] > 0
    for line in ('== change -> page', '== ROS round trip p50', '== soak'):
        assert line in completed.stdout
