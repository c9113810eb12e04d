# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ARMOR's change events and subscriptions: names (relative to the node's namespace) and QoS.

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

# Subscriptions to the answer of a query: armor_msgs/srv/ArmorSubscribe and ArmorUnsubscribe.
SUBSCRIBE_SERVICE = 'armor_subscribe'
UNSUBSCRIBE_SERVICE = 'armor_unsubscribe'
# Each subscription publishes armor_msgs/msg/ArmorAnswer on ANSWER_TOPICS/<subscription id>.
ANSWER_TOPICS = 'armor_answers'
# Transient local: the first message (the whole answer) is published when the subscription is
# made, before its client has had time to subscribe; it is kept for the subscriber that joins.
ANSWER_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=1000,
                        reliability=ReliabilityPolicy.RELIABLE,
                        durability=DurabilityPolicy.TRANSIENT_LOCAL)
