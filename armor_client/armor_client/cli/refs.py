# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""List the loaded references and the client that holds each one's mount.

  armor refs

Exit status: 0 listed, 2 usage error, 3 no service.
"""

import argparse

from armor_client.cli.common import (add_connection_arguments, connect, print_table,
                                     reporting_errors)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the options of armor refs.

    Args:
        parser: the verb's parser.
    """
    add_connection_arguments(parser)


@reporting_errors('refs')
def run(args: argparse.Namespace) -> int:
    """Print the table of references.

    Args:
        args: the parsed command line.

    Returns:
        The exit status.
    """
    with connect(args) as armor:
        rows = [[name, armor.mounted_by(name) or '-'] for name in armor.references()]
    print_table(['reference', 'mounted by'], rows)
    return 0
