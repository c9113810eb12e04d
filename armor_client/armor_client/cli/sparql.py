# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Run a SPARQL SELECT or ASK query and print the rows as a table.

  armor sparql REF QUERY          (QUERY "-" reads the query from stdin)

The query sees asserted and inferred knowledge; the ontology's prefixes are predefined and
":" is the reference's namespace. Examples:
  armor sparql robotics "SELECT ?who ?where WHERE { ?who :isIn ?where }"
  armor sparql robotics "ASK { :robot1 :isIn :kitchen }"
Exit status: 0 answered, 1 the query failed, 2 usage error, 3 no service.
"""

import argparse
import sys

from armor_client.cli.common import (add_connection_arguments, connect, print_answer,
                                     reporting_errors)
from armor_client.errors import error_for


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the options of armor sparql.

    Args:
        parser: the verb's parser.
    """
    parser.add_argument('reference', metavar='REF', help='reference name')
    parser.add_argument('query', metavar='QUERY', help='the SPARQL query, "-" for stdin')
    parser.add_argument('--timeout-ms', type=int, default=None,
                        help='time limit of the service; the rows found by then are printed')
    parser.add_argument('--iri', action='store_true', help='show full IRIs, not short names')
    add_connection_arguments(parser)


@reporting_errors('sparql')
def run(args: argparse.Namespace) -> int:
    """Send the query and print the rows.

    Args:
        args: the parsed command line.

    Returns:
        The exit status.
    """
    query = sys.stdin.read() if args.query == '-' else args.query
    query_args = [query] if args.timeout_ms is None else [query, args.timeout_ms]
    with connect(args) as armor:
        response = armor.call(args.reference, 'QUERY', 'SPARQL', 'FORMATTED', query_args)
    if not response.success:
        raise error_for(response)
    print_answer(response, 'SPARQL', 'FORMATTED', args.iri)
    return 0
