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
    serve_main(args=['armor_service', *args.directive_args], on_ready=_prepare_call_relay)
    return 0


def _prepare_call_relay(node) -> None:
    """Have armor call's relay discover this node now, so that the first call is quick too."""
    try:
        from armor_client.cli import call_relay
    except ImportError:  # the armor command comes with armor_client; a launch file may not
        return
    if call_relay.enabled():
        namespace = node.get_namespace()
        call_relay.prepare('' if namespace == '/' else namespace)  # as armor call names it
