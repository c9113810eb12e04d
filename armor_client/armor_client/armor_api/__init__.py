# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ROS 1 armor_api for ROS 2: same classes, same method names, same argument order.

Code written for armor_py_api ports by changing its imports::

    from armor_api.armor_client import ArmorClient                     # ROS 1
    from armor_client.armor_api.armor_client import ArmorClient        # ROS 2

See docs/porting-from-ros1.md for what else changed (bugs fixed, a node instead of rospy).
"""

from armor_client.armor_api.armor_client import ArmorClient
from armor_client.armor_api.armor_exceptions import (ArmorPyException, ArmorServiceCallError,
                                                     ArmorServiceInternalError)

__all__ = ['ArmorClient', 'ArmorPyException', 'ArmorServiceCallError',
           'ArmorServiceInternalError']
