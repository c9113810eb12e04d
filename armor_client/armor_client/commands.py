# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Every directive the service answers (docs/commands.md), as data.

The command-line tools parse and complete directives with this table, and the client library
names, for every command, the method that sends it (``method``), so that a test can check
that nothing is missing on either side.
"""

from dataclasses import dataclass
from typing import Dict, List, Optional, Sequence, Tuple

QUERY = 'query'
MANIPULATION = 'manipulation'
REFERENCE = 'reference'
CREATING = 'creating'
GLOBAL = 'global'


@dataclass(frozen=True)
class Command:
    """One command / spec combination.

    Attributes:
        words: command, primary spec, secondary spec ('' for an empty spec).
        args: names of the arguments; a trailing '...' means "and more of the same".
        kind: QUERY (never mount-checked), MANIPULATION (refused under a foreign mount),
            REFERENCE (on an existing reference, no mount check), CREATING (makes the
            reference it names) or GLOBAL (needs no reference).
        method: the method of Reference (or Armor, for loading and the utilities) that sends it.
        summary: one line saying what it does.
    """

    words: Tuple[str, str, str]
    args: Tuple[str, ...]
    kind: str
    method: str
    summary: str

    @property
    def name(self) -> str:
        """The command as written in the docs: ``QUERY IND CLASS``."""
        return ' '.join(word for word in self.words if word)


def _command(words: str, args: str, kind: str, method: str, summary: str) -> Command:
    parts = (words.split() + ['', ''])[:3]
    return Command((parts[0], parts[1], parts[2]), tuple(args.split()), kind, method, summary)


COMMANDS: Tuple[Command, ...] = (
    # References and utilities
    _command('LOAD FILE', 'path iri buffered_manipulation reasoner buffered_reasoner', CREATING,
             'load_file', 'create the reference from a local ontology file'),
    _command('LOAD FILE MOUNTED', 'path iri buffered_manipulation reasoner buffered_reasoner',
             CREATING, 'load_file', 'load a file and mount the caller on it'),
    _command('LOAD WEB', 'url iri buffered_manipulation reasoner buffered_reasoner', CREATING,
             'load_web', 'create the reference from a URL (web_loading:=true only)'),
    _command('LOAD WEB MOUNTED', 'url iri buffered_manipulation reasoner buffered_reasoner',
             CREATING, 'load_web', 'load from a URL and mount the caller on it'),
    _command('CREATE', 'iri buffered_manipulation reasoner buffered_reasoner', CREATING, 'create',
             'create the reference as an empty ontology'),
    _command('SAVE', '[path] [format]', REFERENCE, 'save', 'write the ontology to a file'),
    _command('SAVE INFERENCE', '[path] [format]', REFERENCE, 'save',
             'write the ontology and its inferences to a file'),
    _command('DROP', '', REFERENCE, 'drop', 'unload the reference'),
    _command('MOUNT', '', REFERENCE, 'mount', 'become the only client allowed to change it'),
    _command('UNMOUNT', '', REFERENCE, 'unmount', 'release the mount'),
    _command('GET ALL REFS', '', GLOBAL, 'references', 'names of the loaded references'),
    _command('GET REF CLIENT', '[reference]', GLOBAL, 'mounted_by',
             'the client that holds the mount, if any'),
    _command('LOG SCREEN ON', '', GLOBAL, 'log_to_screen', "log directives on the node's screen"),
    _command('LOG SCREEN OFF', '', GLOBAL, 'log_to_screen', 'stop logging to the screen'),
    _command('LOG FILE ON', 'path', GLOBAL, 'log_to_file', 'log directives to a file'),
    _command('LOG FILE OFF', '', GLOBAL, 'log_to_file', 'stop logging to a file'),
    _command('APPLY', '', MANIPULATION, 'apply', 'apply the buffered manipulations'),
    _command('REASON', '', MANIPULATION, 'reason', 'apply the buffer and update the reasoner'),
    # Manipulations
    _command('ADD IND', 'ind', MANIPULATION, 'add_individual', 'declare an individual'),
    _command('ADD IND CLASS', 'ind class', MANIPULATION, 'add_individual_to_class',
             'assert that the individual belongs to the class'),
    _command('REMOVE IND', 'ind', MANIPULATION, 'remove_individual',
             'remove every axiom that mentions the individual'),
    _command('REMOVE IND CLASS', 'ind class', MANIPULATION, 'remove_individual_from_class',
             'remove that class assertion'),
    _command('ADD IND SAME', 'ind ind ...', MANIPULATION, 'add_same_individuals',
             'assert that the individuals are the same'),
    _command('REMOVE IND SAME', 'ind ind ...', MANIPULATION, 'remove_same_individuals',
             'remove that SameIndividual axiom'),
    _command('DISJOINT IND', 'ind ind ...', MANIPULATION, 'make_individuals_different',
             'assert that the individuals are different'),
    _command('DISJOINT IND CLASS', 'class', MANIPULATION, 'make_instances_different',
             'make all instances of the class different from each other'),
    _command('ADD CLASS', 'class', MANIPULATION, 'add_class', 'declare a class'),
    _command('ADD CLASS CLASS', 'sub super', MANIPULATION, 'add_subclass',
             'assert that sub is a subclass of super'),
    _command('REMOVE CLASS', 'class', MANIPULATION, 'remove_class',
             'remove every axiom that mentions the class'),
    _command('REMOVE CLASS CLASS', 'sub super', MANIPULATION, 'remove_subclass',
             'remove that SubClassOf axiom'),
    _command('DISJOINT CLASS', 'class class ...', MANIPULATION, 'make_classes_disjoint',
             'assert that the classes are disjoint'),
    _command('DISJOINT CLASS CLASS', 'class', MANIPULATION, 'make_subclasses_disjoint',
             'make the direct subclasses of the class disjoint'),
    _command('MAKE EQUIVALENT CLASS', 'class', MANIPULATION, 'make_equivalent_to_superclasses',
             'turn its SubClassOf axioms into one EquivalentClasses'),
    _command('ADD CLASS EQUIVALENT', 'class expression', MANIPULATION, 'add_equivalent_class',
             'define the class by a Manchester class expression'),
    _command('REMOVE CLASS EQUIVALENT', 'class expression', MANIPULATION,
             'remove_equivalent_class', 'remove that definition'),
    _command('ADD CARDINALITY MIN', 'class prop n value_class', MANIPULATION,
             'add_min_cardinality', 'class SubClassOf prop min n value_class'),
    _command('ADD DATAPROP IND', 'prop ind type value', MANIPULATION, 'add_data_value',
             'give the individual a data property value'),
    _command('REMOVE DATAPROP IND', 'prop ind type value', MANIPULATION, 'remove_data_value',
             'remove that data property value'),
    _command('REPLACE DATAPROP IND', 'prop ind type new old', MANIPULATION, 'replace_data_value',
             'replace one data property value by another'),
    _command('ADD OBJECTPROP IND', 'prop ind value', MANIPULATION, 'add_object_value',
             'relate the individual to another'),
    _command('REMOVE OBJECTPROP IND', 'prop ind value', MANIPULATION, 'remove_object_value',
             'remove that relation'),
    _command('REPLACE OBJECTPROP IND', 'prop ind new old', MANIPULATION, 'replace_object_value',
             'replace one related individual by another'),
    _command('ADD OBJECTPROP OBJECTPROP', 'sub super', MANIPULATION, 'add_object_subproperty',
             'object sub-property axiom'),
    _command('REMOVE OBJECTPROP OBJECTPROP', 'sub super', MANIPULATION,
             'remove_object_subproperty', 'remove that axiom'),
    _command('ADD DATAPROP DATAPROP', 'sub super', MANIPULATION, 'add_data_subproperty',
             'data sub-property axiom'),
    _command('REMOVE DATAPROP DATAPROP', 'sub super', MANIPULATION, 'remove_data_subproperty',
             'remove that axiom'),
    _command('ADD OBJECTPROP INVERSE', 'prop inverse', MANIPULATION, 'add_inverse_property',
             'assert that two object properties are inverses'),
    _command('REMOVE OBJECTPROP INVERSE', 'prop inverse', MANIPULATION,
             'remove_inverse_property', 'remove that axiom'),
    _command('ADD OBJECTPROP CHARACTERISTIC', 'prop characteristic', MANIPULATION,
             'add_object_characteristic', 'FUNCTIONAL, TRANSITIVE, SYMMETRIC, ...'),
    _command('REMOVE OBJECTPROP CHARACTERISTIC', 'prop characteristic', MANIPULATION,
             'remove_object_characteristic', 'remove that characteristic'),
    _command('ADD DATAPROP CHARACTERISTIC', 'prop characteristic', MANIPULATION,
             'add_data_characteristic', 'FUNCTIONAL'),
    _command('REMOVE DATAPROP CHARACTERISTIC', 'prop characteristic', MANIPULATION,
             'remove_data_characteristic', 'remove that characteristic'),
    _command('ADD OBJECTPROP DOMAIN', 'prop class', MANIPULATION, 'add_object_domain',
             'object property domain'),
    _command('REMOVE OBJECTPROP DOMAIN', 'prop class', MANIPULATION, 'remove_object_domain',
             'remove that domain'),
    _command('ADD OBJECTPROP RANGE', 'prop class', MANIPULATION, 'add_object_range',
             'object property range'),
    _command('REMOVE OBJECTPROP RANGE', 'prop class', MANIPULATION, 'remove_object_range',
             'remove that range'),
    _command('ADD DATAPROP DOMAIN', 'prop class', MANIPULATION, 'add_data_domain',
             'data property domain'),
    _command('REMOVE DATAPROP DOMAIN', 'prop class', MANIPULATION, 'remove_data_domain',
             'remove that domain'),
    _command('ADD DATAPROP RANGE', 'prop datatype', MANIPULATION, 'add_data_range',
             'data property range'),
    _command('REMOVE DATAPROP RANGE', 'prop datatype', MANIPULATION, 'remove_data_range',
             'remove that range'),
    _command('ADD AXIOM', 'axiom', MANIPULATION, 'add_axiom',
             'one axiom in Manchester or functional syntax'),
    _command('REMOVE AXIOM', 'axiom', MANIPULATION, 'remove_axiom', 'remove that axiom'),
    _command('ADD SWRL', 'name rule', MANIPULATION, 'add_rule', 'add a SWRL rule'),
    _command('REMOVE SWRL', 'name rule', MANIPULATION, 'remove_rule', 'remove a SWRL rule'),
    _command('RENAME IND', 'old new', MANIPULATION, 'rename_individual', 'rename an individual'),
    _command('RENAME CLASS', 'old new', MANIPULATION, 'rename_class', 'rename a class'),
    _command('RENAME DATAPROP', 'old new', MANIPULATION, 'rename_data_property',
             'rename a data property'),
    _command('RENAME OBJECTPROP', 'old new', MANIPULATION, 'rename_object_property',
             'rename an object property'),
    # Queries
    _command('QUERY IND', 'ind', QUERY, 'types_of', 'the classes of the individual'),
    _command('QUERY IND CLASS', 'class', QUERY, 'instances', 'the instances of the class'),
    _command('QUERY IND DL', 'expression', QUERY, 'dl_instances',
             'the instances of a Manchester class expression'),
    _command('QUERY CLASS IND', 'ind [most_specific]', QUERY, 'classes_of',
             'the classes of the individual, optionally the most specific only'),
    _command('QUERY IND SAME', 'ind', QUERY, 'same_individuals', 'individuals equal to it'),
    _command('QUERY IND DATAPROP', 'ind', QUERY, 'data_properties_of',
             'the data properties that have values for it'),
    _command('QUERY IND OBJECTPROP', 'ind', QUERY, 'object_properties_of',
             'the object properties that have values for it'),
    _command('QUERY DATAPROP IND', 'prop ind', QUERY, 'data_values', 'its values of the property'),
    _command('QUERY OBJECTPROP IND', 'prop ind', QUERY, 'object_values',
             'the individuals it is related to by the property'),
    _command('QUERY CLASS CLASS', 'class', QUERY, 'subclasses', 'subclasses, all levels'),
    _command('QUERY CLASS DL', 'expression', QUERY, 'dl_subclasses',
             'the subclasses of a Manchester class expression'),
    _command('QUERY CLASS SUPER', 'class', QUERY, 'superclasses', 'superclasses'),
    _command('QUERY CLASS EQUIVALENT', 'class', QUERY, 'equivalent_classes', 'equivalent classes'),
    _command('QUERY CLASS DISJOINT', 'class', QUERY, 'disjoint_classes', 'disjoint classes'),
    _command('QUERY CLASS RESTRICTIONS', 'class', QUERY, 'restrictions',
             'its restrictions, Manchester syntax'),
    _command('QUERY OBJECTPROP OBJECTPROP', 'prop', QUERY, 'object_subproperties',
             'sub-properties of an object property'),
    _command('QUERY DATAPROP DATAPROP', 'prop', QUERY, 'data_subproperties',
             'sub-properties of a data property'),
    _command('QUERY SPARQL', 'query [timeout_ms]', QUERY, 'sparql_lines',
             'SPARQL SELECT or ASK, one string per row'),
    _command('QUERY SPARQL FORMATTED', 'query [timeout_ms]', QUERY, 'sparql',
             'SPARQL SELECT or ASK, rows as variable/value pairs'),
    _command('QUERY CONSISTENCY', '', QUERY, 'check_consistency',
             'is it consistent, and if not, why'),
)

_BY_WORDS: Dict[Tuple[str, str, str], Command] = {c.words: c for c in COMMANDS}
# ARMOR's own spelling of the cardinality command.
_BY_WORDS[('ADD', 'MIN', 'CARDINALITY')] = _BY_WORDS[('ADD', 'CARDINALITY', 'MIN')]


def find(command: str, primary: str = '', secondary: str = '') -> Optional[Command]:
    """The catalogue entry of a directive, matching words case-insensitively ('-' = empty).

    Args:
        command: the command word.
        primary: the primary spec.
        secondary: the secondary spec.

    Returns:
        The entry, or None when the service does not answer that combination.
    """
    key = tuple('' if w == '-' else w.upper() for w in (command, primary, secondary))
    return _BY_WORDS.get(key)


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
