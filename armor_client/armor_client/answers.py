# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""What the client's methods answer, and how a directive's response becomes that answer.

The answer types (Consistency, ChangeHistory, SparqlRows) and ``Answers``, the readers a
method hands with its directive: the generated methods (faces.py) and the hand-written ones
(operations.py) alike.
"""

import json
import re
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

from armor_client.values import answer_value, entity_iri, short_name, Value

Words = Tuple[str, str, str]
Parser = Callable[[Any], Any]


@dataclass(frozen=True)
class Consistency:
    """The answer of QUERY CONSISTENCY.

    Attributes:
        consistent: whether the ontology is consistent.
        explanation: when it is not, the axioms that cause it (Manchester syntax).
    """

    consistent: bool
    explanation: List[str] = field(default_factory=list)

    def __bool__(self) -> bool:
        return self.consistent


@dataclass(frozen=True)
class AcknowledgedChange:
    """One acknowledged change of a reference, as GET REF CHANGES answers it.

    Attributes:
        revision: the reference's revision after it.
        directives: its directives (one, or an atomic list's), each a dict keyed by the
            armor_msgs field names: client_name, command, primary_command_spec,
            secondary_command_spec, args (and reference_name).
    """

    revision: int
    directives: List[Dict[str, Any]]

    def includes(self, command: str, args: Sequence[Any],
                 client_name: Optional[str] = None) -> bool:
        """Whether it holds this directive (command words and arguments as they were sent).

        Example: ``change.includes('ADD IND CLASS', ['box1', 'Box'], 'planner')``.
        """
        wanted = _command_words(command)
        sent = [str(arg) for arg in args]
        return any(_command_words(' '.join((d['command'], d['primary_command_spec'],
                                            d['secondary_command_spec']))) == wanted
                   and list(d['args']) == sent
                   and (client_name is None or d['client_name'] == client_name)
                   for d in self.directives)


class ChangeHistory(list):
    """GET REF CHANGES: the AcknowledgedChange objects after a revision, oldest first.

    Attributes:
        complete: False when some changes after that revision are no longer kept (the node
            keeps a reference's latest 10,000 changes), or when the answer holds only the first
            of them; ``note`` then says which.
        more_after: the revision to ask from again for the changes one answer left out (an
            answer holds at most 1,000 changes or 1 MiB), or None when none were.
    """

    def __init__(self, changes: Sequence[AcknowledgedChange], note: str):
        super().__init__(changes)
        self.note = note
        self.complete = not note
        more = re.search(r'more changes after revision (\d+)', note)
        self.more_after = int(more.group(1)) if more else None


def _command_words(command: str) -> Tuple[str, ...]:
    return tuple(w.upper() for w in command.split() if w not in ('', '-'))


def _change_history(response: Any) -> ChangeHistory:
    changes = []
    for text in response.queried_objects:
        record = json.loads(text)
        changes.append(AcknowledgedChange(int(record['revision']), list(record['directives'])))
    return ChangeHistory(changes, response.error_description)


class SparqlRows(list):
    """SPARQL answer rows (a list); ``timed_out`` says the time limit cut the answer short."""

    def __init__(self, rows: Sequence[Any] = (), timed_out: bool = False):
        super().__init__(rows)
        self.timed_out = timed_out


_BRACKETED_IRI = re.compile(r'<([^<>\s]+)>')


def sparql_cell(text: str, iris: bool) -> Optional[Value]:
    """One SPARQL cell, decoded.

    None when unbound, a bool for true/false (ASK), a blank node as is, else a literal's value
    or an entity's name.
    """
    if not text:
        return None
    if text in ('true', 'false'):
        return text == 'true'
    if text.startswith('_:'):
        return text
    return answer_value(text, iris)


def sparql_rows(items: Sequence[Any], iris: bool) -> List[Dict[str, Optional[Value]]]:
    """FORMATTED SPARQL items as one dict per row (an item with an empty key ends a row).

    The one decoder of SPARQL rows: the client's answers and the command line's tables.

    Args:
        items: sparql_queried_objects (key/value items).
        iris: give entities as full IRIs instead of short names.

    Returns:
        The rows, variable -> value, in the order the core sent them.
    """
    rows: List[Dict[str, Optional[Value]]] = []
    row: Dict[str, Optional[Value]] = {}
    for item in items:
        if not item.key:
            rows.append(row)
            row = {}
        else:
            row[item.key] = sparql_cell(item.value, iris)
    if row:
        rows.append(row)
    return rows


class Answers:
    """How to read answers: entities as short names, or as IRIs when ``iris`` is True."""

    def __init__(self, iris: bool):
        self.iris = iris

    def entity(self, answer: str) -> str:
        """One answered entity as a short name or an IRI."""
        return entity_iri(answer) if self.iris else short_name(answer)

    def entities(self, response: Any) -> List[str]:
        """queried_objects as entity names."""
        return [self.entity(answer) for answer in response.queried_objects]

    def values(self, response: Any) -> List[Value]:
        """queried_objects as Python values: literals converted, entities named."""
        return [answer_value(answer, self.iris) for answer in response.queried_objects]

    def expressions(self, response: Any) -> List[str]:
        """queried_objects as Manchester text, with short names unless iris is True."""
        if self.iris:
            return list(response.queried_objects)
        return [_BRACKETED_IRI.sub(lambda m: short_name(m.group(1)), text)
                for text in response.queried_objects]

    def rows(self, response: Any) -> SparqlRows:
        """sparql_queried_objects (FORMATTED) as one dict per row; unbound variables are None."""
        return SparqlRows(sparql_rows(response.sparql_queried_objects, self.iris),
                          response.timeout)

    @staticmethod
    def lines(response: Any) -> SparqlRows:
        """queried_objects of unformatted SPARQL, one string per row, unchanged."""
        return SparqlRows(response.queried_objects, response.timeout)

    @staticmethod
    def consistency(response: Any) -> Consistency:
        """The answer of QUERY CONSISTENCY."""
        return Consistency(response.is_consistent, list(response.queried_objects))

    @staticmethod
    def nothing(response: Any) -> None:
        """For directives whose answer is only success and consistency."""
        return None
