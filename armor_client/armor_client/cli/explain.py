# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Why does a reference believe something: its justifications (docs/explanations.md).

  armor explain REF instance IND CLASS           # EXPLAIN IND CLASS
  armor explain REF objectprop PROP SUBJECT OBJECT
  armor explain REF dataprop PROP IND VALUE [--type INTEGER]
  armor explain REF subclass SUB SUPER
  armor explain REF inconsistency
  options: -n N (up to N justifications, default 1), --aloud (also the sentence to read
  aloud, with rdfs:labels), --json

Prints the fact, then each justification as an indented list of its axioms, each marked
asserted, axiom or rule. Exit status: 0 explained, 1 refused (227: the fact does not hold;
211: the time limit ran out, the justifications found by then are printed), 2 no service.
"""

import argparse
import json
import sys
from typing import Any, List

from armor_client.cli.common import add_connection_arguments, connect, reporting_errors
from armor_client.errors import ArmorTimeLimitError
from armor_client.explanations import Explanation, parse

_WHAT = {'instance': ('IND', 2), 'objectprop': ('OBJECTPROP', 3), 'dataprop': ('DATAPROP', 3),
         'subclass': ('CLASS', 2), 'inconsistency': ('INCONSISTENCY', 0)}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the arguments of armor explain.

    Args:
        parser: the verb's parser.
    """
    parser.add_argument('reference', metavar='REF', help='reference name')
    parser.add_argument('what', choices=sorted(_WHAT), help='the kind of fact')
    parser.add_argument('names', nargs='*', metavar='NAME',
                        help='instance: IND CLASS; objectprop: PROP SUBJECT OBJECT; '
                             'dataprop: PROP IND VALUE; subclass: SUB SUPER; inconsistency: none')
    parser.add_argument('-n', '--justifications', type=int, default=1,
                        help='how many justifications at most (1 to 20, default 1)')
    parser.add_argument('--type', default='',
                        help='dataprop: the value\'s type '
                        '(INTEGER, LONG, DOUBLE, BOOLEAN, STRING...; '
                        'default: read from the value)')
    parser.add_argument('--aloud', action='store_true',
                        help='also print the explanation as a sentence, with rdfs:labels')
    parser.add_argument('--json', action='store_true', help='print the justifications as JSON')
    add_connection_arguments(parser)


def _value(text: str) -> Any:
    """A typed value from the command line: an integer, a number, a boolean, else the text."""
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            pass
    return {'true': True, 'false': False}.get(text, text)


def _explain(ref: Any, what: str, names: List[str], args: argparse.Namespace) -> Explanation:
    n = args.justifications
    if what == 'instance':
        return ref.explain_instance(*names, justifications=n)
    if what == 'objectprop':
        return ref.explain_object_property(*names, justifications=n)
    if what == 'dataprop':
        value = names[2] if args.type else _value(names[2])
        return ref.explain_data_property(names[0], names[1], value, args.type, justifications=n)
    if what == 'subclass':
        return ref.explain_subclass(*names, justifications=n)
    return ref.explain_inconsistency(justifications=n)


def render(explanation: Explanation, partial: bool = False) -> List[str]:
    """The indented list armor explain prints."""
    lines = [explanation.fact + (' (asserted)' if explanation.asserted else '')]
    for number, justification in enumerate(explanation, 1):
        lines.append(f'  justification {number}:')
        for axiom in justification:
            rule = f'{axiom.rule}: ' if axiom.kind == 'rule' else ''
            bindings = ', '.join(f'{v}={x}' for v, x in sorted(axiom.bindings.items()))
            fired = f'  ({bindings})' if bindings else ''
            lines.append(f'    [{axiom.kind}] {rule}{axiom.text}{fired}')
    if partial:
        lines.append('  (partial: the reasoner time limit ran out before all were found)')
    return lines


@reporting_errors('explain')
def run(args: argparse.Namespace) -> int:
    """Ask for the justifications and print them.

    Args:
        args: the parsed command line.

    Returns:
        The exit status.
    """
    _, count = _WHAT[args.what]
    if len(args.names) != count:
        print(f'armor explain: {args.what} takes {count} name(s), got {len(args.names)}',
              file=sys.stderr)
        return 1
    with connect(args) as armor:
        ref = armor.reference(args.reference)
        partial = False
        try:
            explanation = _explain(ref, args.what, args.names, args)
        except ArmorTimeLimitError as error:
            if error.response is None or not error.response.queried_objects:
                raise
            explanation = parse(error.response.queried_objects, ' '.join(args.names), False, False)
            partial = True
            print(f'armor explain: {error.exit_code}: {error.msg}', file=sys.stderr)
        sentence = explanation.read_aloud(ref.labels(*explanation.names())) if args.aloud else ''
    if args.json:
        print(json.dumps({'fact': explanation.fact, 'asserted': explanation.asserted,
                          'partial': partial,
                          'justifications': [[a.__dict__ for a in j] for j in explanation]}))
    else:
        print('\n'.join(render(explanation, partial)))
        if sentence:
            print(sentence)
    return 1 if partial else 0
