# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A plain rclpy subscriber of armor_changes for the tests: records every message it receives."""

import threading
import time
from typing import Callable, List

from armor_contract.events import CHANGE_QOS, CHANGE_TOPIC
from armor_msgs.msg import ArmorChange


class ChangeListener:
    """Every ArmorChange the node publishes, in the order received (no client library involved).

    Args:
        node: a node that is spun on another thread (an ArmorTransport's).
        namespace: the ARMOR node's namespace.
    """

    def __init__(self, node, namespace: str = ''):
        self._node = node
        self._condition = threading.Condition()
        self.messages: List[ArmorChange] = []
        topic = f'{namespace.rstrip("/")}/{CHANGE_TOPIC}' if namespace else CHANGE_TOPIC
        self._subscription = node.create_subscription(ArmorChange, topic, self._received,
                                                      CHANGE_QOS)

    def _received(self, message: ArmorChange) -> None:
        with self._condition:
            self.messages.append(message)
            self._condition.notify_all()

    def of(self, reference: str) -> List[ArmorChange]:
        with self._condition:
            return [m for m in self.messages if m.reference_name == reference]

    def wait_for(self, condition: Callable[[], bool], timeout_s: float = 30.0) -> None:
        with self._condition:
            if not self._condition.wait_for(condition, timeout_s):
                raise AssertionError(f'condition not met in {timeout_s} s; received: '
                                     f'{[(m.reference_name, m.revision) for m in self.messages]}')

    def wait_until_live(self, make_change: Callable[[], object], timeout_s: float = 30.0) -> None:
        """Make changes until one is received: from then on nothing published is missed."""
        deadline = time.monotonic() + timeout_s
        while True:
            before = len(self.messages)
            make_change()
            with self._condition:
                if self._condition.wait_for(lambda: len(self.messages) > before, 1.0):
                    return
            if time.monotonic() > deadline:
                raise AssertionError('no change message received: is armor_changes published?')

    def close(self) -> None:
        self._node.destroy_subscription(self._subscription)
