# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Start the ARMOR node (and its knowledge core) in the foreground.

ROS arguments pass through, for example:
  armor serve --ros-args -p default_reasoner:=PELLET -p preload_file:=ontologies/robotics.owl
  armor serve --ros-args -r __ns:=/robot1
"""

import argparse

# Registered by armor_service as the verb "serve" of the armor command (entry point group
# armor.verbs): the client package that owns the command never imports the server.
TRAILING = '--ros-args'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.epilog = 'Everything from --ros-args on is handed to the node unchanged.'


def run(args) -> int:
    from armor_service.node import main as serve_main
    serve_main(args=['armor_service', *args.directive_args])
    return 0
