# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""What the ARMOR node and its clients agree on beyond the armor_msgs types.

The node (armor_service) and the clients (armor_client) never import each other; both import
this package:

- ``catalogue``: the knowledge core's own catalogue of commands, exit codes and settings,
  generated from ``java -jar armor-core.jar --catalogue`` into ``catalogue.json`` (``make
  catalogue``; a test fails when the file and the core differ);
- ``exit_codes``: the exit codes as an IntEnum (checked against the catalogue by a test);
- ``services``: the names of ARMOR's services and their QoS profile, on both ends;
- ``events``: the change topic, its QoS, and the subscription services (issue 12).
"""
