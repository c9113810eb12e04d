# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ARMOR's services: their names (relative to the node's namespace) and their QoS profile."""

from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy

DIRECTIVE_SERVICE = 'armor_interface_srv'
LIST_SERVICE = 'armor_interface_serialized_srv'

# The default service QoS keeps 10 samples: with more answers than that in flight to slow
# clients, a reliable writer overwrites ones not yet acknowledged and those clients wait forever
# (seen with 8 client processes on 2 cores). Requests and answers are small; keep many.
SERVICE_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=1000,
                         reliability=ReliabilityPolicy.RELIABLE)
