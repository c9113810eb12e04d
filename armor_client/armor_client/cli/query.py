# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Ask a question and print the answer as a table (short names; --iri for full IRIs).

  armor query REF SPEC [SPEC] ARGS...        (QUERY is implied; "--" ends the specs early)

The specs are those of QUERY in docs/commands.md; the longest known combination is taken, the
rest are arguments (a misspelt spec is answered with the closest ones). Examples:
  armor query robotics IND CLASS OccupiedRoom
  armor query robotics DATAPROP IND batteryLevel robot1
  armor query robotics IND DL "Agent and isIn some Room"
  armor query robotics CONSISTENCY
SPARQL is answered as a table with a column per variable (see also armor sparql).
Exit status: 0 answered, 1 the query failed, 2 usage error, 3 no service.
"""

import argparse
import sys

from armor_client.cli.call import print_response
from armor_client.cli.common import (add_connection_arguments, connect, learn_commands,
                                     print_answer, query_words, reporting_errors)
from armor_client.errors import error_for


# Directive arguments follow a lone '--' (they may start with '-').
TRAILING = '--'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the options of armor query.

    Args:
        parser: the verb's parser.
    """
    parser.add_argument('reference', metavar='REF', help='reference name')
    parser.add_argument('words', nargs='+', metavar='SPEC/ARG',
                        help='the QUERY specs, then the arguments')
    parser.add_argument('--iri', action='store_true', help='show full IRIs, not short names')
    parser.add_argument('--json', action='store_true', help='print the whole response as JSON')
    add_connection_arguments(parser)


@reporting_errors('query')
def run(args: argparse.Namespace) -> int:
    """Send the query and print its answer.

    Args:
        args: the parsed command line (words after a lone "--" in args.directive_args).

    Returns:
        The exit status.
    """
    with connect(args) as armor:
        learn_commands(armor)
        (command, primary, secondary), arguments = query_words(args.words, args.directive_args)
        if command.upper() != 'QUERY':
            raise RuntimeError(f'armor query asks questions: {command} is no QUERY; see '
                               'docs/commands.md#queries')
        if (primary, secondary) == ('SPARQL', ''):
            # A table needs the variable names, which only the formatted answer carries.
            secondary = 'FORMATTED'
        response = armor.call(args.reference, command, primary, secondary, arguments)
    if args.json:
        print_response(response, as_json=True)
        return 0 if response.success else 1
    if not response.success:
        raise error_for(response)
    if response.error_description:
        # A name new to the reference answers an empty list: likely a typo, say so.
        print(f'note: {response.error_description}', file=sys.stderr)
    print_answer(response, primary, secondary, args.iri)
    return 0
