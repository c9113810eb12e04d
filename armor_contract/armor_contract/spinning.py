# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""An executor loop that outlives the entities destroyed under it (the node's and the client's)."""

from typing import Callable

from rclpy.exceptions import InvalidHandle


def spin_while(executor, keep_going: Callable[[], bool], timeout_s: float) -> None:
    """Spin ``executor`` one turn at a time while ``keep_going()`` is true.

    rclpy raises InvalidHandle out of spin when a publisher, client, subscription or event
    handler is destroyed while the executor builds its wait set (the node's subscription sweep
    does it, a client's caller may): the loop would end and nothing would be served or answered
    any more. That turn is lost, the next one builds its wait set without the entity.
    """
    while keep_going():
        try:
            executor.spin_once(timeout_sec=timeout_s)
        except InvalidHandle:
            continue
