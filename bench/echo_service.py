# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The floor for transport benchmarks: a bare rclpy service answering ArmorDirective at once.

It answers every request with the same one-entity response a real QUERY IND CLASS gives on the
robotics ontology, so both sides move the same bytes.
"""

from armor_msgs.msg import ArmorDirectiveRes
from armor_msgs.srv import ArmorDirective
import rclpy
from rclpy.executors import ExternalShutdownException


def main():
    rclpy.init()
    node = rclpy.create_node('armor_echo')
    answer = ArmorDirectiveRes(success=True, is_consistent=True,
                               queried_objects=['<http://www.example.org/robotics#kitchen>'])

    def echo(request, response):
        response.armor_response = answer
        return response

    node.create_service(ArmorDirective, 'armor_echo_srv', echo)
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
