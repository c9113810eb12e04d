# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The asyncio client: the same methods as Armor and Reference, each one awaitable.

>>> import asyncio
>>> from armor_client.aio import AsyncArmor
>>> async def main():                                                    # doctest: +SKIP
...     async with AsyncArmor('planner') as armor:
...         robotics = armor.reference('robotics')
...         rooms, robots = await asyncio.gather(robotics.instances('Room'),
...                                              robotics.instances('Robot'))
>>> asyncio.run(main())                                                  # doctest: +SKIP

Each directive waits for its answer on a worker thread of this object's own pool (rclpy's
service client is not asyncio-native), so the event loop keeps running and up to
``max_concurrent`` directives are in flight at once. A cancelled await stops waiting; the
directive itself has already been sent and still runs.
"""

import asyncio
import concurrent.futures
import contextlib
import functools
from typing import Any, AsyncIterator, Optional, Sequence

from armor_client.batch import BatchBase
from armor_client.errors import ArmorMountError
from armor_client.operations import ReferenceBase
from armor_client.session import Awaiting, SessionBase
from armor_client.subscriptions import AsyncChanges, AsyncSubscription, Query
from armor_client.transport import directive
from armor_msgs.msg import ArmorDirectiveReq, ArmorDirectiveRes


class AsyncReference(ReferenceBase):
    """The asyncio twin of Reference: every method returns an awaitable of Reference's result.

    ``await ref.instances('Room')`` answers what ``Reference.instances('Room')`` answers;
    ``async with ref.mounted():`` and ``async with ref.batch() as batch:`` work as their sync
    counterparts do.

    Args:
        armor: the session that sends the directives.
        name: the reference name.
        iris: answer entities as full IRIs instead of short names.
    """

    armor: 'AsyncArmor'

    @contextlib.asynccontextmanager
    async def mounted(self) -> AsyncIterator['AsyncReference']:
        """Hold the mount for the duration of an async with block.

        Yields:
            This reference.

        Raises:
            ArmorMountError: another client holds the mount.
        """
        # The mixins are annotated with Reference's results; here each returns an awaitable.
        await self.mount()  # type: ignore[func-returns-value]
        try:
            yield self
        except BaseException:
            # The block's own error is the one to report, not a lost mount (lease, DROP).
            with contextlib.suppress(ArmorMountError):
                await self.unmount()  # type: ignore[func-returns-value]
            raise
        await self.unmount()  # type: ignore[func-returns-value]

    def batch(self) -> 'AsyncBatch':
        """A builder for changes sent as one atomic list when ``async with`` ends.

        Returns:
            An empty AsyncBatch on this reference.
        """
        batch: AsyncBatch = self.armor._batch_with_plugin_methods(self.armor, self.name)
        return batch

    def subscribe(self, query: Query, *, iris: Optional[bool] = None) -> AsyncSubscription:
        """The changes of a query's answer as an async iterator; see Reference.subscribe.

        Args:
            query: a QUERY directive as words, a SPARQL SELECT or ASK, or an ArmorDirectiveReq.
            iris: answers as IRIs (default: this reference's setting).

        Returns:
            AsyncSubscription: ``async with ref.subscribe(q) as changes: async for change in
            changes``; the first AnswerChange is the whole answer.
        """
        return AsyncSubscription(self.armor, self.name, query,
                                 self.answers.iris if iris is None else iris)


class AsyncArmor(Awaiting, SessionBase[AsyncReference]):
    """The asyncio twin of Armor: the same arguments and methods, each a coroutine.

    Args:
        *args: Armor's arguments (client_name, then namespace, node, timeout_s,
            service_wait_s, iris and transport by keyword).
        max_concurrent: how many directives may wait for their answers at once.
        **kwargs: Armor's keyword arguments.
    """

    _reference_class = AsyncReference

    def __init__(self, *args: Any, max_concurrent: int = 8, **kwargs: Any):
        super().__init__(*args, **kwargs)
        self._pool = concurrent.futures.ThreadPoolExecutor(max_concurrent,
                                                           thread_name_prefix='armor-aio')

    async def call(self, reference: str, command: str, primary: str = '', secondary: str = '',
                   args: Sequence[Any] = ()) -> ArmorDirectiveRes:
        """Send any directive as this client; see Armor.call.

        Args:
            reference: the reference name ('' for none).
            command: the command word.
            primary: the primary spec.
            secondary: the secondary spec.
            args: the arguments.

        Returns:
            The raw response, also when the directive failed.

        Raises:
            ArmorServiceCallError: the service could not be called or did not answer in time.
        """
        request = directive(self.client_name, reference, command, primary, secondary, args)
        return await self._in_pool(self.transport.call, request, timeout_s=self.timeout_s)

    async def call_list(self, requests: Sequence[ArmorDirectiveReq]) -> Any:
        """Send an atomic list of directives and return the raw list response.

        Args:
            requests: the directives.

        Returns:
            The ArmorDirectiveList response.

        Raises:
            ArmorServiceCallError: the service could not be called or did not answer in time.
        """
        return await self._in_pool(self.transport.call_list, requests, timeout_s=self.timeout_s)

    def changes(self, reference: Optional[str] = None) -> AsyncChanges:
        """Every acknowledged change the node publishes, as an async iterator of Change.

        Args:
            reference: only this reference's changes (None: every reference's).

        Returns:
            AsyncChanges: ``async with armor.changes() as changes: async for change in ...``.
        """
        return AsyncChanges(self.transport, reference)

    async def close(self) -> None:
        """Release the worker threads and the transport (when this object created it)."""
        self._pool.shutdown(wait=True)
        if self._owns_transport:
            self.transport.close()

    async def __aenter__(self) -> 'AsyncArmor':
        return self

    async def __aexit__(self, *exc: Any) -> None:
        await self.close()

    async def _in_pool(self, function: Any, *args: Any, **kwargs: Any) -> Any:
        loop = asyncio.get_running_loop()
        return await loop.run_in_executor(self._pool, functools.partial(function, *args, **kwargs))


class AsyncBatch(BatchBase):
    """The asyncio twin of Batch: methods queue at once, ``await send()`` sends the list.

    Args:
        armor: the session that sends the list.
        reference: the reference the directives change.
    """

    def __init__(self, armor: AsyncArmor, reference: str):
        super().__init__(armor.client_name, reference)
        self._armor = armor

    async def send(self) -> bool:
        """Send the queued directives as one atomic list; see Batch.send.

        Returns:
            Whether the ontology is consistent after the list.

        Raises:
            ArmorServiceInternalError: a directive failed, so nothing changed (``index`` and
                ``responses`` say which and how).
        """
        return self._finish(await self._armor.call_list(self.requests))

    async def __aenter__(self) -> 'AsyncBatch':
        return self

    async def __aexit__(self, exc_type: Any, *exc: Any) -> None:
        if exc_type is None and self.requests:
            await self.send()


AsyncArmor._batch_class = AsyncBatch
