# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Tests never reach a node they did not start (issue 11 item 2).

A user's own node (make run) runs in the domain the user exported; the suite, run from that
shell, must leave it alone. A decoy node stands in for it: a real ARMOR node logging every
directive it receives to a file, while a run of the suite's own kinds of tests (the session
node through the call fixture, the CLI, a test starting a node of its own) goes on beside it.
"""

import os
import pathlib
import subprocess
import sys

from conftest import domains_in_use, release_domain, reserve_domain, start_node

REPO = pathlib.Path(__file__).resolve().parents[2]
# One test of each path a directive can take from a test to a node.
PATHS = ['tests/integration/test_contract_references.py::test_get_all_refs_lists_exactly_the_loaded_references',
         'tests/integration/test_cli.py::test_call_prints_the_answer',
         'tests/integration/test_node_log.py::test_routine_lines_are_info_and_ctrl_c_is_quiet']


def test_a_user_node_on_the_exported_domain_receives_nothing_from_the_suite(tmp_path):
    user_domain = reserve_domain()
    saved = os.environ['ROS_DOMAIN_ID']
    os.environ['ROS_DOMAIN_ID'] = user_domain
    try:
        decoy = start_node(tmp_path)
    finally:
        os.environ['ROS_DOMAIN_ID'] = saved
    # From here on the decoy is like a user's node: nothing marks its domain but its traffic.
    release_domain(user_domain)
    received = tmp_path / 'received.log'
    try:
        env = {**os.environ, 'ROS_DOMAIN_ID': user_domain}
        # Without the call relay: a relay still proving its path when the call is answered
        # asks GET ALL REFS after LOG FILE ON, which would be counted as the suite's.
        logged = subprocess.run(
            [sys.executable, '-m', 'armor_client.cli', 'call', '--no-relay', '-', 'LOG', 'FILE',
             'ON', '--wait', '120', '--', str(received)], env=env, capture_output=True, text=True,
            timeout=300)
        assert logged.returncode == 0, logged.stdout + logged.stderr + decoy.log()
        assert int(user_domain) in domains_in_use()
        suite = subprocess.run(
            [sys.executable, '-m', 'pytest', '-p', 'no:cacheprovider', '-q', *PATHS], cwd=REPO,
            env=env, capture_output=True, text=True, timeout=900)
        assert suite.returncode == 0, suite.stdout[-4000:] + suite.stderr[-2000:]
        assert f'{len(PATHS)} passed' in suite.stdout, suite.stdout[-2000:]
    finally:
        decoy.stop()
    lines = received.read_text().splitlines()
    # Only the decoy's own LOG FILE ON: not one directive of the suite.
    assert len(lines) == 1 and 'LOG FILE ON' in lines[0], '\n'.join(lines)
