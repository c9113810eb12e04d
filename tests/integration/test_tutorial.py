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


def test_in_planning_mode_the_robot_follows_plans_to_every_urgent_room(armor, demo):
    session = Armor('tutorial_plan_test', transport=armor, timeout_s=120)
    steps = demo.run(session, 11, name='tutorial_plan_test', plan=True)
    assert [step.location for step in steps[1:]] == [step.target for step in steps[:-1]]
    for step in steps:
        first = step.plan[0]
        # The robot makes the plan's first move (recharge: it stays), and the rules' choice
        # is reported beside it.
        assert step.target == (step.location if first[0] == 'recharge' else first[3].upper())
        assert step.rules is not None and step.rules[0] in step.reachable + [step.location]
        # Every plan ends recharged at the charging station, and visits every room the
        # reasoner found Urgent at that step (unless the battery is low: then it only recharges).
        assert step.plan[-1] == ('recharge', 'robot', 'e')
        rooms = {action[3].upper() for action in step.plan if action[0] == 'move'}
        if step.low_battery:
            assert not rooms & {'R1', 'R2', 'R3', 'R4'}, step.plan
        else:
            assert set(step.urgent) <= rooms | {step.location}, step
    # Shortest plans: from E, R1 and R3 (urgent at 100 s) and back take 7 moves and a recharge.
    assert len(steps[0].plan) == 8 and steps[0].urgent == ['R1', 'R3']
    visited = [step.target for step in steps]
    assert {'R1', 'R3'} <= set(visited[:7])
    assert min(step.battery for step in steps) > 0
    assert any(step.low_battery for step in steps) and steps[-1].battery == 100
    session.reference('tutorial_plan_test').drop()
