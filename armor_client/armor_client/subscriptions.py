# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Knowledge that tells you when it changes: standing queries and the change topic.

>>> import time
>>> from armor_client import Armor
>>> with Armor('planner') as armor:                                      # doctest: +SKIP
...     robotics = armor.reference('robotics')
...     with robotics.subscribe('QUERY IND CLASS OccupiedRoom', print):
...         robotics.replace_object_value('isIn', 'alice', 'bedroom', 'corridor1')
...         time.sleep(1)
AnswerChange(revision=3, added=['kitchen'], removed=[], answer=['kitchen'], initial=True, ...)
AnswerChange(revision=4, added=['bedroom'], removed=[], answer=['bedroom', 'kitchen'], ...)

- ``Reference.subscribe(query, callback)``: a ``Subscription``; ``callback`` gets the whole
  answer first, then one ``AnswerChange`` per change that moved it (inferred answers too: the
  node asks the reasoner again after each change). ``AsyncReference.subscribe(query)`` is the
  same as an async iterator of AnswerChange.
- ``Armor.changes(callback)`` / ``AsyncArmor.changes()``: every acknowledged change
  (``Change``) the node publishes on armor_changes, with the reference's revision.

Nothing is skipped silently: an AnswerChange whose ``missed`` is above 0 follows messages that
never arrived (its ``answer`` may then be incomplete); a Change whose ``missed`` is not empty
names the revisions of its reference that were not received.
"""

import asyncio
import contextlib
import logging
import re
import shlex
import threading
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any, Callable, Dict, List, Optional, Tuple, Union

from armor_client import commands
from armor_client.errors import ArmorArgumentError, ArmorServiceCallError, error_for
from armor_client.transport import ArmorTransport, directive
from armor_client.values import answer_value, is_literal, short_name
from armor_contract.events import ANSWER_QOS, CHANGE_QOS, CHANGE_TOPIC
from armor_msgs.msg import ArmorAnswer, ArmorChange, ArmorDirectiveReq
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
from rclpy.event_handler import SubscriptionEventCallbacks

_LOG = logging.getLogger('armor_client')
# An unsubscribe nobody answers is no loss: the node ends a subscription whose topic has no
# subscriber left by itself (subscription_idle_s).
_UNSUBSCRIBE_WAIT_S = 5.0
# No QoS event handlers on answer subscriptions: rclpy keeps a reference to each handler it
# ever made in their callback group, memory a closed subscription would not give back.
_NO_EVENT_HANDLERS = SubscriptionEventCallbacks(use_default_callbacks=False)
_SPARQL_START = re.compile(r'\s*(SELECT|ASK|PREFIX|BASE)\b', re.IGNORECASE)
_BRACKETED_IRI = re.compile(r'<([^<>\s]+)>')
Query = Union[str, ArmorDirectiveReq]


@dataclass(frozen=True)
class AnswerChange:
    """What changed in a subscription's answer.

    Attributes:
        revision: the reference's revision the answer holds at (-1: the reference was dropped).
        added: answers that appeared (the first change: the whole answer).
        removed: answers that disappeared.
        answer: the whole answer after the change, sorted.
        initial: whether this is the first change (the answer when the subscription was made).
        missed: how many of the node's messages were missed just before this one (0 normally;
            above 0, ``answer`` may be incomplete).
        exit_code: 0, or why the query could not be answered at this revision (217: the
            reference is inconsistent, 206: it was dropped); its answers change again once it
            can be.
        error: the description of exit_code.
    """

    revision: int
    added: List[Any]
    removed: List[Any]
    answer: List[Any]
    initial: bool = False
    missed: int = 0
    exit_code: int = 0
    error: str = ''


@dataclass(frozen=True)
class Change:
    """One acknowledged change of a reference, as published on armor_changes.

    Attributes:
        reference: the reference that changed.
        revision: its revision after the change (0: the LOAD or CREATE that made it).
        client: the client that sent it.
        directives: the directives that made it (ArmorDirectiveReq; a list: all of its changes).
        consistent: the reference's consistency after it.
        stamp_ns: when the node acknowledged it (nanoseconds since the Unix epoch).
        missed: revisions of the reference before this one that were not received.
    """

    reference: str
    revision: int
    client: str
    directives: List[ArmorDirectiveReq]
    consistent: bool
    stamp_ns: int
    missed: Tuple[int, ...] = field(default=())

    def describe(self) -> str:
        """The directives as typed: ``ADD OBJECTPROP IND isIn alice bedroom; ...``."""
        return '; '.join(' '.join(word for word in (
            d.command, d.primary_command_spec, d.secondary_command_spec, *d.args) if word)
            for d in self.directives)


def query_directive(client: str, reference: str, query: Query,
                    transport: Optional[ArmorTransport] = None) -> ArmorDirectiveReq:
    """The directive a subscription asks.

    Args:
        client: the client name.
        reference: the reference.
        query: a SPARQL SELECT or ASK; or a QUERY directive as words (``QUERY IND CLASS
            OccupiedRoom``, QUERY may be left out; quote arguments with spaces); or an
            ArmorDirectiveReq.
        transport: the node to ask for its catalogue when no command here starts the words
            (a plugin's query); None: only the commands known here.

    Returns:
        The directive.

    Raises:
        ArmorArgumentError: the words name no QUERY command.
    """
    if isinstance(query, ArmorDirectiveReq):
        return query
    if _SPARQL_START.match(query):
        return directive(client, reference, 'QUERY', 'SPARQL', '', [query])
    words = shlex.split(query)
    if words and words[0].upper() != 'QUERY':
        words.insert(0, 'QUERY')
    command, arguments = commands.split_directive(words)
    if command is None and transport is not None:
        commands.find_on(transport, *words[:3])  # learns the node's catalogue
        command, arguments = commands.split_directive(words)
    if command is None or command.words[0] != 'QUERY':
        raise ArmorArgumentError(f'no QUERY command starts "{query}" (docs/commands.md#queries)',
                                 205)
    return directive(client, reference, *command.words, arguments)


def _decoder(iris: bool) -> Callable[[str], Any]:
    """How to read an answer: entities named, literals as values, rows and text shortened."""
    def decode(text: str) -> Any:
        if is_literal(text) or (text.startswith('<') and text.endswith('>') and ' ' not in text):
            return answer_value(text, iris)
        return text if iris else _BRACKETED_IRI.sub(lambda m: short_name(m.group(1)), text)
    return decode


def _sorted(values) -> List[Any]:
    return sorted(values, key=lambda value: (str(type(value)), str(value)))


class Subscription:
    """A standing query: ``callback`` is called with an AnswerChange whenever its answer moves.

    Made by ``Reference.subscribe``; ends with ``close()`` (or the end of a with block). The
    first call, before this object is returned, gives the whole answer. Later calls come from
    the transport's ROS thread, one at a time, in order.

    Args:
        transport: the transport whose node subscribes.
        client_name: the client the query is asked as.
        reference: the reference.
        query: see query_directive.
        callback: called with each AnswerChange (an exception it raises is logged).
        iris: answers as full IRIs instead of short names.
        timeout_s: longest wait for the node's answer to the subscription.

    Attributes:
        id: the node's id of the subscription.
        topic: the topic its changes come on.
        revision: the revision the answer holds at.

    Raises:
        ArmorServiceInternalError: the node refused the query (a subclass by exit code; 205:
            not a query).
        ArmorServiceCallError: the node did not answer.
    """

    def __init__(self, transport: ArmorTransport, client_name: str, reference: str,
                 query: Query, callback: Callable[[AnswerChange], Any], *, iris: bool = False,
                 timeout_s: Optional[float] = None):
        self.reference = reference
        self.directive = query_directive(client_name, reference, query, transport)
        self._decode = _decoder(iris)
        self._callback = callback
        self._transport = transport
        self._timeout_s = timeout_s
        # Re-entrant: a callback may read .answer or close() (it runs holding the lock, for order).
        self._lock = threading.RLock()
        self._closed = False
        response = transport.subscribe(self.directive, timeout_s)
        if not response.success:
            raise error_for(SimpleNamespace(exit_code=response.exit_code, timeout=False,
                                            error_description=response.error_description))
        self.id: str = response.subscription_id
        self.topic: str = response.topic
        self.revision: int = response.revision
        self._answer = {answer: self._decode(answer) for answer in response.answer}
        self._next_sequence = 1
        with self._lock:
            # A group of its own: one message at a time, in order; and it goes with this object
            # (rclpy never forgets what was once in a group).
            self._ros_subscription = transport.node.create_subscription(
                ArmorAnswer, self.topic, self._received, ANSWER_QOS,
                callback_group=MutuallyExclusiveCallbackGroup(),
                event_callbacks=_NO_EVENT_HANDLERS)
            decoded = _sorted(self._answer.values())
            self._deliver(AnswerChange(self.revision, decoded, [], decoded, initial=True))

    @property
    def answer(self) -> List[Any]:
        """The whole answer now (as far as the messages received tell), sorted."""
        with self._lock:
            return _sorted(self._answer.values())

    @property
    def alive(self) -> bool:
        """Whether the node still publishes the subscription's topic (not after a restart)."""
        with self._lock:
            return not self._closed and self._ros_subscription.get_publisher_count() > 0

    def close(self) -> None:
        """End the subscription (the node stops asking); calling it again does nothing."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            self._transport.node.destroy_subscription(self._ros_subscription)
        with contextlib.suppress(ArmorServiceCallError):
            self._transport.unsubscribe(self.id, _UNSUBSCRIBE_WAIT_S)

    def __enter__(self) -> 'Subscription':
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def __repr__(self) -> str:
        return f'Subscription({self.id!r}, {self.reference!r}, revision={self.revision})'

    def _received(self, message: ArmorAnswer) -> None:
        with self._lock:
            # The first message repeats the answer the service gave; a topic is reused once its
            # subscription has ended, so a message may be another subscription's.
            if (self._closed or message.subscription_id != self.id
                    or message.sequence < self._next_sequence):
                return
            missed = message.sequence - self._next_sequence
            self._next_sequence = message.sequence + 1
            removed = [self._answer.pop(text) for text in message.removed if text in self._answer]
            added = []
            for text in message.added:
                if text not in self._answer:
                    self._answer[text] = self._decode(text)
                    added.append(self._answer[text])
            if message.revision >= 0:
                self.revision = message.revision
            self._deliver(AnswerChange(
                message.revision, added, removed, _sorted(self._answer.values()), missed=missed,
                exit_code=message.exit_code, error=message.error_description))

    def _deliver(self, change: AnswerChange) -> None:
        try:
            self._callback(change)
        except Exception:  # the ROS thread must live on: the callback's bug is reported
            _LOG.exception('the callback of subscription %s failed', self.id)


class ChangeWatch:
    """Every change the node publishes on armor_changes, to ``callback`` (made by Armor.changes).

    Args:
        transport: the transport whose node subscribes.
        callback: called with each Change, from the transport's ROS thread, in order.
        reference: only this reference's changes (None: all).

    A watch sees the changes made after it has joined the topic (a fraction of a second after
    it is made); revisions of a reference it saw skip ahead only when messages were lost, and
    Change.missed then names them.
    """

    def __init__(self, transport: ArmorTransport, callback: Callable[[Change], Any],
                 reference: Optional[str] = None):
        self._transport = transport
        self._callback = callback
        self._reference = reference
        self._last: Dict[str, int] = {}
        prefix = transport.namespace.rstrip('/') + '/' if transport.namespace else ''
        self._ros_subscription: Optional[Any] = transport.node.create_subscription(
            ArmorChange, prefix + CHANGE_TOPIC, self._received, CHANGE_QOS)

    def close(self) -> None:
        """Stop watching."""
        if self._ros_subscription is not None:
            self._transport.node.destroy_subscription(self._ros_subscription)
            self._ros_subscription = None

    def __enter__(self) -> 'ChangeWatch':
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def _received(self, message: ArmorChange) -> None:
        if self._reference is not None and message.reference_name != self._reference:
            return
        last = self._last.get(message.reference_name)
        self._last[message.reference_name] = message.revision
        # Revision 0 starts a reference again (loaded anew); a jump ahead is what was lost.
        missed = tuple(range(last + 1, message.revision)) if last is not None else ()
        change = Change(message.reference_name, message.revision, message.client_name,
                        list(message.directives), message.is_consistent,
                        message.stamp.sec * 1_000_000_000 + message.stamp.nanosec, missed)
        try:
            self._callback(change)
        except Exception:  # the ROS thread must live on: the callback's bug is reported
            _LOG.exception('a change callback failed')


class _AsyncQueue:
    """Hands items from a ROS thread to an asyncio consumer, ending with close()."""

    _END = object()

    def __init__(self) -> None:
        self._loop = asyncio.get_running_loop()
        self._queue: asyncio.Queue = asyncio.Queue()

    def put(self, item: Any) -> None:
        self._loop.call_soon_threadsafe(self._queue.put_nowait, item)

    def end(self) -> None:
        self.put(self._END)

    async def get(self) -> Any:
        item = await self._queue.get()
        if item is self._END:
            self._queue.put_nowait(item)
            raise StopAsyncIteration
        return item


class AsyncSubscription:
    """A standing query as an async iterator of AnswerChange (made by AsyncReference.subscribe).

    ``async with ref.subscribe(query) as changes: async for change in changes: ...``; the
    subscription is made on entering (or at the first ``async for``) and ends on leaving (or
    at ``await close()``). The first change is the whole answer.

    Args:
        armor: the AsyncArmor session.
        reference: the reference.
        query: see query_directive.
        iris: answers as full IRIs instead of short names.
    """

    def __init__(self, armor: Any, reference: str, query: Query, iris: bool = False):
        self._armor = armor
        self._reference = reference
        self._query = query
        self._iris = iris
        self._queue: Optional[_AsyncQueue] = None
        self.subscription: Optional[Subscription] = None

    async def start(self) -> 'AsyncSubscription':
        """Make the subscription (once).

        Returns:
            This object.

        Raises:
            ArmorServiceInternalError: the node refused the query.
        """
        if self._queue is None:
            queue = self._queue = _AsyncQueue()
            self.subscription = await self._armor._in_pool(
                Subscription, self._armor.transport, self._armor.client_name, self._reference,
                self._query, queue.put, iris=self._iris, timeout_s=self._armor.timeout_s)
        return self

    async def close(self) -> None:
        """End the subscription; an iteration in progress ends too."""
        if self.subscription is not None:
            await self._armor._in_pool(self.subscription.close)
        if self._queue is not None:
            self._queue.end()

    async def __aenter__(self) -> 'AsyncSubscription':
        return await self.start()

    async def __aexit__(self, *exc: Any) -> None:
        await self.close()

    def __aiter__(self) -> 'AsyncSubscription':
        return self

    async def __anext__(self) -> AnswerChange:
        await self.start()
        assert self._queue is not None
        return await self._queue.get()


class AsyncChanges:
    """armor_changes as an async iterator of Change (made by AsyncArmor.changes).

    ``async with armor.changes() as changes: async for change in changes: ...``.

    Args:
        transport: the transport whose node subscribes.
        reference: only this reference's changes (None: all).
    """

    def __init__(self, transport: ArmorTransport, reference: Optional[str] = None):
        self._transport = transport
        self._reference = reference
        self._queue: Optional[_AsyncQueue] = None
        self._watch: Optional[ChangeWatch] = None

    def _start(self) -> _AsyncQueue:
        if self._queue is None:
            self._queue = _AsyncQueue()
            self._watch = ChangeWatch(self._transport, self._queue.put, self._reference)
        return self._queue

    async def close(self) -> None:
        """Stop watching; an iteration in progress ends."""
        if self._watch is not None:
            self._watch.close()
        if self._queue is not None:
            self._queue.end()

    async def __aenter__(self) -> 'AsyncChanges':
        self._start()
        return self

    async def __aexit__(self, *exc: Any) -> None:
        await self.close()

    def __aiter__(self) -> 'AsyncChanges':
        return self

    async def __anext__(self) -> Change:
        return await self._start().get()
