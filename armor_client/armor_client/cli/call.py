# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Send one directive to a running ARMOR node and print the answer.

  armor call REF COMMAND [PRIMARY [SECONDARY]] -- ARGS...

REF is the reference name ("-" for none, as GET ALL REFS needs none). The exit status is 0
when the directive succeeded, 1 when it failed (its code and description go to stderr), 2
when the command line is wrong and 3 when the service could not be reached. A relative path
argument (LOAD FILE, SAVE, a PDDL mapping...) is this directory's: it is sent made absolute.
JSON answers are indented; --raw prints the results alone, as they came (no "# exit_code"
line), so that an answer can be saved as a file or read by a script. Examples:
  armor call robotics QUERY IND CLASS -- OccupiedRoom
  armor call robotics ADD OBJECTPROP IND -- isIn robot1 bedroom
  armor call - GET ALL REFS
  armor call robotics QUERY PDDL PROBLEM --raw -- mapping.yaml > problem.pddl

The first call starts a background relay that keeps ROS 2 discovered, so that later calls
answer in a few tens of milliseconds instead of a second (ARMOR_CALL_RELAY=0 or --no-relay:
every call starts ROS itself). It exits after 10 minutes without calls.
"""

import argparse
import json
import os
import sys
import threading
from types import SimpleNamespace

from armor_client.cli import call_relay, EXIT_FAILED, EXIT_NO_SERVICE, EXIT_OK

SERVICE = 'armor_interface_srv'


# Directive arguments follow a lone '--' (they may start with '-').
TRAILING = '--'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('reference', metavar='REF', help='reference name, "-" for none')
    parser.add_argument('words', nargs='+', metavar='COMMAND [PRIMARY [SECONDARY]]',
                        help='the command and its two optional specs')
    parser.add_argument('--client', default='armor_cli', help='client name (default: armor_cli)')
    parser.add_argument('--namespace', default='', help='namespace of the ARMOR node')
    parser.add_argument('--timeout', type=float, default=None,
                        help='seconds to wait for the answer (default: no limit)')
    parser.add_argument('--wait', type=float, default=call_relay.DEFAULT_WAIT_S,
                        help='seconds to wait for the service to appear '
                        f'(default: {call_relay.DEFAULT_WAIT_S:g})')
    output = parser.add_mutually_exclusive_group()
    output.add_argument('--json', action='store_true', help='print the whole response as JSON')
    output.add_argument('--raw', action='store_true',
                        help='print only the results, exactly as answered (no "# exit_code" line)')
    parser.add_argument('--no-relay', action='store_true',
                        help='start ROS in this process instead of using the background relay')


def run(args) -> int:
    if len(args.words) > 3:
        raise RuntimeError('at most COMMAND PRIMARY SECONDARY before "--"; put the arguments '
                           f'after "--" (got {" ".join(args.words)})')
    command, primary, secondary = (args.words + ['', ''])[:3]
    fields = {'client': args.client, 'reference': '' if args.reference == '-' else args.reference,
              'command': command, 'primary': primary, 'secondary': secondary,
              'args': list(args.directive_args)}
    waiting = _Waiting(args)
    try:
        answer = _relayed(fields, args, waiting) if _use_relay(args) else None
        if answer is None:
            answer = _direct(fields, args)
    finally:
        waiting.cancel()
    if 'error' in answer:
        message = _unreachable(args) if answer.get('unreachable') else answer['error']
        print(f'armor call: {message}', file=sys.stderr)
        return EXIT_NO_SERVICE
    response = SimpleNamespace(**answer['response'])
    response.sparql_queried_objects = [SimpleNamespace(**item)
                                       for item in response.sparql_queried_objects]
    print_response(response, as_json=args.json, raw=args.raw)
    return EXIT_OK if response.success else EXIT_FAILED


def _use_relay(args) -> bool:
    return call_relay.enabled() and not args.no_relay


def _relayed(fields: dict, args, waiting: '_Waiting'):
    """The relay's answer, or None when no relay took it."""
    # Relative paths are this directory's, not the relay's.
    request = {'directive': fields, 'namespace': args.namespace, 'wait_s': args.wait,
               'timeout_s': args.timeout, 'cwd': os.getcwd()}
    try:
        return call_relay.call(request, on_state=waiting.state)
    except call_relay.RelayRefused as refusal:
        print(f'armor call: {refusal}', file=sys.stderr)
        return None
    except call_relay.RelayUnavailable:
        pass
    # No relay yet: start one and go through it. Discovering the service here as well would
    # do the same work twice on the same cores.
    call_relay.start_in_background(prepare=args.namespace)
    try:
        return call_relay.call(request, on_state=waiting.state, connect_s=2.0)
    except call_relay.RelayUnavailable:
        return None


def _direct(fields: dict, args) -> dict:
    from armor_client.commands import find_on
    from armor_client.errors import ArmorServiceCallError
    from armor_client.transport import ArmorTransport, directive
    words = (fields['command'], fields['primary'], fields['secondary'])
    try:
        with ArmorTransport(namespace=args.namespace, service_wait_s=args.wait) as armor:
            find_on(armor, *words)  # a plugin's command: which of its arguments are paths
            request = directive(fields['client'], fields['reference'], *words, fields['args'])
            response = armor.call(request, timeout_s=args.timeout)
    except ArmorServiceCallError as error:
        return {'error': str(error), 'unreachable': 'did not answer within' in str(error)}
    return {'response': {
        'success': response.success, 'timeout': response.timeout,
        'exit_code': response.exit_code, 'error_description': response.error_description,
        'is_consistent': response.is_consistent,
        'queried_objects': list(response.queried_objects),
        'sparql_queried_objects': [{'key': i.key, 'value': i.value}
                                   for i in response.sparql_queried_objects]}}


def _where(args) -> str:
    namespace = '/' + args.namespace.strip('/') if args.namespace.strip('/') else '/'
    service = namespace.rstrip('/') + '/' + SERVICE
    return (f'service {service} (ROS_DOMAIN_ID={os.environ.get("ROS_DOMAIN_ID", "0 (unset)")}, '
            f'namespace {namespace})')


def _unreachable(args) -> str:
    return (f'no ARMOR {_where(args)} answered within {args.wait:g} s. Is a node running '
            '(armor serve, make run) in this domain and namespace? --wait gives it longer, '
            '--namespace and ROS_DOMAIN_ID choose where to look.')


class _Waiting:
    """After a second without an answer, says what the call is waiting for."""

    def __init__(self, args):
        self._args = args
        self._discovering = True
        self._timer = threading.Timer(1.0, self._say)
        self._timer.daemon = True
        self._timer.start()

    def state(self, state: str) -> None:
        self._discovering = state == 'discovering'

    def cancel(self) -> None:
        self._timer.cancel()

    def _say(self) -> None:
        if self._discovering:
            print(f'armor call: waiting for {_where(self._args)} to be discovered (up to '
                  f'{self._args.wait:g} s)', file=sys.stderr, flush=True)
        else:
            limit = (f'up to {self._args.timeout:g} s' if self._args.timeout
                     else 'without a time limit (--timeout sets one)')
            print(f'armor call: the directive was sent to {_where(self._args)}; waiting for its '
                  f'answer {limit}', file=sys.stderr, flush=True)


def print_response(response, as_json: bool = False, raw: bool = False) -> None:
    if raw:
        if not response.success:
            print(f'error {response.exit_code}: {response.error_description}', file=sys.stderr)
        for item in response.queried_objects:
            print(item, end='' if item.endswith('\n') else '\n')
        _print_rows(response.sparql_queried_objects)
        return
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
        print(_readable(item))
    _print_rows(response.sparql_queried_objects)


def _readable(item: str) -> str:
    """A JSON answer (GET CATALOGUE's, GET REF CHANGES') indented; other text as it is."""
    if not item.startswith(('{', '[')):
        return item
    try:
        return json.dumps(json.loads(item), indent=2, ensure_ascii=False)
    except ValueError:
        return item


def _print_rows(items) -> None:
    row = []
    for item in items:
        if item.key:
            row.append(f'{item.key}={item.value}')
        else:
            print('  '.join(row))
            row = []
    if row:
        print('  '.join(row))
