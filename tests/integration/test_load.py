# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A short load run in the suite; the full 8 x 2,000 is `python tests/integration/load.py`."""

from load import run


def test_concurrent_clients_lose_nothing_and_mounts_hold(tmp_path):
    report = run(tmp_path, clients=8, operations=120)
    assert report['clients_finished'] == 8 and not report['deadlocked'], report
    assert report['node_alive']
    assert report['unexpected_errors'] == [], report
    assert report['lost'] == 0 and report['doubled'] == 0, report
    assert report['wrong_counters'] == 0, report
    assert report['exclusivity_violations'] == 0, report
    assert report['mount_sessions'] > 5, report
