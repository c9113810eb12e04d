# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Send one directive to a running ARMOR node and print the answer.

  armor call REF COMMAND [PRIMARY [SECONDARY]] -- ARGS...

REF is the reference name ("-" for none, as GET ALL REFS needs none). The exit status is 0
when the directive succeeded, 1 when it failed (its code and description go to stderr), and 2
when the service could not be reached. Examples:
  armor call robotics QUERY IND CLASS -- OccupiedRoom
  armor call robotics ADD OBJECTPROP IND -- isIn robot1 bedroom
  armor call - GET ALL REFS
"""

import argparse
import json
import sys

from armor_client.errors import ArmorServiceCallError
from armor_client.transport import ArmorTransport, directive


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('reference', metavar='REF', help='reference name, "-" for none')
    parser.add_argument('words', nargs='+', metavar='COMMAND [PRIMARY [SECONDARY]]',
                        help='the command and its two optional specs')
    parser.add_argument('--client', default='armor_cli', help='client name (default: armor_cli)')
    parser.add_argument('--namespace', default='', help='namespace of the ARMOR node')
    parser.add_argument('--timeout', type=float, default=None,
                        help='seconds to wait for the answer (default: no limit)')
    parser.add_argument('--wait', type=float, default=30.0,
                        help='seconds to wait for the service to appear (default: 30)')
    parser.add_argument('--json', action='store_true', help='print the whole response as JSON')


def run(args) -> int:
    if len(args.words) > 3:
        raise RuntimeError('at most COMMAND PRIMARY SECONDARY before "--"; put the arguments '
                           f'after "--" (got {" ".join(args.words)})')
    command, primary, secondary = (args.words + ['', ''])[:3]
    reference = '' if args.reference == '-' else args.reference
    request = directive(args.client, reference, command, primary, secondary,
                        args.directive_args)
    try:
        with ArmorTransport(namespace=args.namespace, service_wait_s=args.wait) as armor:
            response = armor.call(request, timeout_s=args.timeout)
    except ArmorServiceCallError as error:
        print(f'armor call: {error}', file=sys.stderr)
        return 2
    print_response(response, as_json=args.json)
    return 0 if response.success else 1


def print_response(response, as_json: bool = False) -> None:
    if as_json:
        print(json.dumps({
            'success': response.success, 'timeout': response.timeout,
            'exit_code': response.exit_code, 'error_description': response.error_description,
            'is_consistent': response.is_consistent,
            'queried_objects': list(response.queried_objects),
            'sparql_queried_objects': [{'key': i.key, 'value': i.value}
                                       for i in response.sparql_queried_objects]}, indent=2))
        return
    if not response.success:
        print(f'error {response.exit_code}: {response.error_description}', file=sys.stderr)
    elif response.error_description:
        # What a success says: names new to the reference (a typo?), a value that was not stored.
        print(f'note: {response.error_description}', file=sys.stderr)
    flags = []
    if response.success:
        flags.append('consistent' if response.is_consistent else 'INCONSISTENT')
    if response.timeout:
        flags.append('timed out')
    print(f'# exit_code {response.exit_code}, {"".join(f + ", " for f in flags)}'
          f'{len(response.queried_objects) or len(response.sparql_queried_objects)} result(s)')
    for item in response.queried_objects:
        print(item)
    row = []
    for item in response.sparql_queried_objects:
        if item.key:
            row.append(f'{item.key}={item.value}')
        else:
            print('  '.join(row))
            row = []
    if row:
        print('  '.join(row))
