# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The ARMOR ROS 2 node: serves armor_msgs services in front of the Java knowledge core."""
