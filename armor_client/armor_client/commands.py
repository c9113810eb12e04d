# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Every directive the service answers, as data: the knowledge core's own catalogue.

The core owns the list (``java -jar armor-core.jar --catalogue``; generated into
armor_contract's catalogue.json by ``make catalogue`` and checked against the core by a test),
so a command added in Java is parsed and completed here without a line of Python. The
command-line tools parse and complete directives with it, after learning from the running
node (``learn``) the commands its plugins add.
"""

from typing import Dict, Iterable, List, Optional, Sequence, Tuple

from armor_contract.catalogue import (  # noqa: F401  (the kinds are part of this module's API)
    Command, CREATING, DROPPING, GLOBAL, load, MANIPULATION, MOUNTING, QUERY, REFERENCE)

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
                return command, list(words[length:])
    return None, list(words)


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
