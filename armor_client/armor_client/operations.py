# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The commands of the contract as methods, shared by the sync, asyncio and batch clients.

``Manipulations``, ``Queries`` and ``ReferenceCommands`` only build directives and say how to
read the answer; the class that mixes them in decides what "send" means through
``_execute``: a reference (ReferenceBase) sends through its session and returns what the
session's ``_then`` makes of the answer (Reference: the value, AsyncReference: an awaitable of
it), and Batch queues the directive for one atomic list. ``SessionCommands`` does the same for
the directives of a session (loading, the utilities) through ``_session`` (session.py). Every
method therefore ends in ``return self._execute(...)`` or ``return self._session(...)``, and
is written once for the sync and the asyncio client alike.
"""

import enum
import json
import re
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

from armor_client.errors import error_for
from armor_client.planning import PlannerBridge
from armor_client.scenes import Scenes
from armor_client.explanations import Explanations
from armor_contract import catalogue
from armor_client.values import answer_value, entity_iri, short_name, typed_argument, Value

Words = Tuple[str, str, str]
Parser = Callable[[Any], Any]


class Reasoner(str, enum.Enum):
    """The reasoners every node has; any OWLReasonerFactory class name works too."""

    HERMIT = 'HERMIT'
    PELLET = 'PELLET'
    JFACT = 'JFACT'
    ELK = 'ELK'


class Characteristic(str, enum.Enum):
    """Characteristics of an object property (a data property can only be FUNCTIONAL)."""

    FUNCTIONAL = 'FUNCTIONAL'
    INVERSE_FUNCTIONAL = 'INVERSE_FUNCTIONAL'
    TRANSITIVE = 'TRANSITIVE'
    SYMMETRIC = 'SYMMETRIC'
    ASYMMETRIC = 'ASYMMETRIC'
    REFLEXIVE = 'REFLEXIVE'
    IRREFLEXIVE = 'IRREFLEXIVE'


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


def word(value: Union[str, enum.Enum]) -> str:
    """The string ARMOR expects for an enum member or a plain string."""
    return value.value if isinstance(value, enum.Enum) else str(value)


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


class Manipulations:
    """Every change ARMOR can make to a reference (each refused with 102 under another's mount).

    Arguments naming entities take a plain name (``Robot``), a full IRI
    (``http://example.org/onto#Robot`` or ``<...>``) or a prefixed name (``dev:Charger``).
    Naming an entity that does not exist creates it.

    Every method raises ArmorServiceInternalError (a subclass by exit code) when ARMOR refuses
    the directive, and ArmorServiceCallError when the service cannot be called.
    """

    def _execute(self, words: Words, args: Sequence[Any], parse: Parser) -> Any:
        raise NotImplementedError

    def _change(self, command: str, primary: str, secondary: str, *args: Any) -> Any:
        return self._execute((command, primary, secondary), args, Answers.nothing)

    # Individuals

    def add_individual(self, individual: str) -> None:
        """Declare an individual (ADD IND).

        Args:
            individual: its name.
        """
        return self._change('ADD', 'IND', '', individual)

    def add_individual_to_class(self, individual: str, cls: str) -> None:
        """Assert that an individual belongs to a class (ADD IND CLASS).

        Args:
            individual: the individual.
            cls: the class.
        """
        return self._change('ADD', 'IND', 'CLASS', individual, cls)

    def remove_individual(self, individual: str) -> None:
        """Remove every axiom that mentions the individual (REMOVE IND).

        Args:
            individual: the individual.
        """
        return self._change('REMOVE', 'IND', '', individual)

    def remove_individual_from_class(self, individual: str, cls: str) -> None:
        """Remove the assertion that an individual belongs to a class (REMOVE IND CLASS).

        Args:
            individual: the individual.
            cls: the class.
        """
        return self._change('REMOVE', 'IND', 'CLASS', individual, cls)

    def add_same_individuals(self, *individuals: str) -> None:
        """Assert that two or more names denote the same individual (ADD IND SAME).

        Args:
            individuals: the names, at least two.
        """
        return self._change('ADD', 'IND', 'SAME', *individuals)

    def remove_same_individuals(self, *individuals: str) -> None:
        """Remove a SameIndividual assertion (REMOVE IND SAME).

        Args:
            individuals: the names as they were asserted the same.
        """
        return self._change('REMOVE', 'IND', 'SAME', *individuals)

    def make_individuals_different(self, *individuals: str) -> None:
        """Assert that the individuals are pairwise different (DISJOINT IND).

        Args:
            individuals: two or more individuals.
        """
        return self._change('DISJOINT', 'IND', '', *individuals)

    def make_instances_different(self, cls: str) -> None:
        """Make all instances of a class, inferred ones too, pairwise different.

        DISJOINT IND CLASS: the usual way to give the reasoner the unique name assumption.

        Args:
            cls: the class.
        """
        return self._change('DISJOINT', 'IND', 'CLASS', cls)

    def rename_individual(self, old: str, new: str) -> None:
        """Rename an individual everywhere (RENAME IND).

        Args:
            old: its name now.
            new: its new name.
        """
        return self._change('RENAME', 'IND', '', old, new)

    # Classes

    def add_class(self, cls: str) -> None:
        """Declare a class (ADD CLASS).

        Args:
            cls: its name.
        """
        return self._change('ADD', 'CLASS', '', cls)

    def add_subclass(self, subclass: str, superclass: str) -> None:
        """Assert SubClassOf(subclass, superclass) (ADD CLASS CLASS).

        Args:
            subclass: the more specific class.
            superclass: the more general class.
        """
        return self._change('ADD', 'CLASS', 'CLASS', subclass, superclass)

    def remove_class(self, cls: str) -> None:
        """Remove every axiom that mentions the class (REMOVE CLASS).

        Args:
            cls: the class.
        """
        return self._change('REMOVE', 'CLASS', '', cls)

    def remove_subclass(self, subclass: str, superclass: str) -> None:
        """Remove SubClassOf(subclass, superclass) (REMOVE CLASS CLASS).

        Args:
            subclass: the more specific class.
            superclass: the more general class.
        """
        return self._change('REMOVE', 'CLASS', 'CLASS', subclass, superclass)

    def make_classes_disjoint(self, *classes: str) -> None:
        """Assert that the classes are pairwise disjoint (DISJOINT CLASS).

        Args:
            classes: two or more classes.
        """
        return self._change('DISJOINT', 'CLASS', '', *classes)

    def make_subclasses_disjoint(self, cls: str) -> None:
        """Make the direct subclasses of a class, inferred ones too, disjoint.

        DISJOINT CLASS CLASS.

        Args:
            cls: the parent class.
        """
        return self._change('DISJOINT', 'CLASS', 'CLASS', cls)

    def make_equivalent_to_superclasses(self, cls: str) -> None:
        """Turn a class's SubClassOf axioms into one EquivalentClasses axiom.

        MAKE EQUIVALENT CLASS: the class becomes defined by what it was said to be.

        Args:
            cls: the class (it must have superclasses).
        """
        return self._change('MAKE', 'EQUIVALENT', 'CLASS', cls)

    def add_equivalent_class(self, cls: str, expression: str) -> None:
        """Define a class by a class expression (ADD CLASS EQUIVALENT).

        Args:
            cls: the class.
            expression: Manchester syntax, e.g. ``Room and (contains some Agent)``.
        """
        return self._change('ADD', 'CLASS', 'EQUIVALENT', cls, expression)

    def remove_equivalent_class(self, cls: str, expression: str) -> None:
        """Remove a definition added by add_equivalent_class (REMOVE CLASS EQUIVALENT).

        Args:
            cls: the class.
            expression: the same class expression.
        """
        return self._change('REMOVE', 'CLASS', 'EQUIVALENT', cls, expression)

    def add_min_cardinality(self, cls: str, prop: str, count: int, value_class: str) -> None:
        """Assert ``cls SubClassOf prop min count value_class`` (ADD CARDINALITY MIN).

        Args:
            cls: the class restricted.
            prop: an object property.
            count: the least number of values.
            value_class: the class of the values.
        """
        return self._change('ADD', 'CARDINALITY', 'MIN', cls, prop, int(count), value_class)

    def rename_class(self, old: str, new: str) -> None:
        """Rename a class everywhere (RENAME CLASS).

        Args:
            old: its name now.
            new: its new name.
        """
        return self._change('RENAME', 'CLASS', '', old, new)

    # Property values

    def add_data_value(self, prop: str, individual: str, value: Value,
                       datatype: str = '') -> None:
        """Give an individual a data property value (ADD DATAPROP IND).

        Args:
            prop: the data property.
            individual: the individual.
            value: bool, int, float or str; the type follows the value (BOOLEAN, INTEGER,
                DOUBLE, STRING) unless datatype says otherwise.
            datatype: ARMOR's type name (LONG, FLOAT, ...) or an ``xsd:`` datatype.
        """
        return self._change('ADD', 'DATAPROP', 'IND', prop, individual,
                            *typed_argument(value, datatype))

    def remove_data_value(self, prop: str, individual: str, value: Value,
                          datatype: str = '') -> None:
        """Remove a data property value (REMOVE DATAPROP IND).

        Args:
            prop: the data property.
            individual: the individual.
            value: the value to remove, typed as when it was added.
            datatype: as for add_data_value.
        """
        return self._change('REMOVE', 'DATAPROP', 'IND', prop, individual,
                            *typed_argument(value, datatype))

    def replace_data_value(self, prop: str, individual: str, new: Value, old: Value,
                           datatype: str = '') -> None:
        """Replace one data property value by another in one step (REPLACE DATAPROP IND).

        Args:
            prop: the data property.
            individual: the individual.
            new: the value it gets.
            old: the value it loses (of the same type).
            datatype: as for add_data_value, for both values.
        """
        value_type, new_text = typed_argument(new, datatype)
        return self._change('REPLACE', 'DATAPROP', 'IND', prop, individual, value_type, new_text,
                            typed_argument(old, value_type)[1])

    def add_object_value(self, prop: str, individual: str, value: str) -> None:
        """Relate an individual to another (ADD OBJECTPROP IND).

        Args:
            prop: the object property.
            individual: the subject.
            value: the individual it is related to.
        """
        return self._change('ADD', 'OBJECTPROP', 'IND', prop, individual, value)

    def remove_object_value(self, prop: str, individual: str, value: str) -> None:
        """Remove a relation between two individuals (REMOVE OBJECTPROP IND).

        Args:
            prop: the object property.
            individual: the subject.
            value: the related individual.
        """
        return self._change('REMOVE', 'OBJECTPROP', 'IND', prop, individual, value)

    def replace_object_value(self, prop: str, individual: str, new: str, old: str) -> None:
        """Replace the related individual in one step (REPLACE OBJECTPROP IND).

        Args:
            prop: the object property.
            individual: the subject.
            new: the individual it becomes related to.
            old: the individual it stops being related to.
        """
        return self._change('REPLACE', 'OBJECTPROP', 'IND', prop, individual, new, old)

    # Properties

    def add_object_subproperty(self, subproperty: str, superproperty: str) -> None:
        """Assert SubObjectPropertyOf (ADD OBJECTPROP OBJECTPROP).

        Args:
            subproperty: the more specific object property.
            superproperty: the more general one.
        """
        return self._change('ADD', 'OBJECTPROP', 'OBJECTPROP', subproperty, superproperty)

    def remove_object_subproperty(self, subproperty: str, superproperty: str) -> None:
        """Remove SubObjectPropertyOf (REMOVE OBJECTPROP OBJECTPROP).

        Args:
            subproperty: the more specific object property.
            superproperty: the more general one.
        """
        return self._change('REMOVE', 'OBJECTPROP', 'OBJECTPROP', subproperty, superproperty)

    def add_data_subproperty(self, subproperty: str, superproperty: str) -> None:
        """Assert SubDataPropertyOf (ADD DATAPROP DATAPROP).

        Args:
            subproperty: the more specific data property.
            superproperty: the more general one.
        """
        return self._change('ADD', 'DATAPROP', 'DATAPROP', subproperty, superproperty)

    def remove_data_subproperty(self, subproperty: str, superproperty: str) -> None:
        """Remove SubDataPropertyOf (REMOVE DATAPROP DATAPROP).

        Args:
            subproperty: the more specific data property.
            superproperty: the more general one.
        """
        return self._change('REMOVE', 'DATAPROP', 'DATAPROP', subproperty, superproperty)

    def add_inverse_property(self, prop: str, inverse: str) -> None:
        """Assert that two object properties are inverses (ADD OBJECTPROP INVERSE).

        Args:
            prop: one object property.
            inverse: the other.
        """
        return self._change('ADD', 'OBJECTPROP', 'INVERSE', prop, inverse)

    def remove_inverse_property(self, prop: str, inverse: str) -> None:
        """Remove an InverseObjectProperties axiom (REMOVE OBJECTPROP INVERSE).

        Args:
            prop: one object property.
            inverse: the other.
        """
        return self._change('REMOVE', 'OBJECTPROP', 'INVERSE', prop, inverse)

    def add_object_characteristic(self, prop: str,
                                  characteristic: Union[Characteristic, str]) -> None:
        """Give an object property a characteristic (ADD OBJECTPROP CHARACTERISTIC).

        Args:
            prop: the object property.
            characteristic: FUNCTIONAL, TRANSITIVE, SYMMETRIC, ... (see Characteristic).
        """
        return self._change('ADD', 'OBJECTPROP', 'CHARACTERISTIC', prop, word(characteristic))

    def remove_object_characteristic(self, prop: str,
                                     characteristic: Union[Characteristic, str]) -> None:
        """Take a characteristic from an object property (REMOVE OBJECTPROP CHARACTERISTIC).

        Args:
            prop: the object property.
            characteristic: as for add_object_characteristic.
        """
        return self._change('REMOVE', 'OBJECTPROP', 'CHARACTERISTIC', prop, word(characteristic))

    def add_data_characteristic(self, prop: str,
                                characteristic: Union[Characteristic, str] = 'FUNCTIONAL'
                                ) -> None:
        """Make a data property functional (ADD DATAPROP CHARACTERISTIC).

        Args:
            prop: the data property.
            characteristic: FUNCTIONAL, the only one OWL 2 has for data properties.
        """
        return self._change('ADD', 'DATAPROP', 'CHARACTERISTIC', prop, word(characteristic))

    def remove_data_characteristic(self, prop: str,
                                   characteristic: Union[Characteristic, str] = 'FUNCTIONAL'
                                   ) -> None:
        """Make a data property no longer functional (REMOVE DATAPROP CHARACTERISTIC).

        Args:
            prop: the data property.
            characteristic: FUNCTIONAL.
        """
        return self._change('REMOVE', 'DATAPROP', 'CHARACTERISTIC', prop, word(characteristic))

    def add_object_domain(self, prop: str, cls: str) -> None:
        """Assert an object property's domain (ADD OBJECTPROP DOMAIN).

        Args:
            prop: the object property.
            cls: the class of its subjects.
        """
        return self._change('ADD', 'OBJECTPROP', 'DOMAIN', prop, cls)

    def remove_object_domain(self, prop: str, cls: str) -> None:
        """Remove an object property's domain (REMOVE OBJECTPROP DOMAIN).

        Args:
            prop: the object property.
            cls: the domain class.
        """
        return self._change('REMOVE', 'OBJECTPROP', 'DOMAIN', prop, cls)

    def add_object_range(self, prop: str, cls: str) -> None:
        """Assert an object property's range (ADD OBJECTPROP RANGE).

        Args:
            prop: the object property.
            cls: the class of its values.
        """
        return self._change('ADD', 'OBJECTPROP', 'RANGE', prop, cls)

    def remove_object_range(self, prop: str, cls: str) -> None:
        """Remove an object property's range (REMOVE OBJECTPROP RANGE).

        Args:
            prop: the object property.
            cls: the range class.
        """
        return self._change('REMOVE', 'OBJECTPROP', 'RANGE', prop, cls)

    def add_data_domain(self, prop: str, cls: str) -> None:
        """Assert a data property's domain (ADD DATAPROP DOMAIN).

        Args:
            prop: the data property.
            cls: the class of its subjects.
        """
        return self._change('ADD', 'DATAPROP', 'DOMAIN', prop, cls)

    def remove_data_domain(self, prop: str, cls: str) -> None:
        """Remove a data property's domain (REMOVE DATAPROP DOMAIN).

        Args:
            prop: the data property.
            cls: the domain class.
        """
        return self._change('REMOVE', 'DATAPROP', 'DOMAIN', prop, cls)

    def add_data_range(self, prop: str, datatype: str) -> None:
        """Assert a data property's range (ADD DATAPROP RANGE).

        Args:
            prop: the data property.
            datatype: ARMOR's type name (INTEGER, LONG, ...) or an ``xsd:`` datatype.
        """
        return self._change('ADD', 'DATAPROP', 'RANGE', prop, datatype)

    def remove_data_range(self, prop: str, datatype: str) -> None:
        """Remove a data property's range (REMOVE DATAPROP RANGE).

        Args:
            prop: the data property.
            datatype: the range datatype.
        """
        return self._change('REMOVE', 'DATAPROP', 'RANGE', prop, datatype)

    def rename_object_property(self, old: str, new: str) -> None:
        """Rename an object property everywhere (RENAME OBJECTPROP).

        Args:
            old: its name now.
            new: its new name.
        """
        return self._change('RENAME', 'OBJECTPROP', '', old, new)

    def rename_data_property(self, old: str, new: str) -> None:
        """Rename a data property everywhere (RENAME DATAPROP).

        Args:
            old: its name now.
            new: its new name.
        """
        return self._change('RENAME', 'DATAPROP', '', old, new)

    # Axioms and rules

    def add_axiom(self, axiom: str) -> None:
        """Add one axiom (ADD AXIOM).

        Args:
            axiom: Manchester syntax (``Robot SubClassOf isIn max 1 Location``) or OWL
                functional syntax.
        """
        return self._change('ADD', 'AXIOM', '', axiom)

    def remove_axiom(self, axiom: str) -> None:
        """Remove one axiom (REMOVE AXIOM).

        Args:
            axiom: as for add_axiom.
        """
        return self._change('REMOVE', 'AXIOM', '', axiom)

    def add_rule(self, name: str, rule: str) -> None:
        """Add a SWRL rule (ADD SWRL).

        Properties the rule uses must exist already (the parser needs to know their kind).

        Args:
            name: a label for the rule.
            rule: ``Robot(?r), isIn(?r, ?l) -> Visited(?l)``; built-ins as ``swrlb:lessThan``.
        """
        return self._change('ADD', 'SWRL', '', name, rule)

    def remove_rule(self, name: str, rule: str) -> None:
        """Remove a SWRL rule (REMOVE SWRL).

        Args:
            name: its label.
            rule: the rule, as added.
        """
        return self._change('REMOVE', 'SWRL', '', name, rule)

    # Buffers

    def apply(self) -> None:
        """Apply the buffered manipulations of a buffered reference (APPLY)."""
        return self._change('APPLY', '', '')

    def reason(self) -> None:
        """Apply the buffer and bring the reasoner up to date (REASON)."""
        return self._change('REASON', '', '')


class Queries:
    """Every question ARMOR answers about a reference, from asserted and inferred knowledge.

    Entities come back as short names (``kitchen``) or, with ``iris=True``, as IRIs
    (``http://www.example.org/robotics#kitchen``); literals as int, float, bool or str.
    Answers are sorted by the service. Queries are never refused because of a mount.

    Every method raises ArmorServiceInternalError (a subclass by exit code) when ARMOR refuses
    the directive, and ArmorServiceCallError when the service cannot be called.
    """

    answers: Answers

    def _execute(self, words: Words, args: Sequence[Any], parse: Parser) -> Any:
        raise NotImplementedError

    def types_of(self, individual: str) -> List[str]:
        """The classes of an individual (QUERY IND).

        Args:
            individual: the individual.

        Returns:
            Its classes, asserted and inferred; empty when it has none (or does not exist).
        """
        return self._execute(('QUERY', 'IND', ''), [individual], self.answers.entities)

    def classes_of(self, individual: str, most_specific: bool = False) -> List[str]:
        """The classes of an individual (QUERY CLASS IND).

        Args:
            individual: the individual.
            most_specific: only the most specific classes.

        Returns:
            The classes.
        """
        args = [individual, 'true'] if most_specific else [individual]
        return self._execute(('QUERY', 'CLASS', 'IND'), args, self.answers.entities)

    def instances(self, cls: str) -> List[str]:
        """The instances of a class, asserted and inferred (QUERY IND CLASS).

        Args:
            cls: the class.

        Returns:
            Its instances.
        """
        return self._execute(('QUERY', 'IND', 'CLASS'), [cls], self.answers.entities)

    def dl_instances(self, expression: str) -> List[str]:
        """The instances of a class expression, a "DL query" (QUERY IND DL).

        Args:
            expression: Manchester syntax, e.g. ``Agent and isIn some Room``.

        Returns:
            Its instances.
        """
        return self._execute(('QUERY', 'IND', 'DL'), [expression], self.answers.entities)

    def same_individuals(self, individual: str) -> List[str]:
        """The individuals inferred equal to one (QUERY IND SAME).

        Args:
            individual: the individual.

        Returns:
            The others (it is not in the list).
        """
        return self._execute(('QUERY', 'IND', 'SAME'), [individual], self.answers.entities)

    def data_properties_of(self, individual: str) -> List[str]:
        """The data properties that have values for an individual (QUERY IND DATAPROP).

        Args:
            individual: the individual.

        Returns:
            The data properties.
        """
        return self._execute(('QUERY', 'IND', 'DATAPROP'), [individual], self.answers.entities)

    def object_properties_of(self, individual: str) -> List[str]:
        """The object properties that have values for an individual (QUERY IND OBJECTPROP).

        Args:
            individual: the individual.

        Returns:
            The object properties.
        """
        return self._execute(('QUERY', 'IND', 'OBJECTPROP'), [individual],
                             self.answers.entities)

    def data_values(self, prop: str, individual: str) -> List[Value]:
        """An individual's values of a data property (QUERY DATAPROP IND).

        Args:
            prop: the data property.
            individual: the individual.

        Returns:
            The values as int, float, bool or str.
        """
        return self._execute(('QUERY', 'DATAPROP', 'IND'), [prop, individual],
                             self.answers.values)

    def object_values(self, prop: str, individual: str) -> List[str]:
        """The individuals an individual is related to by an object property.

        QUERY OBJECTPROP IND.

        Args:
            prop: the object property.
            individual: the subject.

        Returns:
            The related individuals.
        """
        return self._execute(('QUERY', 'OBJECTPROP', 'IND'), [prop, individual],
                             self.answers.entities)

    def subclasses(self, cls: str) -> List[str]:
        """The subclasses of a class, all levels (QUERY CLASS CLASS).

        Args:
            cls: the class.

        Returns:
            Its subclasses.
        """
        return self._execute(('QUERY', 'CLASS', 'CLASS'), [cls], self.answers.entities)

    def dl_subclasses(self, expression: str) -> List[str]:
        """The named subclasses of a class expression (QUERY CLASS DL).

        Args:
            expression: Manchester syntax.

        Returns:
            The subclasses.
        """
        return self._execute(('QUERY', 'CLASS', 'DL'), [expression], self.answers.entities)

    def superclasses(self, cls: str) -> List[str]:
        """The superclasses of a class (QUERY CLASS SUPER).

        Args:
            cls: the class.

        Returns:
            Its superclasses.
        """
        return self._execute(('QUERY', 'CLASS', 'SUPER'), [cls], self.answers.entities)

    def equivalent_classes(self, cls: str) -> List[str]:
        """The named classes equivalent to a class (QUERY CLASS EQUIVALENT).

        Args:
            cls: the class.

        Returns:
            The equivalent classes (not the class itself).
        """
        return self._execute(('QUERY', 'CLASS', 'EQUIVALENT'), [cls], self.answers.entities)

    def disjoint_classes(self, cls: str) -> List[str]:
        """The classes disjoint with a class (QUERY CLASS DISJOINT).

        Args:
            cls: the class.

        Returns:
            The disjoint classes.
        """
        return self._execute(('QUERY', 'CLASS', 'DISJOINT'), [cls], self.answers.entities)

    def restrictions(self, cls: str) -> List[str]:
        """The restrictions in a class's superclasses and definitions (QUERY CLASS RESTRICTIONS).

        Args:
            cls: the class.

        Returns:
            One restriction per string, Manchester syntax (``contains some Agent``).
        """
        return self._execute(('QUERY', 'CLASS', 'RESTRICTIONS'), [cls],
                             self.answers.expressions)

    def object_subproperties(self, prop: str) -> List[str]:
        """The sub-properties of an object property (QUERY OBJECTPROP OBJECTPROP).

        Args:
            prop: the object property.

        Returns:
            Its sub-properties.
        """
        return self._execute(('QUERY', 'OBJECTPROP', 'OBJECTPROP'), [prop],
                             self.answers.entities)

    def data_subproperties(self, prop: str) -> List[str]:
        """The sub-properties of a data property (QUERY DATAPROP DATAPROP).

        Args:
            prop: the data property.

        Returns:
            Its sub-properties.
        """
        return self._execute(('QUERY', 'DATAPROP', 'DATAPROP'), [prop], self.answers.entities)

    def sparql(self, query: str, timeout_ms: Optional[int] = None) -> SparqlRows:
        """A SPARQL SELECT or ASK over asserted and inferred knowledge (QUERY SPARQL FORMATTED).

        The ontology's prefixes are predefined and ``:`` is the reference's namespace.

        Args:
            query: the query, e.g. ``SELECT ?room WHERE { ?room a :Room }``.
            timeout_ms: a time limit for the service; the rows found by then come back with
                ``timed_out`` set.

        Returns:
            One dict per row, variable -> value (None when unbound); an ASK answers
            ``[{'ASK': True}]`` or ``[{'ASK': False}]``.
        """
        args: List[Any] = [query] if timeout_ms is None else [query, int(timeout_ms)]
        return self._execute(('QUERY', 'SPARQL', 'FORMATTED'), args, self.answers.rows)

    def sparql_lines(self, query: str, timeout_ms: Optional[int] = None) -> SparqlRows:
        """A SPARQL query answered as ARMOR's text rows (QUERY SPARQL).

        Args:
            query: the query.
            timeout_ms: as for sparql().

        Returns:
            One string per row: the value alone for one variable, ``a=...; b=...`` for
            several, ``true``/``false`` for ASK.
        """
        args: List[Any] = [query] if timeout_ms is None else [query, int(timeout_ms)]
        return self._execute(('QUERY', 'SPARQL', ''), args, Answers.lines)

    def ask(self, query: str) -> bool:
        """A SPARQL ASK query as a bool.

        Args:
            query: ``ASK { :robot1 :isIn :kitchen }``.

        Returns:
            The answer.
        """
        return self._execute(('QUERY', 'SPARQL', 'FORMATTED'), [query],
                             lambda response: self.answers.rows(response)[0]['ASK'])

    def check_consistency(self) -> Consistency:
        """Whether the ontology is consistent, and why not (QUERY CONSISTENCY).

        Returns:
            A Consistency (true in a boolean context when consistent).
        """
        return self._execute(('QUERY', 'CONSISTENCY', ''), [], Answers.consistency)


class ReferenceCommands:
    """Saving, dropping and mounting a reference (never refused because of a mount).

    Every method raises ArmorServiceInternalError (a subclass by exit code) when ARMOR refuses
    the directive, and ArmorServiceCallError when the service cannot be called.
    """

    def _execute(self, words: Words, args: Sequence[Any], parse: Parser) -> Any:
        raise NotImplementedError

    def save(self, path: str = '', format: str = '', *, inferences: bool = False) -> None:
        """Write the ontology to a file on the node's machine (SAVE / SAVE INFERENCE).

        Args:
            path: where ('' = the file it was loaded from); a relative path is the
                caller's (made absolute here); inside the node's allowed_dirs.
            format: rdfxml, owlxml, turtle, functional or manchester ('' = as loaded).
            inferences: also write the inferred types, property values and hierarchy (the
                live ontology does not change).
        """
        args = [path, format] if format else ([path] if path else [])
        return self._execute(('SAVE', 'INFERENCE' if inferences else '', ''), args,
                             Answers.nothing)

    def drop(self) -> None:
        """Unload the reference (DROP)."""
        return self._execute(('DROP', '', ''), [], Answers.nothing)

    def mount(self) -> None:
        """Become the only client allowed to change this reference (MOUNT).

        Raises ArmorMountError (203) when another client holds the mount.
        """
        return self._execute(('MOUNT', '', ''), [], Answers.nothing)

    def unmount(self) -> None:
        """Release the mount (UNMOUNT).

        Raises ArmorMountError (203) when this client does not hold the mount.
        """
        return self._execute(('UNMOUNT', '', ''), [], Answers.nothing)


def reasoning_args(iri: str, buffered_manipulation: bool, reasoner: Union[Reasoner, str],
                   buffered_reasoner: bool) -> List[str]:
    """The arguments of CREATE, which are also the last four of LOAD FILE and LOAD WEB."""
    return [iri, str(bool(buffered_manipulation)).lower(), word(reasoner),
            str(bool(buffered_reasoner)).lower()]


def load_args(source: str, iri: str, buffered_manipulation: bool, reasoner: Union[Reasoner, str],
              buffered_reasoner: bool) -> List[str]:
    """The five arguments of LOAD FILE and LOAD WEB."""
    return [source, *reasoning_args(iri, buffered_manipulation, reasoner, buffered_reasoner)]


def _catalogue(response: Any) -> catalogue.Catalogue:
    texts = list(response.queried_objects)
    return catalogue.parse(json.loads(texts[0]) if texts else
                           {'commands': [], 'exit_codes': [], 'settings': []})


class SessionCommands:
    """Loading references and the utilities that need none: the directives of a session.

    ``_session(reference, words, args, parse)`` sends (Armor) or returns an awaitable of
    (AsyncArmor) ``parse(response)``, raising ArmorServiceInternalError (a subclass by exit
    code) when ARMOR refuses the directive. ``_loaded`` makes the Reference object of the
    session's kind for a reference just loaded.
    """

    def _session(self, reference: str, words: Words, args: Sequence[Any], parse: Parser) -> Any:
        raise NotImplementedError

    def _loaded(self, name: str, response: Any) -> Any:
        raise NotImplementedError

    def load_file(self, name: str, path: str, iri: str = '', *,
                  reasoner: Union[Reasoner, str] = '', buffered_manipulation: bool = False,
                  buffered_reasoner: bool = False, mount: bool = False) -> Any:
        """Load an ontology file as a new reference (LOAD FILE [MOUNTED]).

        Loading a name that is loaded from the same file reuses it, as ARMOR did.

        Args:
            name: the reference name.
            path: the file on the node's machine, inside its allowed_dirs; a relative path
                is the caller's (made absolute here).
            iri: the ontology IRI that plain names resolve against ('' = the file's own).
            reasoner: HERMIT, PELLET, JFACT, ELK or '' for the node's default.
            buffered_manipulation: queue changes until apply() or reason().
            buffered_reasoner: the reasoner sees changes only at reason().
            mount: also mount this client on it.

        Returns:
            The Reference (AsyncReference from AsyncArmor).

        Raises:
            ArmorFileError: the file cannot be read or lies outside allowed_dirs, or the name
                is loaded from another source.
            ArmorReasonerError: the reasoner cannot be created.
        """
        return self._session(name, ('LOAD', 'FILE', 'MOUNTED' if mount else ''),
                             load_args(path, iri, buffered_manipulation, reasoner,
                                       buffered_reasoner),
                             lambda response: self._loaded(name, response))

    def load_web(self, name: str, url: str, iri: str = '', *,
                 reasoner: Union[Reasoner, str] = '', buffered_manipulation: bool = False,
                 buffered_reasoner: bool = False, mount: bool = False) -> Any:
        """Load an ontology from a URL as a new reference (LOAD WEB [MOUNTED]).

        The node must run with ``web_loading:=true``.

        Args:
            name: the reference name.
            url: where the ontology is.
            iri: as for load_file.
            reasoner: as for load_file.
            buffered_manipulation: as for load_file.
            buffered_reasoner: as for load_file.
            mount: as for load_file.

        Returns:
            The Reference (AsyncReference from AsyncArmor).

        Raises:
            ArmorFileError: web loading is off (218) or the download failed.
        """
        return self._session(name, ('LOAD', 'WEB', 'MOUNTED' if mount else ''),
                             load_args(url, iri, buffered_manipulation, reasoner,
                                       buffered_reasoner),
                             lambda response: self._loaded(name, response))

    def create(self, name: str, iri: str, *, reasoner: Union[Reasoner, str] = '',
               buffered_manipulation: bool = False, buffered_reasoner: bool = False) -> Any:
        """Create a reference holding a new, empty ontology (CREATE).

        Args:
            name: the reference name.
            iri: the ontology IRI (plain names resolve against it).
            reasoner: as for load_file.
            buffered_manipulation: as for load_file.
            buffered_reasoner: as for load_file.

        Returns:
            The Reference (AsyncReference from AsyncArmor).
        """
        return self._session(name, ('CREATE', '', ''),
                             reasoning_args(iri, buffered_manipulation, reasoner,
                                            buffered_reasoner),
                             lambda response: self._loaded(name, response))

    def references(self) -> List[str]:
        """The names of the loaded references, GET ALL REFS.

        Returns:
            The names.
        """
        return self._session('', ('GET', 'ALL', 'REFS'), [],
                             lambda response: list(response.queried_objects))

    def load_progress(self) -> List[str]:
        """The LOADs in flight, GET LOAD PROGRESS.

        Returns:
            One line per LOAD: reference, phase, bytes read, bytes in all, elapsed ms.
        """
        return self._session('', ('GET', 'LOAD', 'PROGRESS'), [],
                             lambda response: list(response.queried_objects))

    def catalogue(self) -> Any:
        """What the running node answers, GET CATALOGUE: commands, exit codes, settings.

        Returns:
            An armor_contract.catalogue.Catalogue (empty if the node sent no JSON).
        """
        return self._session('', ('GET', 'CATALOGUE', ''), [], _catalogue)

    def mounted_by(self, reference: str) -> Optional[str]:
        """The client that holds a reference's mount (GET REF CLIENT).

        Args:
            reference: the reference name.

        Returns:
            The client name, or None when nobody holds it.

        Raises:
            ArmorUnknownReferenceError: no such reference.
        """
        return self._session('', ('GET', 'REF', 'CLIENT'), [reference],
                             lambda response: (response.queried_objects[0]
                                               if response.queried_objects else None))

    def revision(self, reference: str) -> int:
        """A reference's revision: how many changes it has acknowledged (GET REF REVISION).

        Read it before a change whose answer might be lost; see changes_since.
        """
        return self._session('', ('GET', 'REF', 'REVISION'), [reference],
                             lambda response: int(response.queried_objects[0])
                             if response.queried_objects else 0)

    def digest(self, reference: str) -> str:
        """A SHA-256 of a reference's asserted axioms, annotations and imports (GET REF DIGEST).

        Equal digests mean equal ontologies: compare one before and after an answer was lost,
        or between two copies of a reference.
        """
        return self._session('', ('GET', 'REF', 'DIGEST'), [reference],
                             lambda response: response.queried_objects[0]
                             if response.queried_objects else '')

    def state_damage(self) -> List[Dict[str, Any]]:
        """What the state directory could not restore or cannot keep now (GET STATE DAMAGE).

        Returns:
            One dict per damaged reference (``reference``, ``restored``, ``revision``,
            ``problems``, ``kept_in``, as docs/durability.md describes); empty when nothing.
        """
        return self._session('', ('GET', 'STATE', 'DAMAGE'), [],
                             lambda response: [json.loads(item)
                                               for item in response.queried_objects])

    def changes_since(self, reference: str, revision: int = -1,
                      client: Optional[str] = None) -> ChangeHistory:
        """A reference's acknowledged changes after a revision, oldest first (GET REF CHANGES).

        How a client whose answer never arrived (ArmorCoreUnavailableError, a time-out, a lost
        reply) learns whether its change was applied before sending it again::

            before = armor.revision('map')
            try:
                armor.reference('map').add_object_value('isIn', 'bob', 'kitchen')
            except (ArmorCoreUnavailableError, ArmorServiceCallError):
                if not any(change.includes('ADD OBJECTPROP IND', ['isIn', 'bob', 'kitchen'],
                                           armor.client_name)
                           for change in armor.changes_since('map', before, armor.client_name)):
                    ...  # not applied: send it again

        Args:
            reference: the reference name.
            revision: the revision after which to list changes (-1: every kept change).
            client: only the changes with a directive of this client (None: all).

        Returns:
            A ChangeHistory (a list of AcknowledgedChange); ``complete`` is False when older
            changes after ``revision`` are no longer kept.
        """
        return self._session('', ('GET', 'REF', 'CHANGES'),
                             [reference, str(revision), *([client] if client else [])],
                             _change_history)

    def log_to_screen(self, on: bool) -> None:
        """Turn the node's logging of directives to its screen on or off (LOG SCREEN ON/OFF).

        Args:
            on: True to log.
        """
        return self._session('', ('LOG', 'SCREEN', 'ON' if on else 'OFF'), [], Answers.nothing)

    def log_to_file(self, path: Optional[str]) -> None:
        """Log directives to a file on the node's machine, or stop (LOG FILE ON/OFF).

        Args:
            path: the log file (inside the node's allowed_dirs; a relative path is the
                caller's); None stops logging to a file.
        """
        if path is None:
            return self._session('', ('LOG', 'FILE', 'OFF'), [], Answers.nothing)
        return self._session('', ('LOG', 'FILE', 'ON'), [path], Answers.nothing)


class ReferenceBase(Manipulations, Queries, ReferenceCommands, PlannerBridge, Scenes,
                    Explanations):
    """What Reference and AsyncReference share: the state, sending, and reading an answer.

    Each directive goes through the session's ``call``, and its answer through the session's
    ``_then``: the sync session hands the parsed value back, the asyncio one an awaitable of
    it. Reference and AsyncReference add only their context managers (mounted, batch).

    Args:
        armor: the session that sends the directives (Armor or AsyncArmor).
        name: the reference name.
        iris: answer entities as full IRIs instead of short names.
    """

    def __init__(self, armor: Any, name: str, iris: bool = False):
        self.armor = armor
        self.name = name
        self.answers = Answers(iris)
        self.consistent: Optional[bool] = None

    def __repr__(self) -> str:
        return f'{type(self).__name__}({self.name!r}, client={self.armor.client_name!r})'

    def mounted_by(self) -> Any:
        """The client that holds this reference's mount (GET REF CLIENT).

        Returns:
            Its name, or None (an awaitable of it from AsyncReference).
        """
        return self.armor.mounted_by(self.name)

    def revision(self) -> Any:
        """How many changes this reference has acknowledged (GET REF REVISION).

        See Armor.changes_since for what it is for.
        """
        return self.armor.revision(self.name)

    def changes_since(self, revision: int = -1, client: Optional[str] = None) -> Any:
        """This reference's acknowledged changes after a revision (GET REF CHANGES).

        Returns:
            A ChangeHistory (an awaitable of it from AsyncReference); see Armor.changes_since.
        """
        return self.armor.changes_since(self.name, revision, client)

    def _execute(self, words: Words, args: Sequence[Any], parse: Parser) -> Any:
        return self.armor._then(self.armor.call(self.name, *words, args),
                                lambda response: self._answer(response, parse))

    def _answer(self, response: Any, parse: Parser) -> Any:
        """The parsed answer of a response to this reference; raises when it failed."""
        if not response.success:
            raise error_for(response)
        self.consistent = response.is_consistent
        return parse(response)
