# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The core's catalogue, read from the generated catalogue.json.

The knowledge core owns what exists: each command with its kind and arguments, each exit
code, each setting with its type and default. ``make catalogue`` writes its answer to
``--catalogue`` here; nothing in this file is written by hand.
"""

import functools
import json
from dataclasses import dataclass
from importlib import resources
from typing import Any, Dict, Optional, Tuple

# Kinds of command (CommandKind.java): how the core runs a directive.
QUERY = 'query'
MANIPULATION = 'manipulation'
MOUNTING = 'mounting'
DROPPING = 'dropping'
REFERENCE = 'reference'
CREATING = 'creating'
GLOBAL = 'global'


@dataclass(frozen=True)
class FaceParameter:
    """One parameter of a command's client method: its name and type (``string`` or ``int``)."""

    name: str
    type: str


@dataclass(frozen=True)
class Face:
    """The method a command has in the clients (its registration's ``face``).

    Attributes:
        method: the method's name, the same in Python and C++.
        answer: what it returns: ``none``, ``entities``, ``values`` or ``expressions``.
        parameters: one per required argument; a variadic command's one list.
    """

    method: str
    answer: str
    parameters: Tuple[FaceParameter, ...]


@dataclass(frozen=True)
class Command:
    """One command / spec combination.

    Attributes:
        words: command, primary spec, secondary spec ('' for an empty spec).
        aliases: other spellings of the words that the core answers the same way.
        kind: QUERY (never mount-checked), MANIPULATION (refused under a foreign mount),
            MOUNTING (MOUNT, UNMOUNT), DROPPING (DROP), REFERENCE (on an existing reference,
            changes nothing), CREATING (makes the reference it names) or GLOBAL (needs none).
        required: names of the arguments it needs.
        optional: names of the arguments it may take after them.
        variadic: the last required argument may be repeated.
        changes_ontology: whether it can change what an ontology says.
        summary: one line saying what it does.
        origin: ``core`` for a built-in command, else the file name of the plugin jar.
        face: its client method, when its registration declares one.
    """

    words: Tuple[str, str, str]
    aliases: Tuple[Tuple[str, str, str], ...]
    kind: str
    required: Tuple[str, ...]
    optional: Tuple[str, ...]
    variadic: bool
    changes_ontology: bool
    summary: str
    origin: str = 'core'
    face: Optional[Face] = None

    @property
    def name(self) -> str:
        """The command as written in the docs: ``QUERY IND CLASS``."""
        return ' '.join(word for word in self.words if word)

    @property
    def path_positions(self) -> Tuple[int, ...]:
        """Which arguments name a file on the node's machine: those named with the word path."""
        return tuple(i for i, name in enumerate(self.required + self.optional)
                     if 'path' in name.split())

    @property
    def args(self) -> Tuple[str, ...]:
        """Argument names as a usage line shows them: ``ind``, ``[path]``, ``...``."""
        shown = [name.replace(' ', '_') for name in self.required]
        shown += [f'[{name.replace(" ", "_")}]' for name in self.optional]
        return tuple(shown + (['...'] if self.variadic else []))


@dataclass(frozen=True)
class ExitCodeEntry:
    """One exit code: its number, its name in ExitCode.java, and what it means."""

    code: int
    name: str
    meaning: str


@dataclass(frozen=True)
class Setting:
    """One setting of the core.

    Attributes:
        key: its name, the same as the node's parameter.
        type: 'boolean', 'integer', 'double', 'string' or 'string_array'.
        default: the core's default.
        description: what it sets.
        read_only: whether it takes effect only at start.
    """

    key: str
    type: str
    default: Any
    description: str
    read_only: bool


@dataclass(frozen=True)
class Catalogue:
    """Everything the core offers."""

    commands: Tuple[Command, ...]
    exit_codes: Tuple[ExitCodeEntry, ...]
    settings: Tuple[Setting, ...]

    def setting(self, key: str) -> Optional[Setting]:
        """The setting of that key, or None."""
        return next((s for s in self.settings if s.key == key), None)


def _words(key: str) -> Tuple[str, str, str]:
    parts = ['' if word == '-' else word for word in key.split()] + ['', '']
    return (parts[0], parts[1], parts[2])


def _face(data: Optional[Dict[str, Any]]) -> Optional[Face]:
    if not data:
        return None
    return Face(data['method'], data['answer'],
                tuple(FaceParameter(p['name'], p['type']) for p in data['parameters']))


def parse(data: Dict[str, Any]) -> Catalogue:
    """A catalogue from the core's JSON (``--catalogue`` or the ``catalogue`` socket operation).

    Args:
        data: the decoded JSON object.

    Returns:
        The catalogue.
    """
    commands = tuple(Command(
        words=_words(entry['key']), aliases=tuple(_words(a) for a in entry['aliases']),
        kind=entry['kind'], required=tuple(entry['args']['required']),
        optional=tuple(entry['args']['optional']), variadic=entry['args']['variadic'],
        changes_ontology=entry['changes_ontology'], summary=entry['summary'],
        origin=entry.get('origin', 'core'), face=_face(entry.get('face')))
        for entry in data['commands'])
    codes = tuple(ExitCodeEntry(e['code'], e['name'], e['meaning']) for e in data['exit_codes'])
    settings = tuple(Setting(s['key'], s['type'], s['default'], s['description'], s['read_only'])
                     for s in data['settings'])
    return Catalogue(commands, codes, settings)


@functools.lru_cache(maxsize=None)
def load() -> Catalogue:
    """The catalogue of the core this package was generated from (catalogue.json)."""
    text = resources.files('armor_contract').joinpath('catalogue.json').read_text('utf-8')
    return parse(json.loads(text))
