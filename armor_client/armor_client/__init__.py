# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Python client for ARMOR for ROS 2.

>>> from armor_client import ArmorTransport, directive
>>> with ArmorTransport() as armor:                                  # doctest: +SKIP
...     answer = armor.call(directive('me', 'robotics', 'QUERY', 'IND', 'CLASS', ['Room']))
...     print(answer.queried_objects)
"""

from armor_client.errors import ArmorError, ArmorServiceCallError, ArmorServiceInternalError
from armor_client.transport import ArmorTransport, directive

__all__ = ['ArmorError', 'ArmorServiceCallError', 'ArmorServiceInternalError', 'ArmorTransport',
           'directive']
