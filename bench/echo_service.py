# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The floor for transport benchmarks: a bare rclpy service answering ArmorDirective at once.

    python bench/echo_service.py [--namespace NS] [--executor single|multi]

It answers every request with the same one-entity response a real QUERY IND CLASS gives on the
robotics ontology, so both sides move the same bytes. `single` (rclpy.spin) is the floor;
`multi` spins on the executor the ARMOR node uses (MultiThreadedExecutor, 16 threads, a
reentrant group), which tells how much of the service's overhead is that choice alone.
"""

import argparse

from armor_msgs.msg import ArmorDirectiveRes
from armor_msgs.srv import ArmorDirective
import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor

ECHO_SERVICE = 'armor_echo_srv'


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--namespace', default='')
    parser.add_argument('--executor', choices=('single', 'multi'), default='single')
    options = parser.parse_args()
    rclpy.init()
    node = rclpy.create_node('armor_echo', namespace=options.namespace)
    answer = ArmorDirectiveRes(success=True, is_consistent=True,
                               queried_objects=['<http://www.example.org/robotics#kitchen>'])

    def echo(request, response):
        response.armor_response = answer
        return response

    try:
        if options.executor == 'single':
            node.create_service(ArmorDirective, ECHO_SERVICE, echo)
            rclpy.spin(node)
        else:
            node.create_service(ArmorDirective, ECHO_SERVICE, echo,
                                callback_group=ReentrantCallbackGroup())
            executor = MultiThreadedExecutor(num_threads=16)
            executor.add_node(node)
            executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
