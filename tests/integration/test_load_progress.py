# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Loading a large ontology shows progress (issue 11 item 11): armor load draws a bar from
GET LOAD PROGRESS, and the node logs what it read, with counts."""

import re

from ontology_factory import write_abox
from terminal import Terminal


def test_a_large_load_draws_a_bar_and_the_node_logs_its_counts(armor, armor_node):
    big = write_abox(armor_node.scratch / 'big-abox.owl', rooms=2000, robots=60000)
    size_mb = big.stat().st_size / 1e6
    terminal = Terminal(['-m', 'armor_client.cli', 'load', 'big_abox', str(big)])
    try:
        screen = terminal.wait_for('loaded ', timeout_s=600)
    finally:
        code = terminal.close()
    try:
        assert code == 0, terminal.screen
        bar = re.search(r'loading big_abox: \[[#-]{30}\] +\d+% [\d.]+/([\d.]+) MB', screen)
        assert bar, screen
        assert abs(float(bar.group(1)) - size_mb) < 0.1, (bar.group(0), size_mb)
        log = armor_node.log()
        counts = re.search(r"\[INFO\] .*loading 'big_abox': read \S+ in \d+ s: (\d+) axioms, "
                           r"(\d+) individuals; starting PELLET", log)
        assert counts, log[-3000:]
        assert int(counts.group(2)) >= 62000, counts.group(0)
        assert re.search(r"\[INFO\] .*loading 'big_abox' took \d+ s", log), log[-3000:]
    finally:
        terminal = None
        from armor_client import directive
        armor.call(directive('test', 'big_abox', 'DROP'), timeout_s=300)
