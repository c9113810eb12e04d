# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The exceptions of ROS 1 armor_api, under their old module name.

``ArmorServiceCallError``: the service could not be called. ``ArmorServiceInternalError``:
ARMOR answered that the directive failed; ``.code`` (also ``.exit_code``) is its exit code and
``.msg`` (also ``.description``) its description.
"""

from armor_client.errors import ArmorError, ArmorServiceCallError, ArmorServiceInternalError

# armor_api's common base class had this name.
ArmorPyException = ArmorError

__all__ = ['ArmorPyException', 'ArmorServiceCallError', 'ArmorServiceInternalError']
