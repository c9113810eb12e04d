# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ARMOR's change events: the topic's name (relative to the node's namespace) and its QoS.

Every acknowledged change of a reference is published on CHANGE_TOPIC as an
armor_msgs/msg/ArmorChange, with the reference's revision after it. Reliable, with a deep
keep-last history, so that a subscriber that is briefly slow still receives every message; one
that falls further behind sees revisions jump and knows what it missed.
"""

from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

CHANGE_TOPIC = 'armor_changes'

# Volatile: a subscriber starts with the changes made after it joined (the current state is a
# query away); 1000 messages keep up with bursts of changes (a list of 1000 directives is one).
CHANGE_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=1000,
                        reliability=ReliabilityPolicy.RELIABLE,
                        durability=DurabilityPolicy.VOLATILE)
