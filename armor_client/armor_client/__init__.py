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
- ``ref.subscribe(query, callback)``, ``armor.changes(callback)`` (``armor_client.subscriptions``):
  be told when an answer, or anything, changes; async iterators in ``armor_client.aio``.
- ``ArmorTransport`` and ``directive``: raw ArmorDirectiveReq / ArmorDirectiveRes.
"""

import importlib

# Where each name lives. Imported on first use (PEP 562): `armor call` through its relay needs
# none of them, and importing rclpy and the message packages costs a quarter of a second.
_EXPORTS = {
    'Batch': 'armor_client.batch',
    'Characteristic': 'armor_client.operations', 'Consistency': 'armor_client.answers',
    'Reasoner': 'armor_client.operations', 'SparqlRows': 'armor_client.answers',
    'AcknowledgedChange': 'armor_client.answers', 'ChangeHistory': 'armor_client.answers',
    'Armor': 'armor_client.reference', 'Reference': 'armor_client.reference',
    'ArmorTransport': 'armor_client.transport', 'directive': 'armor_client.transport',
    'SceneAnswer': 'armor_client.scenes', 'SceneClass': 'armor_client.scenes',
    'Recognition': 'armor_client.scenes',
    'Explanation': 'armor_client.explanations', 'ExplainedAxiom': 'armor_client.explanations',
    **{name: 'armor_client.subscriptions' for name in (
        'AnswerChange', 'Change', 'ChangeWatch', 'Subscription')},
    **{name: 'armor_client.errors' for name in (
        'ArmorArgumentError', 'ArmorCallTimeout', 'ArmorCoreUnavailableError', 'ArmorError',
        'ArmorFileError', 'ArmorMountError', 'ArmorNotEntailedError', 'ArmorReasonerError',
        'ArmorRolledBackError',
        'ArmorServiceCallError', 'ArmorServiceInternalError', 'ArmorTimeLimitError',
        'ArmorUnknownReferenceError')},
}

__all__ = sorted(_EXPORTS)


def __getattr__(name):
    if name not in _EXPORTS:
        raise AttributeError(f'module {__name__!r} has no attribute {name!r}')
    value = getattr(importlib.import_module(_EXPORTS[name]), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(list(globals()) + list(_EXPORTS))
