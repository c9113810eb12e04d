# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Change events from the core, pushed to every open page over its WebSocket, coalesced.

The core announces each acknowledged change (issue 12's change events: reference, revision,
client, directives, consistency) on the node's connection; CoreProcess hands each to
``LiveUpdates.on_event`` on its reader thread. A page needs to know *that* a reference changed
(it then refetches what it shows), not each change: so the hub keeps only the latest revision
and consistency per reference, and how many directives the node answered on each (queries
too: the recent-directives list moves with them), and sends every page that whole table, at
most once per ``COALESCE_S``. A page that reads slowly is sent the newest table when it is
ready for one, never a queue of old ones: memory stays constant however fast the robot
changes its knowledge.
"""

import asyncio
import json
import threading
from typing import Any, Dict, Iterable, Optional, Set

# Changes reach a page well within a second, and a robot changing facts every few milliseconds
# makes each open page refetch ten times a second at most (bench/web_view.py: what the pages
# cost the robot is their browser's CPU, not these refetches).
COALESCE_S = 0.1


class PageChannel:
    """One open page: the latest table not yet sent to it, and a wake-up when there is one."""

    def __init__(self) -> None:
        self._latest: Optional[str] = None
        self._ready = asyncio.Event()

    def offer(self, message: str) -> None:
        self._latest = message  # replaces an unsent older one
        self._ready.set()

    async def next_message(self) -> str:
        await self._ready.wait()
        self._ready.clear()
        message, self._latest = self._latest, None
        assert message is not None
        return message


class LiveUpdates:
    """The table of the references' latest revisions, and the pages it is sent to."""

    def __init__(self, loop: asyncio.AbstractEventLoop):
        self._loop = loop
        self._lock = threading.Lock()
        self._references: Dict[str, Dict[str, Any]] = {}
        self._events = 0
        # Directives the node answered per reference, queries and failures too: what the
        # recent-directives list shows moves with them, not only with the revision.
        self._answered: Dict[str, int] = {}
        self._directives = 0
        self._scheduled = False
        self._pages: Set[PageChannel] = set()
        self._changed = asyncio.Event()

    def on_event(self, event: Dict[str, Any]) -> None:
        """Take one core event (called on the core connection's reader thread: kept short)."""
        if event.get('event') != 'change':
            return
        reference = str(event.get('reference', ''))
        with self._lock:
            self._events += 1
            if _is_drop(event):
                self._references.pop(reference, None)
            else:
                self._references[reference] = {
                    'revision': event.get('revision'),
                    'consistent': event.get('is_consistent'),
                    'client': event.get('client_name', ''),
                    'stamp_ns': event.get('stamp_ns'),
                }
            wake = self._schedule()
        self._wake(wake)

    def on_directives(self, references: Iterable[str]) -> None:
        """Count directives the node answered (called on ROS callback threads: kept short)."""
        with self._lock:
            for reference in references:
                self._answered[reference] = self._answered.get(reference, 0) + 1
                self._directives += 1
            wake = self._schedule()
        self._wake(wake)

    def _schedule(self) -> bool:
        """Under the lock: whether the broadcaster needs waking for this news."""
        wake = not self._scheduled
        self._scheduled = True
        return wake

    def _wake(self, wake: bool) -> None:
        if wake and not self._loop.is_closed():
            self._loop.call_soon_threadsafe(self._changed.set)

    def version(self, reference: Optional[str] = None) -> Any:
        """What answers are kept by: a revision, or (reference None) the count of changes."""
        with self._lock:
            if reference is None:
                return self._events
            known = self._references.get(reference)
            return None if known is None else known['revision']

    def answered(self) -> Any:
        """What the recent-directives list is kept by: changes and directives answered so far."""
        with self._lock:
            return (self._events, self._directives)

    def consistent(self, reference: str) -> Optional[bool]:
        """A reference's consistency after its last change (None: no change seen yet)."""
        with self._lock:
            known = self._references.get(reference)
            return None if known is None else known['consistent']

    def table(self) -> str:
        with self._lock:
            return json.dumps({'type': 'revisions', 'events': self._events,
                               'references': self._references, 'answered': self._answered})

    def join(self) -> PageChannel:
        page = PageChannel()
        page.offer(self.table())
        self._pages.add(page)
        return page

    def leave(self, page: PageChannel) -> None:
        self._pages.discard(page)

    async def broadcast(self) -> None:
        """Send the table to every page after each burst of changes, once per COALESCE_S."""
        while True:
            await self._changed.wait()
            self._changed.clear()
            with self._lock:
                self._scheduled = False
            table = self.table()
            for page in list(self._pages):
                page.offer(table)
            await asyncio.sleep(COALESCE_S)


def _is_drop(event: Dict[str, Any]) -> bool:
    return any(str(d.get('command', '')).upper() == 'DROP' for d in event.get('directives') or []
               if isinstance(d, dict))
