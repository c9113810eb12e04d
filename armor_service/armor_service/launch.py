# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The harness's old name, kept so that scripts importing it from here keep working."""

from armor_service.node_harness import ArmorNodeProcess  # noqa: F401
