# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""How the web view reads the core: a few requests at a time, shared and cached per revision.

Every page fetch becomes either a read-only view (socket op "view") or a QUERY directive, sent
on the node's own connection to the core, where it waits for the reference's lock and runs
under the reasoner's and SPARQL's time limits as a ROS client's directive does. Three things
keep a busy page from slowing the robot's clients:

- at most ``MAX_CONCURRENT`` web requests reach the core at once (the rest wait here);
- identical view requests in flight are sent once, and their answer is kept until the
  reference changes (its revision, from the change events), so five open pages cost one read
  per change, not five;
- the pages' reads of one reference take turns, each starting no sooner than
  ``BUSY_SHARE_INVERSE - 1`` times the previous one's duration after it ended: on a large
  reference, whose views take the reasoner a while after each change, they keep it busy a
  tenth of the time at most, however fast the robot changes it (the page then follows a
  little later);
- the core itself reads large views in short slices between directives (ViewReads.java).
"""

import asyncio
import collections
import concurrent.futures
import json
import time
from typing import Any, Awaitable, Callable, Dict, Hashable, Optional, Tuple

from armor_service import core_ops
from armor_service.core_process import CoreUnavailable

MAX_CONCURRENT = 2
CACHE_ENTRIES = 256
BUSY_SHARE_INVERSE = 10
# The client name of the page's directives (the recent-directives list hides them by default).
WEB_CLIENT = 'armor_web'


class ViewFailed(Exception):
    """The core refused a view: unknown reference or name, bad parameter, time limit."""

    def __init__(self, exit_code: int, description: str):
        super().__init__(description)
        self.exit_code = exit_code
        self.description = description


class CoreReads:
    """Blocking requests to the core, made awaitable on the web view's event loop."""

    def __init__(self, core, timeout_s: Callable[[], Optional[float]]):
        self._core = core
        self._timeout_s = timeout_s
        self._pool = concurrent.futures.ThreadPoolExecutor(
            max_workers=MAX_CONCURRENT, thread_name_prefix='armor-web-read')

    async def view(self, request: Dict[str, Any]) -> Dict[str, Any]:
        """A view's JSON answer; raises ViewFailed with the core's exit code and reason."""
        answer = await self._send(core_ops.view, request)
        if 'error' in answer:
            raise ViewFailed(answer['error']['exit_code'], answer['error']['description'])
        return answer

    async def directive(self, reference: str, command: str, primary: str, secondary: str,
                        *args: str) -> Dict[str, Any]:
        """A QUERY directive's response, as the core's JSON (the armor_msgs fields)."""
        return await self._send(core_ops.answer, core_ops.directive(
            WEB_CLIENT, reference, command, primary, secondary, args))

    async def _send(self, operation: Callable[..., Dict[str, Any]],
                    request: Dict[str, Any]) -> Dict[str, Any]:
        """A core_ops operation run in the read pool, with the web view's time limit."""
        loop = asyncio.get_running_loop()
        return await loop.run_in_executor(self._pool, operation, self._core.request, request,
                                          self._timeout_s())

    def close(self) -> None:
        self._pool.shutdown(wait=False, cancel_futures=True)


class SharedAnswers:
    """Answers kept while their reference is unchanged; one fetch for all who ask meanwhile.

    A key's answer is reused while ``version`` (a reference's revision, from the change events)
    is the same and it is younger than ``max_age_s``; callers asking for a key being fetched
    wait for that fetch. The least recently used answers go beyond ``CACHE_ENTRIES``.

    Fetches that name a ``reference`` take turns on it, and each starts no sooner than
    ``BUSY_SHARE_INVERSE - 1`` times the previous one's duration after it ended: whatever the
    pages ask, their reads of one reference keep it busy a ``1 / BUSY_SHARE_INVERSE`` share of
    the time at most. An ``on_demand`` fetch (a question a person asked once, such as "why?")
    takes its turn but neither waits for that pause nor sets it: a slow explanation would
    otherwise hold every panel of its reference back for nine times its duration.
    """

    def __init__(self, entries: int = CACHE_ENTRIES):
        self._entries: 'collections.OrderedDict[Hashable, Tuple[Any, float, bytes]]' = \
            collections.OrderedDict()
        self._in_flight: Dict[Tuple[Hashable, Any], asyncio.Task] = {}
        # reference -> its turn (a lock) and when its last fetch ended and how long it took.
        self._turns: Dict[str, asyncio.Lock] = {}
        self._last_fetch: Dict[str, Tuple[float, float]] = {}
        self._limit = entries

    async def get(self, key: Hashable, version: Any, max_age_s: float,
                  fetch: Callable[[], Awaitable[Any]], reference: Optional[str] = None,
                  on_demand: bool = False) -> bytes:
        """The answer of fetch() for key at version, as JSON bytes."""
        kept = self._entries.get(key)
        if kept is not None and kept[0] == version and time.monotonic() - kept[1] < max_age_s:
            self._entries.move_to_end(key)
            return kept[2]
        flight = (key, version)
        task = self._in_flight.get(flight)
        if task is None:
            # A task of its own: a page that goes away does not cancel the others' answer.
            task = asyncio.get_running_loop().create_task(
                self._fetch(key, version, fetch, reference, on_demand))
            self._in_flight[flight] = task
            task.add_done_callback(lambda done: self._landed(flight, done))
        return await asyncio.shield(task)

    def _landed(self, flight: Tuple[Hashable, Any], task: asyncio.Task) -> None:
        self._in_flight.pop(flight, None)
        if not task.cancelled():
            task.exception()  # retrieved: a failure nobody waits for any more is no warning

    async def _fetch(self, key: Hashable, version: Any, fetch: Callable[[], Awaitable[Any]],
                     reference: Optional[str], on_demand: bool) -> bytes:
        if reference is None:
            body = await self._encoded(fetch)
        else:
            async with self._turns.setdefault(reference, asyncio.Lock()):
                if on_demand:
                    body = await self._encoded(fetch)
                else:
                    body = await self._in_turn(reference, fetch)
        self._entries[key] = (version, time.monotonic(), body)
        self._entries.move_to_end(key)
        while len(self._entries) > self._limit:
            self._entries.popitem(last=False)
        return body

    @staticmethod
    async def _encoded(fetch: Callable[[], Awaitable[Any]]) -> bytes:
        return json.dumps(await fetch(), ensure_ascii=False).encode('utf-8')

    async def _in_turn(self, reference: str, fetch: Callable[[], Awaitable[Any]]) -> bytes:
        """A periodic read: after the pause the previous one set, then setting the next."""
        ended, took = self._last_fetch.get(reference, (0.0, 0.0))
        pause = ended + (BUSY_SHARE_INVERSE - 1) * took - time.monotonic()
        if pause > 0:
            await asyncio.sleep(pause)
        started = time.monotonic()
        try:
            return await self._encoded(fetch)
        finally:
            ended = time.monotonic()
            self._last_fetch[reference] = (ended, ended - started)


__all__ = ['CoreReads', 'CoreUnavailable', 'SharedAnswers', 'ViewFailed', 'WEB_CLIENT']
