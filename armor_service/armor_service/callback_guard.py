# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Callbacks that cannot take the node down.

An exception that escapes a callback ends rclpy's executor, and with it every service of the
node: one malformed request or one bug would stop the robot's knowledge for every client. A
guarded callback logs the failure with its traceback and, for a service, answers what
``refuse`` fills in (an internal-error code and a description), so the caller is told.
"""

import functools
import traceback
from typing import Any, Callable, Optional

Refuse = Callable[[Any, Any, str], None]


def guarded(callback: Callable, logger: Any, what: str,
            refuse: Optional[Refuse] = None) -> Callable:
    """``callback`` with every exception logged instead of raised.

    Args:
        callback: a service callback (request, response), a timer's or a subscription's.
        logger: the node's logger (or a child of it).
        what: names the callback in the log ("service /armor_interface_srv").
        refuse: for a service, fills ``response`` for the caller given (request, response,
            description); without it the response is answered as it stands.
    """
    @functools.wraps(callback)
    def run(*args: Any) -> Any:
        try:
            return callback(*args)
        except Exception as error:
            logger.error(f'{what} failed:\n{traceback.format_exc().rstrip()}')
            if len(args) != 2:
                return None
            request, response = args
            if refuse is not None:
                refuse(request, response, f'internal error of the node in {what}: '
                       f'{type(error).__name__}: {error} (the traceback is in the node\'s log)')
            return response
    return run
