# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""An interactive prompt: type directives, see answers as tables.

  armor shell [REF]

At the prompt, type a directive as COMMAND [PRIMARY [SECONDARY]] ARGS..., quoting arguments
with spaces ("Agent and isIn some Room"); the specs end where the longest known command does,
or at "--". Tab completes commands and specs, then names of classes, individuals and
properties of the current reference. History is kept in ~/.armor_shell_history.
Shell commands:
  use REF      address REF from now on        refs     list the references
  help [CMD]   commands, or one in detail     names    reload the names for completion
  quit         leave (also Ctrl-D)
Lines read from a pipe run the same way, without prompt, so a file of directives is a script.
"""

import argparse
import os
import shlex
import sys
from typing import Callable, Iterable, List, Optional, TextIO

from armor_client import commands
from armor_client.cli.common import (add_connection_arguments, connect, learn_commands,
                                     print_answer, print_table)
from armor_client.errors import ArmorError, error_for
from armor_client.operations import Characteristic, Reasoner
from armor_client.reference import Armor

HISTORY_FILE = os.path.join(os.path.expanduser('~'), '.armor_shell_history')
SHELL_COMMANDS = ('help', 'names', 'quit', 'refs', 'use')
# Every class, property and individual (typed or declared) of a reference.
NAMES_QUERY = ('SELECT DISTINCT ?entity WHERE { { ?entity a owl:Class } UNION '
               '{ ?entity a owl:ObjectProperty } UNION { ?entity a owl:DatatypeProperty } UNION '
               '{ ?entity a owl:NamedIndividual } UNION { ?entity a ?class . ?class a owl:Class } '
               'FILTER(isIRI(?entity)) }')
# Words that are arguments of some changes but not names: offered after every change.
KEYWORDS = tuple(sorted({*(r.value for r in Reasoner), *(c.value for c in Characteristic),
                         'STRING', 'INTEGER', 'LONG', 'DOUBLE', 'FLOAT', 'BOOLEAN', 'true',
                         'false', 'rdfxml', 'owlxml', 'turtle', 'functional', 'manchester'}))


class Completer:
    """What Tab offers, given the line so far; knows nothing of readline or ROS.

    Args:
        names: returns the entity names of the current reference (called when needed).
        references: returns the loaded reference names.
    """

    def __init__(self, names: Callable[[], Iterable[str]],
                 references: Callable[[], Iterable[str]]):
        self._names = names
        self._references = references

    def candidates(self, line: str) -> List[str]:
        """The completions of the last (partial) word of a line.

        Args:
            line: the text before the cursor.

        Returns:
            The sorted candidates that start with the partial word.
        """
        words = line.split()
        partial = '' if not words or line[-1:].isspace() else words.pop()
        if not words:
            pool = list(SHELL_COMMANDS) + commands.next_words([])
        elif words[0] == 'use':
            pool = list(self._references()) if len(words) == 1 else []
        elif words[0] == 'help':
            pool = commands.next_words(words[1:])
        else:
            command, _ = commands.split_directive(words)
            pool = [] if '--' in words else commands.next_words(words)
            if command is not None:
                pool += list(self._names())
                if command.kind != commands.QUERY:
                    pool += KEYWORDS
        if partial.isupper() or not partial:
            matches = [w for w in pool if w.startswith(partial)]
        else:
            # Command words complete case-insensitively, names exactly.
            matches = [w for w in pool if w.startswith(partial)
                       or (w.isupper() and w.startswith(partial.upper()))]
        return sorted(set(matches))


class Shell:
    """The prompt's state and its commands.

    Args:
        armor: the session that sends the directives.
        reference: the reference addressed at first ('' for none).
        iris: show entities as IRIs.
        out: where answers go.
    """

    def __init__(self, armor: Armor, reference: str, iris: bool, out: TextIO):
        self.armor = armor
        self.reference = reference
        self.iris = iris
        self.out = out
        self._names: Optional[List[str]] = None
        self.completer = Completer(self.names, armor.references)

    @property
    def prompt(self) -> str:
        """``armor:REF> ``."""
        return f'armor:{self.reference or "-"}> '

    def names(self) -> List[str]:
        """Short names of the current reference's entities, fetched once per change."""
        if self._names is None:
            self._names = []
            if self.reference:
                rows = self.armor.reference(self.reference).sparql(NAMES_QUERY)
                self._names = sorted({row['entity'] for row in rows})
        return self._names

    def run_line(self, line: str) -> bool:
        """Run one line.

        Args:
            line: what was typed.

        Returns:
            False when the shell should end.
        """
        try:
            words = shlex.split(line, comments=True)
        except ValueError as error:
            print(f'cannot read that line: {error}', file=self.out)
            return True
        if not words:
            return True
        verb = words[0]
        if verb in ('quit', 'exit'):
            return False
        try:
            if verb == 'use':
                self._use(words[1:])
            elif verb == 'refs':
                self._refs()
            elif verb == 'help':
                self._help(words[1:])
            elif verb == 'names':
                self._names = None
                print(f'{len(self.names())} names', file=self.out)
            else:
                self._directive(words)
        except ArmorError as error:
            code = '' if error.exit_code is None else f' {error.exit_code}'
            print(f'error{code}: {error.description}', file=self.out)
        except RuntimeError as error:
            print(f'error: {error}', file=self.out)
        return True

    def _use(self, words: List[str]) -> None:
        if len(words) != 1:
            print('use REF', file=self.out)
            return
        loaded = self.armor.references()
        if words[0] not in loaded:
            # Now, not at the next directive: a typo in the name would only show up later as 206.
            print(f'error: no reference named {words[0]!r} is loaded (loaded: '
                  f'{", ".join(loaded) or "none"}); still using {self.reference or "none"}',
                  file=self.out)
            return
        self.reference = words[0]
        self._names = None

    def _refs(self) -> None:
        rows = [[name, self.armor.mounted_by(name) or '-'] for name in self.armor.references()]
        print_table(['reference', 'mounted by'], rows, self.out)

    def _help(self, words: List[str]) -> None:
        typed = [w.upper() for w in words]
        chosen = [c for c in commands.COMMANDS if c.name.split()[:len(typed)] == typed]
        if not chosen:
            print(f'no command starts with {" ".join(words)}', file=self.out)
        for entry in chosen:
            print(f'{entry.name:34} {" ".join(entry.args):34} {entry.summary}', file=self.out)

    def _directive(self, words: List[str]) -> None:
        command, arguments = commands.split_directive(words)
        if command is None:
            # Sent as typed: the node answers 205 with the commands closest to it.
            typed, arguments = commands.as_typed(words)
            response = self.armor.call(self.reference, *typed, arguments)
            if not response.success:
                raise error_for(response)
            for item in response.queried_objects:
                print(item, file=self.out)
            return
        sent = command.words
        if sent == ('QUERY', 'SPARQL', ''):
            # Rows as variable/value pairs, so that the table's columns carry the query's names.
            sent = ('QUERY', 'SPARQL', 'FORMATTED')
        response = self.armor.call(self.reference, *sent, arguments)
        if not response.success:
            raise error_for(response)
        if response.error_description:
            # A success that says something: a name new to the reference (a typo?), a value
            # not found.
            print(f'note: {response.error_description}', file=self.out)
        if command.kind == commands.QUERY:
            print_answer(response, command.words[1], command.words[2], self.iris, self.out)
        elif response.queried_objects:
            for item in response.queried_objects:
                print(item, file=self.out)
        else:
            state = 'consistent' if response.is_consistent else 'INCONSISTENT'
            print(f'ok ({state})', file=self.out)
        if command.kind != commands.QUERY:
            self._names = None


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the options of armor shell.

    Args:
        parser: the verb's parser.
    """
    parser.add_argument('reference', metavar='REF', nargs='?', default='',
                        help='the reference to address first')
    parser.add_argument('--iri', action='store_true', help='show full IRIs, not short names')
    add_connection_arguments(parser)


def run(args: argparse.Namespace) -> int:
    """Read and run lines until quit or end of input.

    Args:
        args: the parsed command line.

    Returns:
        0.
    """
    interactive = sys.stdin.isatty()
    with connect(args) as armor:
        learn_commands(armor)
        shell = Shell(armor, args.reference, args.iri, sys.stdout)
        if interactive:
            _interactive(shell)
        else:
            for line in sys.stdin:
                if not shell.run_line(line):
                    break
    return 0


def _interactive(shell: Shell) -> None:
    import readline
    readline.set_completer_delims(' \t\n"\'')
    readline.parse_and_bind('tab: complete')
    matches: List[str] = []

    def complete(text: str, state: int) -> Optional[str]:
        if state == 0:
            # Python's readline appends nothing to a completed word: the space is added here, so
            # that a unique match is followed by a space, as in other shells.
            matches[:] = [m + ' ' for m in shell.completer.candidates(readline.get_line_buffer()[
                :readline.get_endidx()])]
        return matches[state] if state < len(matches) else None

    readline.set_completer(complete)
    try:
        readline.read_history_file(HISTORY_FILE)
    except OSError:
        pass  # no history yet
    print('ARMOR shell: help lists the commands, Tab completes, quit leaves.')
    try:
        while True:
            try:
                line = input(shell.prompt)
            except EOFError:
                print()
                break
            except KeyboardInterrupt:
                print()
                continue
            if not shell.run_line(line):
                break
    finally:
        readline.write_history_file(HISTORY_FILE)
