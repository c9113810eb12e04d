# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Write a reference's ontology to a file (on the node's machine).

  armor save REF [PATH] [--format turtle] [--inferences]

PATH is made absolute against the current directory, as every client's paths are; without
PATH the ontology goes back to the file it was loaded from. The node writes only inside its
allowed_dirs. --inferences adds the inferred types, property values and hierarchy to the file
(the live ontology does not change).
Exit status: 0 saved, 1 refused, 2 usage error, 3 no service.
"""

import argparse

from armor_client.cli.common import add_connection_arguments, connect, reporting_errors
from armor_client.paths import absolute

FORMATS = ('rdfxml', 'owlxml', 'turtle', 'functional', 'manchester')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the options of armor save.

    Args:
        parser: the verb's parser.
    """
    parser.add_argument('reference', metavar='REF', help='reference name')
    parser.add_argument('path', metavar='PATH', nargs='?', default='',
                        help='file to write (default: the file it was loaded from)')
    parser.add_argument('--format', choices=FORMATS, default='',
                        help='syntax of the file (default: as loaded)')
    parser.add_argument('--inferences', action='store_true', help='also write the inferences')
    add_connection_arguments(parser)


@reporting_errors('save')
def run(args: argparse.Namespace) -> int:
    """Save and say where.

    Args:
        args: the parsed command line.

    Returns:
        The exit status.
    """
    path = absolute(args.path)
    with connect(args) as armor:
        armor.reference(args.reference).save(path, args.format, inferences=args.inferences)
    print(f'saved {args.reference} to {path or "the file it was loaded from"}')
    return 0
