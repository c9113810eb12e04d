# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The README's first example prints what the README says (issue 11 item 14), on a node of
its own so that no other test has moved alice."""

import re
import subprocess
import sys

from conftest import REPO, start_node

NAMESPACE = '/readme'


def test_the_readme_example_answers_as_printed(tmp_path):
    block = re.search(r'```console\n(.*?)```', (REPO / 'README.md').read_text(), re.DOTALL)
    steps = []
    for line in block.group(1).splitlines():
        if line.startswith('$ '):
            steps.append((line[2:].split(), []))
        else:
            steps[-1][1].append(line)
    node = start_node(tmp_path, namespace=NAMESPACE)
    try:
        for words, expected in steps:
            assert words[:2] == ['armor', 'call'], words
            done = subprocess.run([sys.executable, '-m', 'armor_client.cli', 'call', '--namespace',
                                   NAMESPACE, '--wait', '120', *words[2:]],
                                  capture_output=True, text=True, timeout=180)
            assert done.stdout.splitlines() == expected, (words, done.stdout, done.stderr)
    finally:
        node.stop()
