# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The composite commands as methods, shared by the sync, asyncio and batch clients.

The methods of the commands with a face in the catalogue are generated (faces.py, by
``make catalogue``); the ones here are those a face cannot say: typed data values, enum
arguments with defaults, optional flags, SPARQL rows, loading options, the utilities.

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
from typing import Any, Dict, List, Optional, Sequence, TYPE_CHECKING, Union

from armor_client.answers import (  # noqa: F401 (the answer types, imported from here before)
    AcknowledgedChange, Answers, ChangeHistory, Consistency, Parser, SparqlRows, Words,
    _change_history, sparql_cell, sparql_rows)
from armor_client.errors import ArmorError, error_for
from armor_client.faces import ManipulationFaces, QueryFaces
from armor_client.planning import PlannerBridge
from armor_client.scenes import Scenes
from armor_client.explanations import Explanations
from armor_contract import catalogue
from armor_client.values import typed_argument, Value


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


def word(value: Union[str, enum.Enum]) -> str:
    """The string ARMOR expects for an enum member or a plain string."""
    return value.value if isinstance(value, enum.Enum) else str(value)


class Manipulations(ManipulationFaces):
    """Every change ARMOR can make to a reference (each refused with 102 under another's mount).

    Arguments naming entities take a plain name (``Robot``), a full IRI
    (``http://example.org/onto#Robot`` or ``<...>``) or a prefixed name (``dev:Charger``).
    Naming an entity that does not exist creates it.

    Every method raises ArmorServiceInternalError (a subclass by exit code) when ARMOR refuses
    the directive, and ArmorServiceCallError when the service cannot be called.
    """

    def _change(self, command: str, primary: str, secondary: str, *args: Any) -> Any:
        return self._execute((command, primary, secondary), args, Answers.nothing)

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


class Queries(QueryFaces):
    """Every question ARMOR answers about a reference, from asserted and inferred knowledge.

    Entities come back as short names (``kitchen``) or, with ``iris=True``, as IRIs
    (``http://www.example.org/robotics#kitchen``); literals as int, float, bool or str.
    Answers are sorted by the service. Queries are never refused because of a mount.

    Every method raises ArmorServiceInternalError (a subclass by exit code) when ARMOR refuses
    the directive, and ArmorServiceCallError when the service cannot be called.
    """

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

    if not TYPE_CHECKING:  # type checkers keep refusing names a reference lacks (typos)
        def __getattr__(self, name: str) -> Any:
            # Only names this class lacks reach here: maybe a method of the node's plugins
            # (plugin_faces.py), learned from its catalogue on the first such name.
            armor = self.__dict__.get('armor')
            if name.startswith('_') or armor is None:
                raise AttributeError(name)
            try:
                found = armor._plugin_method(name)
            except ArmorError as e:
                raise AttributeError(f'{type(self).__name__!r} object has no attribute '
                                     f"{name!r}, and the node's catalogue, which may add one, "
                                     f'could not be read: {e}') from e
            if not found:
                raise AttributeError(f'{type(self).__name__!r} object has no attribute '
                                     f'{name!r}, nor does a plugin of the node give one')
            return object.__getattribute__(self, name)

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
