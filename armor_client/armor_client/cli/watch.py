# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Watch a query's answer change (or every change of a reference) until Ctrl-C.

  armor watch REF SPEC [SPEC] ARGS...        (a query, written as for armor query: its answer)
  armor watch REF                            (every change of REF; - for all)

With a query, prints its answer now, then one line per answer that appears ("+ name") or
disappears ("- name") with the revision it holds at, inferred answers included: the node asks
the reasoner again after each change. QUERY may be written or left out, and "--" ends the
specs early, as for armor query. Examples:
  armor watch robotics IND CLASS OccupiedRoom
  armor watch robotics SPARQL "SELECT ?who ?room WHERE { ?who :isIn ?room }"
Without one, prints one line per acknowledged change: revision, client, directives.
Lines starting with "!" report what went wrong: the query failing at a revision (e.g. 217,
inconsistent), messages missed (the answer shown may then be incomplete); a line starting
with "#" says when the query is answered again after such a failure.
Exit status: 0 after Ctrl-C, 1 the node refused the query, 2 usage error, 3 no service.
"""

import argparse
import os
import signal
import sys
import threading
import time
from typing import Any, Callable

from armor_client.cli.common import (add_connection_arguments, connect, learn_commands,
                                     query_words, reporting_errors)
from armor_client.subscriptions import AnswerChange, Change
from armor_client.transport import directive
from armor_client.values import Value

# Directive arguments follow a lone '--' (they may start with '-').
TRAILING = '--'
# How long an answer topic may go without its publisher before the watch subscribes again.
_GONE_S = 5.0
# Set to end the watch: SIGTERM, or nobody reading any more.
_STOP = threading.Event()


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the options of armor watch.

    Args:
        parser: the verb's parser.
    """
    parser.add_argument('reference', metavar='REF', help='reference name ("-": every reference, '
                        'when watching changes)')
    parser.add_argument('words', nargs='*', metavar='SPEC/ARG',
                        help='the QUERY specs, then the arguments (none: watch every change of '
                        'REF)')
    parser.add_argument('--iri', action='store_true', help='show full IRIs, not short names')
    add_connection_arguments(parser)


@reporting_errors('watch')
def run(args: argparse.Namespace) -> int:
    """Watch until Ctrl-C (or SIGTERM).

    Args:
        args: the parsed command line (words after a lone "--" in args.directive_args).

    Returns:
        The exit status.
    """
    import rclpy
    from rclpy.signals import SignalHandlerOptions
    # Without rclpy's signal handlers Ctrl-C is a KeyboardInterrupt here, and the subscription
    # is ended on the way out; SIGTERM too.
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    stop = _STOP
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    try:
        with connect(args, iris=args.iri) as armor:
            _watch(args, armor, stop)
    except KeyboardInterrupt:
        pass
    finally:
        rclpy.try_shutdown()
    return 0


def _watch(args: argparse.Namespace, armor: Any, stop: threading.Event) -> None:
    if args.words or args.directive_args:
        learn_commands(armor)
        words, arguments = query_words(args.words, args.directive_args)
        query = directive(armor.client_name, args.reference, *words, arguments)
        while not stop.is_set():
            printer = _AnswerPrinter(args.reference, query)
            with armor.reference(args.reference).subscribe(query, printer.print) as watched:
                _wait(stop, lambda: watched.alive)
            if not stop.is_set():
                _say(f'! the node no longer answers subscription {watched.id} (it was '
                     'restarted?): subscribing again')
    else:
        reference = None if args.reference == '-' else args.reference
        with armor.changes(_print_change, reference):
            _say(f'# watching the changes of {reference or "every reference"} (Ctrl-C ends)')
            _wait(stop)


class _AnswerPrinter:
    """Prints a subscription's answer, then its changes."""

    def __init__(self, reference: str, query: Any):
        self._title = ' '.join(word for word in (
            reference, query.command, query.primary_command_spec, query.secondary_command_spec,
            *query.args) if word)
        self._failing = False

    def print(self, change: AnswerChange) -> None:
        if change.initial:
            count = len(change.answer)
            _say(f'# {self._title}: {count} answer{"" if count == 1 else "s"} at revision '
                 f'{change.revision} (Ctrl-C ends)')
            for answer in change.answer:
                _say(_text(answer))
            return
        if change.missed:
            _say(f'! {change.missed} update(s) missed before revision {change.revision}: the '
                 'answer shown may be incomplete')
        if change.exit_code:
            _say(f'! revision {change.revision}: error {change.exit_code}: {change.error}')
        elif self._failing:
            # Else the "!" line would stay the last one on screen, as if nothing had changed.
            count = len(change.answer)
            _say(f'# revision {change.revision}: answered again, {count} '
                 f'answer{"" if count == 1 else "s"}')
        self._failing = change.exit_code != 0
        for answer in change.removed:
            _say(f'- {_text(answer)}  (revision {change.revision})')
        for answer in change.added:
            _say(f'+ {_text(answer)}  (revision {change.revision})')


def _print_change(change: Change) -> None:
    if change.missed:
        first, last = change.missed[0], change.missed[-1]
        _say(f'! {change.reference}: revision{"s" if last > first else ""} '
             f'{first}{f"-{last}" if last > first else ""} missed')
    consistency = '' if change.consistent else '  (inconsistent)'
    _say(f'{change.reference}  revision {change.revision}  {change.client or "-"}: '
         f'{change.describe()}{consistency}')


def _text(value: Value) -> str:
    if isinstance(value, bool):
        return 'true' if value else 'false'
    return str(value)


def _wait(stop: threading.Event, alive: Callable[[], bool] = lambda: True) -> None:
    """Until stop is set, or alive() has been false for _GONE_S."""
    gone_since = None
    while not stop.wait(0.5):
        if alive():
            gone_since = None
        elif gone_since is None:
            gone_since = time.monotonic()
        elif time.monotonic() - gone_since > _GONE_S:
            return


def _say(line: str) -> None:
    try:
        print(line, flush=True)
    except BrokenPipeError:
        # The reader went away (armor watch ... | head): end the watch quietly.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        _STOP.set()
