# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""What the verbs of the armor command share: connection options, errors, tables."""

import argparse
import functools
import sys
from typing import Any, Callable, List, Optional, Sequence, TextIO, Tuple

from armor_client import commands
from armor_client.cli import EXIT_FAILED, EXIT_NO_SERVICE
from armor_client.errors import ArmorServiceCallError, ArmorServiceInternalError
from armor_client.answers import Answers, sparql_rows
from armor_client.reference import Armor
from armor_client.values import answer_value, is_literal, split_literal

# Column titles of the entity answers, by (primary, secondary) spec of the QUERY.
_ENTITY_COLUMN = {
    ('IND', ''): 'class', ('CLASS', 'IND'): 'class', ('CLASS', 'CLASS'): 'class',
    ('CLASS', 'DL'): 'class', ('CLASS', 'SUPER'): 'class', ('CLASS', 'EQUIVALENT'): 'class',
    ('CLASS', 'DISJOINT'): 'class', ('IND', 'CLASS'): 'individual', ('IND', 'DL'): 'individual',
    ('IND', 'SAME'): 'individual', ('OBJECTPROP', 'IND'): 'individual',
    ('IND', 'DATAPROP'): 'data property', ('DATAPROP', 'DATAPROP'): 'data property',
    ('IND', 'OBJECTPROP'): 'object property', ('OBJECTPROP', 'OBJECTPROP'): 'object property',
    ('CLASS', 'RESTRICTIONS'): 'restriction', ('CONSISTENCY', ''): 'cause of inconsistency',
}


def add_connection_arguments(parser: argparse.ArgumentParser) -> None:
    """The options every verb that talks to a node has.

    Args:
        parser: the verb's parser.
    """
    parser.add_argument('--client', default='armor_cli', help='client name (default: armor_cli)')
    parser.add_argument('--namespace', default='', help='namespace of the ARMOR node')
    parser.add_argument('--timeout', type=float, default=None,
                        help='seconds to wait for each answer (default: no limit)')
    parser.add_argument('--wait', type=float, default=30.0,
                        help='seconds to wait for the service to appear (default: 30)')


def connect(args: argparse.Namespace, iris: bool = False) -> Armor:
    """An Armor session as the connection options say.

    Args:
        args: parsed options of add_connection_arguments().
        iris: answer entities as IRIs.

    Returns:
        The session (close it when done).
    """
    return Armor(args.client, namespace=args.namespace, timeout_s=args.timeout,
                 service_wait_s=args.wait, iris=iris)


def learn_commands(armor: Armor) -> None:
    """Teach the command table what the node's plugins add (nothing, from an older node)."""
    try:
        commands.learn(armor.catalogue().commands)
    except ArmorServiceInternalError:
        pass


def query_words(words: Sequence[str],
                trailing: Sequence[str]) -> Tuple[Tuple[str, str, str], List[str]]:
    """A QUERY as armor query and armor watch take it: its specs and its arguments.

    QUERY may be left out; the longest known combination of specs is taken, the rest are
    arguments; a lone "--" ends the specs early (its arguments are ``trailing``). Words that
    name no known combination (a misspelt spec) are split as typed, so that the node answers
    205 with the closest commands. Learn the node's plugins first (learn_commands).

    Args:
        words: the words before "--".
        trailing: the words after it.

    Returns:
        ((command, primary, secondary), arguments).
    """
    words = list(words)
    if words and words[0].upper() not in commands.next_words([]):
        words.insert(0, 'QUERY')
    if trailing:
        words += ['--', *trailing]
    command, arguments = commands.split_directive(words)
    if command is None:
        return commands.as_typed(words)
    return command.words, arguments


def reporting_errors(verb: str) -> Callable[[Callable[..., int]], Callable[..., int]]:
    """Turn ARMOR's errors into the armor command's exit statuses.

    A failed directive prints ``error CODE: description`` on stderr and exits 1; a service
    that cannot be reached exits 3, as armor call does.

    Args:
        verb: the verb's name, for messages.

    Returns:
        A decorator for the verb's run().
    """
    def decorate(run: Callable[..., int]) -> Callable[..., int]:
        @functools.wraps(run)
        def guarded(*args: Any) -> int:
            try:
                return run(*args)
            except ArmorServiceInternalError as error:
                print(f'error {error.exit_code}: {error.description}', file=sys.stderr)
                return EXIT_FAILED
            except ArmorServiceCallError as error:
                print(f'armor {verb}: {error}', file=sys.stderr)
                return EXIT_NO_SERVICE
        return guarded
    return decorate


def print_table(headers: Sequence[str], rows: Sequence[Sequence[Any]],
                out: Optional[TextIO] = None) -> None:
    """Print rows under headers in aligned columns, and a count line.

    Args:
        headers: the column titles.
        rows: the rows, as many cells as headers each (None prints as empty).
        out: where to print (default: stdout).
    """
    out = out or sys.stdout
    cells = [[_text(cell) for cell in row] for row in rows]
    widths = [max([len(header)] + [len(row[i]) for row in cells])
              for i, header in enumerate(headers)]
    print('  '.join(h.ljust(w) for h, w in zip(headers, widths)).rstrip(), file=out)
    print('  '.join('-' * w for w in widths), file=out)
    for row in cells:
        print('  '.join(c.ljust(w) for c, w in zip(row, widths)).rstrip(), file=out)
    print(f'({len(rows)} row{"" if len(rows) == 1 else "s"})', file=out)


def print_answer(response: Any, primary: str, secondary: str, iris: bool,
                 out: Optional[TextIO] = None) -> None:
    """Print a query's answer as a readable table.

    SPARQL rows get one column per variable; literals a value and a type column; entities
    one column of short names (IRIs with iris=True); QUERY CONSISTENCY its verdict first.

    Args:
        response: the ArmorDirectiveRes of a successful query.
        primary: the QUERY's primary spec.
        secondary: the QUERY's secondary spec.
        iris: show entities as IRIs.
        out: where to print (default: stdout).
    """
    out = out or sys.stdout
    key = (primary.upper(), secondary.upper())
    if key[0] == 'CONSISTENCY':
        print('consistent' if response.is_consistent else 'INCONSISTENT', file=out)
        if response.is_consistent:
            return
    if (len(response.queried_objects) == 1 and '\n' in response.queried_objects[0]
            and not is_literal(response.queried_objects[0])):
        # A document (a PDDL problem): its own lines, not a one-cell table as wide as it.
        print(response.queried_objects[0].rstrip('\n'), file=out)
    elif response.sparql_queried_objects:
        headers, rows = sparql_table(response.sparql_queried_objects, iris)
        print_table(headers, rows, out)
    elif response.queried_objects and all(is_literal(a) for a in response.queried_objects):
        print_table(['value', 'type'], [split_literal(a) for a in response.queried_objects], out)
    elif key in (('CLASS', 'RESTRICTIONS'), ('CONSISTENCY', '')):
        print_table([_ENTITY_COLUMN[key]], [[a] for a in Answers(iris).expressions(response)],
                    out)
    else:
        print_table([_ENTITY_COLUMN.get(key, 'answer')],
                    [[answer_value(a, iris)] for a in response.queried_objects], out)
    if response.timeout:
        print('(time limit reached: the rows found by then)', file=out)


def sparql_table(items: Sequence[Any], iris: bool) -> Tuple[List[str], List[List[Any]]]:
    """Headers and rows of a FORMATTED SPARQL answer (items with an empty key end rows).

    Args:
        items: the sparql_queried_objects.
        iris: show entities as IRIs.

    Returns:
        (variable names in order, one list of cells per row).
    """
    rows = [row for row in sparql_rows(items, iris) if row]
    headers = list(dict.fromkeys(key for row in rows for key in row))
    return headers, [[row.get(h) for h in headers] for row in rows]


def _text(cell: Any) -> str:
    if cell is None:
        return ''
    if isinstance(cell, bool):
        return 'true' if cell else 'false'
    return str(cell)
