# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The surveillance tutorial, short: the robot's beliefs and decisions step by step."""

import importlib.util

from armor_client import Armor
from conftest import REPO
import pytest


@pytest.fixture(scope='module')
def demo():
    spec = importlib.util.spec_from_file_location(
        'surveillance_demo', REPO / 'examples' / 'surveillance_demo.py')
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_robot_patrols_urgent_rooms_and_recharges(armor, demo):
    session = Armor('tutorial_test', transport=armor, timeout_s=120)
    steps = demo.run(session, 11, name='tutorial_test')
    assert [step.target for step in steps] == [
        'C1', 'R1', 'C1', 'R2', 'C1', 'C2', 'R3', 'C2', 'E', 'E', 'C1']
    assert [step.location for step in steps[1:]] == [step.target for step in steps[:-1]]
    assert [step.time for step in steps] == list(range(100, 210, 10))
    assert [step.battery for step in steps] == [100, 90, 80, 70, 60, 50, 40, 30, 20, 10, 100]
    # What the reasoner concluded: urgency from the visit times, reach from the doors.
    assert steps[0].urgent == ['R1', 'R3'] and steps[0].reachable == ['C1', 'C2']
    assert steps[1].urgent == ['R1', 'R3'] and steps[1].reachable == ['C2', 'E', 'R1', 'R2']
    assert steps[2].urgent == ['R3'] and steps[5].urgent == ['R3', 'R4']
    assert [step.low_battery for step in steps] == [False] * 8 + [True, True, False]
    assert steps[1].reason == 'urgent, unvisited for 80 s'
    assert steps[8].reason == 'low battery: to the charging station'
    assert steps[9].reason == 'low battery: recharging'
    reference = session.reference('tutorial_test')
    assert reference.object_values('isIn', 'robot') == ['C1']
    assert reference.data_values('visitedAt', 'C1') == [210]
    assert reference.mounted_by() is None
    reference.drop()
