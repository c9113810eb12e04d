# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The executor loop of the client's transport and of the node goes on past an entity destroyed
under it (rclpy's InvalidHandle out of spin_once) and stops when told."""

from armor_contract.spinning import spin_while
from rclpy.exceptions import InvalidHandle


class _ExecutorLosingAnEntity:
    """spin_once raises as rclpy does when an event handler went away during the wait set."""

    def __init__(self, raising_turns):
        self.raising_turns = set(raising_turns)
        self.turns = 0

    def spin_once(self, timeout_sec):
        self.turns += 1
        if self.turns in self.raising_turns:
            raise InvalidHandle('destroyed while building the wait set')


def test_turns_go_on_after_an_entity_was_destroyed_under_the_executor():
    executor = _ExecutorLosingAnEntity(raising_turns={1, 3})
    spin_while(executor, lambda: executor.turns < 5, timeout_s=0.01)
    assert executor.turns == 5


def test_the_loop_ends_when_told_and_not_before():
    executor = _ExecutorLosingAnEntity(raising_turns=())
    spin_while(executor, lambda: executor.turns < 2, timeout_s=0.01)
    assert executor.turns == 2
