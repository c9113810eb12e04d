# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The Python client: one Armor session, one Reference object per ontology.

The package's docstring (``armor_client``) shows them in use.
"""

import contextlib
from typing import Any, Callable, Iterator, Optional, Sequence

from armor_client.batch import Batch
from armor_client.errors import ArmorMountError
from armor_client.operations import ReferenceBase
from armor_client.session import Blocking, SessionBase
from armor_client.subscriptions import AnswerChange, Change, ChangeWatch, Query, Subscription
from armor_client.transport import directive
from armor_msgs.msg import ArmorDirectiveRes


class Reference(ReferenceBase):
    """One loaded ontology: every command of the contract as a method.

    Get one from Armor.reference(), Armor.load_file(), Armor.load_web() or Armor.create().
    Manipulations return None; ``consistent`` holds the consistency ARMOR reported with the
    last answer. Queries return Python values (see Queries).

    Args:
        armor: the session that sends the directives.
        name: the reference name.
        iris: answer entities as full IRIs instead of short names.
    """

    armor: 'Armor'

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
        batch: Batch = self.armor._batch_with_plugin_methods(
            self.armor.transport, self.armor.client_name, self.name, self.armor.timeout_s)
        return batch

    def subscribe(self, query: Query, callback: Callable[[AnswerChange], Any], *,
                  iris: Optional[bool] = None) -> Subscription:
        """Be told whenever the answer to a query changes, inferred answers included.

        Args:
            query: a QUERY directive as words (``'QUERY IND CLASS OccupiedRoom'``; QUERY may be
                left out), a SPARQL SELECT or ASK, or an ArmorDirectiveReq.
            callback: called with the whole answer at once, then with an AnswerChange (what
                appeared, what disappeared, at which revision) after each change that moved it.
            iris: answers as IRIs (default: this reference's setting).

        Returns:
            The Subscription (close it, or use it in a with block).

        Raises:
            ArmorServiceInternalError: the node refused the query (205: not a query).
        """
        return Subscription(self.armor.transport, self.armor.client_name, self.name, query,
                            callback, iris=self.answers.iris if iris is None else iris,
                            timeout_s=self.armor.timeout_s)


class Armor(Blocking, SessionBase[Reference]):
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

    _reference_class = Reference
    _batch_class = Batch

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

    def changes(self, callback: Callable[[Change], Any],
                reference: Optional[str] = None) -> ChangeWatch:
        """Be told of every acknowledged change, as the node publishes it on armor_changes.

        Args:
            callback: called with each Change (from a ROS thread, in order).
            reference: only this reference's changes (None: every reference's).

        Returns:
            The ChangeWatch (close it, or use it in a with block).
        """
        return ChangeWatch(self.transport, callback, reference)

    def close(self) -> None:
        """Release the transport (when this object created it)."""
        if self._owns_transport:
            self.transport.close()

    def __enter__(self) -> 'Armor':
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()
