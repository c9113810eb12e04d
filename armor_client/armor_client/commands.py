# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Every directive the service answers, as data: the knowledge core's own catalogue.

The core owns the list (``java -jar armor-core.jar --catalogue``; generated into
armor_contract's catalogue.json by ``make catalogue`` and checked against the core by a test),
so a command added in Java is parsed and completed here without a line of Python. The
command-line tools parse and complete directives with it, after learning from the running
node (``learn``) the commands its plugins add.
"""

import difflib
import json
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple

from armor_contract.catalogue import (  # noqa: F401  (the kinds are part of this module's API)
    Command, CREATING, DROPPING, GLOBAL, load, MANIPULATION, MOUNTING, parse, QUERY, REFERENCE)

COMMANDS: Tuple[Command, ...] = load().commands

_BY_WORDS: Dict[Tuple[str, str, str], Command] = {
    words: command for command in COMMANDS for words in (command.words, *command.aliases)}


def learn(answered: Iterable[Command]) -> List[Command]:
    """Add what a running node answers beyond the shipped catalogue (plugins' commands).

    Args:
        answered: the commands of the node's own catalogue (GET CATALOGUE).

    Returns:
        The commands that were new here.
    """
    global COMMANDS
    added = [command for command in answered if command.words not in _BY_WORDS]
    for command in added:
        for words in (command.words, *command.aliases):
            _BY_WORDS.setdefault(words, command)
    COMMANDS = COMMANDS + tuple(added)
    return added


def find_on(transport: Any, command: str, primary: str = '',
            secondary: str = '') -> Optional[Command]:
    """find(), after learning the node's catalogue when the words are unknown here.

    A plugin's commands are known only to the node that loaded it; a client that needs their
    argument names (which are paths) asks the node once, through ``transport``.

    Args:
        transport: an ArmorTransport to the node.
        command: the command word.
        primary: the primary spec.
        secondary: the secondary spec.

    Returns:
        The entry, or None when the node does not answer that combination either.
    """
    found = find(command, primary, secondary)
    if found is None and command.strip():
        from armor_client.transport import directive
        response = transport.call(directive('armor_cli', '', 'GET', 'CATALOGUE'))
        if response.success and response.queried_objects:
            learn(parse(json.loads(response.queried_objects[0])).commands)
            found = find(command, primary, secondary)
    return found


def find(command: str, primary: str = '', secondary: str = '') -> Optional[Command]:
    """The catalogue entry of a directive, matching words case-insensitively ('-' = empty).

    Args:
        command: the command word.
        primary: the primary spec.
        secondary: the secondary spec.

    Returns:
        The entry, or None when the service does not answer that combination.
    """
    words = ['' if w == '-' else w.upper() for w in (command, primary, secondary)]
    return _BY_WORDS.get((words[0], words[1], words[2]))


def split_directive(words: Sequence[str]) -> Tuple[Optional[Command], List[str]]:
    """Split typed words into a command and its arguments, taking the longest known command.

    ``['QUERY', 'IND', 'CLASS', 'Room']`` is QUERY IND CLASS with the argument ``Room``;
    ``['QUERY', 'IND', 'robot1']`` is QUERY IND with ``robot1``. A ``--`` word ends the
    command early, for arguments that are spelled like specs.

    Args:
        words: the words as typed (command, specs, then arguments).

    Returns:
        (command, arguments); the command is None when no known command starts the words.
    """
    if '--' in words:
        cut = list(words).index('--')
        return find(*words[:cut][:3]) if 0 < cut <= 3 else None, list(words[cut + 1:])
    for length in (3, 2, 1):
        if len(words) >= length:
            command = find(*words[:length])
            if command is not None:
                arguments = list(words[length:])
                if length < 3 and _misspelt_spec(words[:length], command, arguments):
                    return None, arguments[1:]
                return command, arguments
    return None, list(words)


def as_typed(words: Sequence[str]) -> Tuple[Tuple[str, str, str], List[str]]:
    """The specs and arguments of words that name no known command, split as the user meant.

    Sent so, the node answers 205 naming the closest commands (``QUERY IND CLAS Room`` is
    QUERY IND CLAS with ``Room``, not QUERY IND with two arguments). The specs are the longest
    known start plus the next word, or, when even the first word is unknown, it and the words
    after it written like it (letters, in the same case); ``--`` ends them early.

    Args:
        words: the words as typed.

    Returns:
        ((command, primary, secondary), arguments).

    Raises:
        RuntimeError: more than three words before ``--``.
    """
    words = list(words)
    if '--' in words:
        cut = words.index('--')
        if cut > 3:
            raise RuntimeError('at most COMMAND PRIMARY SECONDARY before "--"; put the arguments '
                               f'after "--" (got {" ".join(words[:cut])})')
        specs, arguments = words[:cut], words[cut + 1:]
    else:
        known = next((n for n in (2, 1) if len(words) > n and find(*words[:n])), 0)
        count = known + 1
        while (not known and count < min(3, len(words)) and words[count].isalpha()
               and words[count].isupper() == words[0].isupper()):
            count += 1
        specs, arguments = words[:count], words[count:]
    command, primary, secondary = (specs + ['', '', ''])[:3]
    return (command, primary, secondary), arguments


def _misspelt_spec(typed: Sequence[str], command: Command, arguments: Sequence[str]) -> bool:
    """Whether the first argument is rather a misspelt spec.

    So it is when the command cannot take the arguments as they are, and that word is close
    to a spec that can follow.
    """
    count = len(arguments)
    takes = len(command.required) <= count and (
        command.variadic or count <= len(command.required) + len(command.optional))
    return (not takes and bool(arguments)
            and bool(difflib.get_close_matches(arguments[0].upper(), next_words(typed), n=1,
                                               cutoff=0.75)))


def next_words(typed: Sequence[str]) -> List[str]:
    """The words that can follow ``typed`` in a command (for completion).

    Args:
        typed: the complete words typed so far (``['QUERY']``, ``['QUERY', 'IND']``).

    Returns:
        The possible next command or spec words, sorted; empty once a command is complete and
        nothing longer starts with it.
    """
    upper = [word.upper() for word in typed]
    candidates = set()
    for words in _BY_WORDS:
        present = [word for word in words if word]
        if len(present) > len(upper) and present[:len(upper)] == upper:
            candidates.add(present[len(upper)])
    return sorted(candidates)
