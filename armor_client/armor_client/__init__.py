# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Python client for ARMOR for ROS 2.

>>> from armor_client import Armor
>>> with Armor('planner') as armor:                                      # doctest: +SKIP
...     robotics = armor.reference('robotics')
...     robotics.add_object_value('isIn', 'alice', 'bedroom')
...     print(robotics.instances('OccupiedRoom'))
['bedroom', 'kitchen']

- ``Armor`` / ``Reference``: one method per command, Python values back, exceptions on error;
  ``with ref.mounted():``, ``with ref.batch() as batch:`` (one atomic list).
- ``armor_client.aio``: ``AsyncArmor`` / ``AsyncReference``, the same methods for asyncio.
- ``armor_client.armor_api``: ROS 1 armor_api's ``ArmorClient``, for porting old code.
- ``ArmorTransport`` and ``directive``: raw ArmorDirectiveReq / ArmorDirectiveRes.
"""

from armor_client.batch import Batch
from armor_client.errors import (ArmorArgumentError, ArmorCallTimeout, ArmorCoreUnavailableError,
                                 ArmorError, ArmorFileError, ArmorMountError,
                                 ArmorReasonerError, ArmorRolledBackError, ArmorServiceCallError,
                                 ArmorServiceInternalError, ArmorTimeLimitError,
                                 ArmorUnknownReferenceError)
from armor_client.operations import Characteristic, Consistency, Reasoner, SparqlRows
from armor_client.reference import Armor, Reference
from armor_client.transport import ArmorTransport, directive

__all__ = ['Armor', 'ArmorArgumentError', 'ArmorCallTimeout', 'ArmorCoreUnavailableError',
           'ArmorError', 'ArmorFileError', 'ArmorMountError', 'ArmorReasonerError',
           'ArmorRolledBackError', 'ArmorServiceCallError', 'ArmorServiceInternalError',
           'ArmorTimeLimitError', 'ArmorTransport', 'ArmorUnknownReferenceError', 'Batch',
           'Characteristic', 'Consistency', 'Reasoner', 'Reference', 'SparqlRows', 'directive']
