# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The Python client: one Armor session, one Reference object per ontology.

>>> from armor_client import Armor
>>> with Armor('planner') as armor:                                      # doctest: +SKIP
...     robotics = armor.reference('robotics')
...     robotics.add_object_value('isIn', 'alice', 'bedroom')
...     print(robotics.instances('OccupiedRoom'))
['bedroom', 'kitchen']
"""

import contextlib
import os
from typing import Any, Iterator, List, Optional, Sequence, Union

from armor_client.batch import Batch
from armor_client.errors import ArmorMountError, error_for
from armor_client.operations import (Answers, Manipulations, Queries, Reasoner, ReferenceCommands,
                                     word, Words)
from armor_client.transport import ArmorTransport, directive
from armor_msgs.msg import ArmorDirectiveRes
from rclpy.node import Node


def default_client_name() -> str:
    """A client name unique to this process: ``armor_py_<pid>``."""
    return f'armor_py_{os.getpid()}'


def reasoning_args(iri: str, buffered_manipulation: bool, reasoner: Union[Reasoner, str],
                   buffered_reasoner: bool) -> List[str]:
    """The arguments of CREATE, which are also the last four of LOAD FILE and LOAD WEB."""
    return [iri, str(bool(buffered_manipulation)).lower(), word(reasoner),
            str(bool(buffered_reasoner)).lower()]


def load_args(source: str, iri: str, buffered_manipulation: bool, reasoner: Union[Reasoner, str],
              buffered_reasoner: bool) -> List[str]:
    """The five arguments of LOAD FILE and LOAD WEB."""
    return [source, *reasoning_args(iri, buffered_manipulation, reasoner, buffered_reasoner)]


class Armor:
    """A connection to one ARMOR node, speaking as one client.

    Args:
        client_name: the name this program uses in directives (the mount holder's name);
            None picks ``armor_py_<pid>``.
        namespace: the namespace of the ARMOR node ('' for the default).
        node: a node this program already spins; None to create and spin one.
        timeout_s: longest wait for each answer (None: as long as it takes).
        service_wait_s: how long the first call waits for the service to appear.
        iris: answer entities as full IRIs instead of short names.
        transport: an ArmorTransport to share (then namespace and node are not used).
    """

    def __init__(self, client_name: Optional[str] = None, *, namespace: str = '',
                 node: Optional[Node] = None, timeout_s: Optional[float] = 60.0,
                 service_wait_s: float = 30.0, iris: bool = False,
                 transport: Optional[ArmorTransport] = None):
        self.client_name = client_name or default_client_name()
        self.timeout_s = timeout_s
        self.iris = iris
        self._owns_transport = transport is None
        self.transport = transport or ArmorTransport(node=node, namespace=namespace,
                                                     service_wait_s=service_wait_s)

    def reference(self, name: str, iris: Optional[bool] = None) -> 'Reference':
        """The object for a reference that is loaded (or will be).

        Args:
            name: the reference name.
            iris: answer entities as IRIs (default: this session's setting).

        Returns:
            A Reference; nothing is sent until a method is called.
        """
        return Reference(self, name, self.iris if iris is None else iris)

    def load_file(self, name: str, path: str, iri: str = '', *,
                  reasoner: Union[Reasoner, str] = '', buffered_manipulation: bool = False,
                  buffered_reasoner: bool = False, mount: bool = False) -> 'Reference':
        """Load an ontology file as a new reference (LOAD FILE [MOUNTED]).

        Loading a name that is loaded from the same file reuses it, as ARMOR did.

        Args:
            name: the reference name.
            path: the file, as the node sees it (inside its allowed_dirs).
            iri: the ontology IRI that plain names resolve against ('' = the file's own).
            reasoner: HERMIT, PELLET, JFACT, ELK or '' for the node's default.
            buffered_manipulation: queue changes until apply() or reason().
            buffered_reasoner: the reasoner sees changes only at reason().
            mount: also mount this client on it.

        Returns:
            The Reference.

        Raises:
            ArmorFileError: the file cannot be read or lies outside allowed_dirs, or the name
                is loaded from another source.
            ArmorReasonerError: the reasoner cannot be created.
        """
        arguments = load_args(path, iri, buffered_manipulation, reasoner, buffered_reasoner)
        spec = 'MOUNTED' if mount else ''
        response = self._require(self.call(name, 'LOAD', 'FILE', spec, arguments))
        return self._loaded(name, response)

    def load_web(self, name: str, url: str, iri: str = '', *,
                 reasoner: Union[Reasoner, str] = '', buffered_manipulation: bool = False,
                 buffered_reasoner: bool = False, mount: bool = False) -> 'Reference':
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
            The Reference.

        Raises:
            ArmorFileError: web loading is off (218) or the download failed.
        """
        arguments = load_args(url, iri, buffered_manipulation, reasoner, buffered_reasoner)
        spec = 'MOUNTED' if mount else ''
        response = self._require(self.call(name, 'LOAD', 'WEB', spec, arguments))
        return self._loaded(name, response)

    def create(self, name: str, iri: str, *, reasoner: Union[Reasoner, str] = '',
               buffered_manipulation: bool = False,
               buffered_reasoner: bool = False) -> 'Reference':
        """Create a reference holding a new, empty ontology (CREATE).

        Args:
            name: the reference name.
            iri: the ontology IRI (plain names resolve against it).
            reasoner: as for load_file.
            buffered_manipulation: as for load_file.
            buffered_reasoner: as for load_file.

        Returns:
            The Reference.
        """
        arguments = reasoning_args(iri, buffered_manipulation, reasoner, buffered_reasoner)
        response = self._require(self.call(name, 'CREATE', '', '', arguments))
        return self._loaded(name, response)

    def references(self) -> List[str]:
        """The names of the loaded references (GET ALL REFS).

        Returns:
            The names.
        """
        return list(self._require(self.call('', 'GET', 'ALL', 'REFS')).queried_objects)

    def mounted_by(self, reference: str) -> Optional[str]:
        """The client that holds a reference's mount (GET REF CLIENT).

        Args:
            reference: the reference name.

        Returns:
            The client name, or None when nobody holds it.

        Raises:
            ArmorUnknownReferenceError: no such reference.
        """
        holders = self._require(self.call('', 'GET', 'REF', 'CLIENT', [reference]))
        return holders.queried_objects[0] if holders.queried_objects else None

    def log_to_screen(self, on: bool) -> None:
        """Turn the node's logging of directives to its screen on or off (LOG SCREEN ON/OFF).

        Args:
            on: True to log.
        """
        self._require(self.call('', 'LOG', 'SCREEN', 'ON' if on else 'OFF'))

    def log_to_file(self, path: Optional[str]) -> None:
        """Log directives to a file on the node's machine, or stop (LOG FILE ON/OFF).

        Args:
            path: the log file (inside the node's allowed_dirs); None stops logging to a file.
        """
        if path is None:
            self._require(self.call('', 'LOG', 'FILE', 'OFF'))
        else:
            self._require(self.call('', 'LOG', 'FILE', 'ON', [path]))

    def call(self, reference: str, command: str, primary: str = '', secondary: str = '',
             args: Sequence[Any] = ()) -> ArmorDirectiveRes:
        """Send any directive as this client and return ARMOR's raw response.

        Args:
            reference: the reference name ('' for none).
            command: the command word.
            primary: the primary spec.
            secondary: the secondary spec.
            args: the arguments (each sent as str).

        Returns:
            The response, also when the directive failed.

        Raises:
            ArmorServiceCallError: the service could not be called or did not answer in time.
        """
        return self.transport.call(
            directive(self.client_name, reference, command, primary, secondary, args),
            timeout_s=self.timeout_s)

    def close(self) -> None:
        """Release the transport (when this object created it)."""
        if self._owns_transport:
            self.transport.close()

    def __enter__(self) -> 'Armor':
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def _loaded(self, name: str, response: ArmorDirectiveRes) -> 'Reference':
        reference = self.reference(name)
        reference.consistent = response.is_consistent
        return reference

    @staticmethod
    def _require(response: ArmorDirectiveRes) -> ArmorDirectiveRes:
        if not response.success:
            raise error_for(response)
        return response


class Reference(Manipulations, Queries, ReferenceCommands):
    """One loaded ontology: every command of the contract as a method.

    Get one from Armor.reference(), Armor.load_file(), Armor.load_web() or Armor.create().
    Manipulations return None; ``consistent`` holds the consistency ARMOR reported with the
    last answer. Queries return Python values (see Queries).

    Args:
        armor: the session that sends the directives.
        name: the reference name.
        iris: answer entities as full IRIs instead of short names.
    """

    def __init__(self, armor: Armor, name: str, iris: bool = False):
        self.armor = armor
        self.name = name
        self.answers = Answers(iris)
        self.consistent: Optional[bool] = None

    def __repr__(self) -> str:
        return f'Reference({self.name!r}, client={self.armor.client_name!r})'

    def mounted_by(self) -> Optional[str]:
        """The client that holds this reference's mount (GET REF CLIENT).

        Returns:
            Its name, or None.
        """
        return self.armor.mounted_by(self.name)

    @contextlib.contextmanager
    def mounted(self) -> Iterator['Reference']:
        """Hold the mount for the duration of a with block; released even on an exception.

        Yields:
            This reference.

        Raises:
            ArmorMountError: another client holds the mount.
        """
        self.mount()
        try:
            yield self
        except BaseException:
            # The block's own error is the one to report, not a lost mount (lease, DROP).
            with contextlib.suppress(ArmorMountError):
                self.unmount()
            raise
        self.unmount()

    def batch(self) -> Batch:
        """A builder for changes sent together as one atomic list.

        Use it as ``with ref.batch() as batch: batch.add_...(...)``: the list is sent when
        the block ends without an exception, and all or none of the changes happen.

        Returns:
            An empty Batch on this reference.
        """
        return Batch(self.armor.transport, self.armor.client_name, self.name,
                     self.armor.timeout_s)

    def _execute(self, words: Words, args: Sequence[Any], parse: Any) -> Any:
        response = self.armor.call(self.name, *words, args)
        if not response.success:
            raise error_for(response)
        self.consistent = response.is_consistent
        return parse(response)
