# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Owns the Java knowledge core: starts it, talks to it, notices its death, starts it again.

Reasoners hang, overflow their stack or exhaust memory on real ontologies. Running them in a
child process means the node survives all three: requests in flight when the core dies fail
with CORE_UNAVAILABLE, and a new core is started in the background.

Events: besides answering requests, the core pushes frames nobody asked for (no ``id``).
``CoreProcess.add_event_listener(callback)`` hands each to ``callback(event)``, a dict, on one
delivery thread, in the order the core sent them (so per reference in revision order). Kinds,
by ``event["event"]``:

``"change"``: one acknowledged change of a reference (a directive, or a whole atomic list)::

    {"event": "change", "reference": str, "revision": int, "client_name": str,
     "directives": [directive dict, ...], "exit_code": 0, "is_consistent": bool,
     "stamp_ns": int}

  ``revision`` is the reference's revision after the change: 0 for the LOAD or CREATE that
  made it, one more for each later change (a list: one for each reference it changed), and one
  more for its DROP, its last event. Failed and rolled-back directives make none. Revisions
  live in the journal, so they continue across core and node restarts. A directive dict has
  the armor_msgs ArmorDirectiveReq field names. ``stamp_ns`` is when the core acknowledged the
  change (nanoseconds since the Unix epoch).

A listener must return quickly (it holds up the events after it) and should not raise (an
exception is logged and the next listener still gets the event). Events of a core that dies
are not repeated by the next one: a listener that needs every change compares revisions.
"""

import concurrent.futures
import itertools
import json
import logging
import os
import queue
import shutil
import socket
import subprocess
import tempfile
import threading
import time
from typing import Any, Callable, Dict, List, Optional

from armor_service import core_ops, wire

_READY_PREFIX = 'ARMOR core ready on '
# What the core prints instead of the ready line when it cannot start (CoreMain.java).
_CANNOT_START_PREFIX = 'ARMOR core cannot start: '
# Every line the core writes on stderr starts with its level (server/ProcessLog.java).
_LEVELS = {'ERROR': 'error', 'WARN': 'warning', 'INFO': 'info', 'DEBUG': 'debug',
           'TRACE': 'debug'}


# Options that say how the JVM shares classes: given any, the node adds no archive of its own.
_SHARING_OPTIONS = ('-Xshare', '-XX:SharedArchiveFile', '-XX:ArchiveClassesAtExit')


def _class_archive(jar: str, jvm_options: tuple) -> List[str]:
    """The JVM options that map the core's classes from the archive set-up made beside the jar.

    tools/setup.sh records armor-core.jsa (tools/core_archive.py): a start that maps the classes
    spends about a third less CPU than one that loads them. An archive the JVM cannot use (the
    jar or the JDK changed since) is ignored without a word (-Xshare:auto, its log off); no
    archive, no options.
    """
    archive = os.path.splitext(jar)[0] + '.jsa'
    if any(option.startswith(_SHARING_OPTIONS) for option in jvm_options) \
            or not os.path.isfile(archive):
        return []
    return [f'-XX:SharedArchiveFile={archive}', '-Xshare:auto', '-Xlog:cds=off',
            '-Xlog:cds+dynamic=off']


class CoreUnavailable(Exception):
    """The core died, is restarting, or could not be reached in time."""


class CoreProcess:
    """A supervised core process reached over a Unix domain socket.

    One connection carries all requests: each has an id, the core answers each on its own
    thread, and a reader thread hands every answer to the caller waiting for that id. Safe to
    call from many threads at once.
    """

    def __init__(self, jar: str, config: dict, *, java: str = 'java',
                 jvm_options: tuple = (), start_timeout_s: float = 120.0,
                 restart_wait_s: float = 60.0,
                 logger: Optional[logging.Logger] = None,
                 on_ready: Optional[Callable[[Callable[[dict], dict]], None]] = None):
        """Configure; nothing starts before start().

        on_ready(send) runs after every start, before any caller's request reaches the new
        core: it restores state through send(payload) -> reply.
        """
        self._log = logger or logging.getLogger('armor_core')
        # The core writes its DEBUG lines (and the reasoners' chatter) only when they are shown.
        debug = ['-Darmor.log.level=debug'] if _shows_debug(self._log) else []
        self._command = [java, *_class_archive(jar, jvm_options), *jvm_options, *debug,
                         '-jar', jar]
        self._config = json.dumps(config)
        self._start_timeout_s = start_timeout_s
        self._restart_wait_s = restart_wait_s
        self._on_ready = on_ready
        self._ids = itertools.count(1)
        self._state = threading.Condition()
        self._send_lock = threading.Lock()
        self._pending: dict = {}
        self._process: Optional[subprocess.Popen] = None
        self._socket: Optional[socket.socket] = None
        self._generation = 0
        self._lost = 0
        self._restarting = False
        self._available = False
        self._stopping = False
        self._socket_dir = tempfile.mkdtemp(prefix='armor-core-')
        self._event_listeners: List[Callable[[Dict[str, Any]], None]] = []
        self._events: 'queue.Queue[Optional[dict]]' = queue.Queue()
        self._event_thread: Optional[threading.Thread] = None

    @property
    def pid(self) -> Optional[int]:
        process = self._process
        return process.pid if process else None

    def start(self) -> None:
        """Start the core and connect; raises CoreUnavailable if it does not come up."""
        with self._state:
            self._generation += 1
            generation = self._generation
        socket_path = os.path.join(self._socket_dir, f'core-{generation}.sock')
        # A session of its own: Ctrl-C in the node's terminal must not kill the core behind
        # the node's back. The core exits by itself when its stdin (this pipe) closes.
        process = subprocess.Popen(
            [*self._command, socket_path, self._config], stdin=subprocess.PIPE,
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
        threading.Thread(target=self._forward_stderr, args=(process,), daemon=True,
                         name='armor-core-stderr').start()
        try:
            self._wait_until_ready(process)
            connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            connection.connect(socket_path)
        except Exception as error:
            process.kill()
            process.wait()
            raise CoreUnavailable(f'the knowledge core did not start: {error}') from error
        with self._state:
            self._process = process
            self._socket = connection
        threading.Thread(target=self._read_replies, args=(connection, generation), daemon=True,
                         name='armor-core-reader').start()
        threading.Thread(target=self._watch_exit, args=(process, generation), daemon=True,
                         name='armor-core-watch').start()
        if self._on_ready:
            try:
                self._on_ready(lambda payload: self._exchange(payload, connection, generation,
                                                              None))
            except Exception as error:
                with self._state:
                    self._lost = generation
                process.kill()
                raise CoreUnavailable(f'restoring the new core failed: {error}') from error
        with self._state:
            if generation == self._generation and process.poll() is None:
                self._available = True
                self._state.notify_all()
        self._log.info(f'knowledge core {process.pid} ready on {socket_path}')

    def request(self, payload: dict, timeout_s: Optional[float] = None) -> dict:
        """Send one request and wait for its reply (forever when timeout_s is None)."""
        with self._state:
            if not self._state.wait_for(lambda: self._available or self._stopping,
                                        timeout=self._restart_wait_s):
                raise CoreUnavailable(
                    f'the knowledge core is restarting and was not back within '
                    f'{self._restart_wait_s:.0f} s')
            if self._stopping:
                raise CoreUnavailable('the node is shutting down')
            connection = self._socket
            generation = self._generation
        return self._exchange(payload, connection, generation, timeout_s)

    def add_event_listener(self, callback: Callable[[Dict[str, Any]], None]) -> None:
        """Call callback(event) for every event the core pushes from now on (module docstring)."""
        with self._state:
            self._event_listeners = [*self._event_listeners, callback]
            if self._event_thread is None:
                self._event_thread = threading.Thread(target=self._deliver_events, daemon=True,
                                                      name='armor-core-events')
                self._event_thread.start()

    def remove_event_listener(self, callback: Callable[[Dict[str, Any]], None]) -> None:
        """Stop calling callback (a no-op for one never added)."""
        with self._state:
            self._event_listeners = [c for c in self._event_listeners if c is not callback]

    def catalogue(self, timeout_s: Optional[float] = None) -> dict:
        """The running core's catalogue: commands (with plugins'), exit codes, settings."""
        return core_ops.catalogue(self.request, timeout_s)

    def _exchange(self, payload: dict, connection: socket.socket, generation: int,
                  timeout_s: Optional[float]) -> dict:
        with self._state:
            request_id = next(self._ids)
        # Encoded outside the send lock: a large request never holds up the others.
        frame = wire.encode_frame({'id': request_id, **payload})
        with self._state:
            future: concurrent.futures.Future = concurrent.futures.Future()
            self._pending[request_id] = future
        try:
            with self._send_lock:
                connection.sendall(frame)
        except OSError as error:
            self._core_lost(generation, f'sending to the core failed: {error}')
        try:
            reply = future.result(timeout=timeout_s)
        except concurrent.futures.TimeoutError:
            with self._state:
                self._pending.pop(request_id, None)
            raise
        if 'error' in reply:
            raise CoreUnavailable(f'the core refused the request: {reply["error"]}')
        return reply

    def stop(self) -> None:
        """Stop supervising and end the core."""
        with self._state:
            self._stopping = True
            self._available = False
            process, connection = self._process, self._socket
            self._fail_pending('the node is shutting down')
            self._state.notify_all()
        self._events.put(None)
        if connection:
            connection.close()
        if process and process.poll() is None:
            process.stdin.close()
            try:
                process.wait(timeout=5)
            except (subprocess.TimeoutExpired, OSError):
                # OSError: the timed wait sleeps, which fails under a faked clock (libfaketime).
                process.kill()
                process.wait()
        shutil.rmtree(self._socket_dir, ignore_errors=True)

    def _wait_until_ready(self, process: subprocess.Popen) -> None:
        deadline = time.monotonic() + self._start_timeout_s
        ready = threading.Event()
        failure = []

        def read_stdout():
            for raw in process.stdout:
                line = raw.decode('utf-8', 'replace').rstrip()
                if line.startswith(_READY_PREFIX):
                    ready.set()
                elif line.startswith(_CANNOT_START_PREFIX):
                    failure.append(line[len(_CANNOT_START_PREFIX):])
                elif line:
                    self._log.info(f'core: {line}')
            failure.append(f'exited with code {process.wait()}')
            ready.set()

        threading.Thread(target=read_stdout, daemon=True, name='armor-core-stdout').start()
        if not ready.wait(max(0.0, deadline - time.monotonic())):
            raise TimeoutError(f'no ready line within {self._start_timeout_s:.0f} s')
        if failure and process.poll() is not None:
            raise RuntimeError(failure[0])

    def _forward_stderr(self, process: subprocess.Popen) -> None:
        """Log each core line at its own level; lines without one (a stack trace's) at the last."""
        level = 'warning'
        for raw in process.stderr:
            line = raw.decode('utf-8', 'replace').rstrip()
            if not line:
                continue
            word, _, rest = line.partition(' ')
            if word in _LEVELS:
                level, line = _LEVELS[word], rest
            # One call site per level: rclpy refuses a call site whose severity changes.
            if level == 'error':
                self._log.error(f'core: {line}')
            elif level == 'warning':
                self._log.warning(f'core: {line}')
            elif level == 'info':
                self._log.info(f'core: {line}')
            else:
                self._log.debug(f'core: {line}')

    def _read_replies(self, connection: socket.socket, generation: int) -> None:
        try:
            while True:
                reply = wire.receive_frame(connection)
                if 'id' not in reply:
                    if 'event' in reply and self._event_listeners:
                        self._events.put(reply)
                    continue
                with self._state:
                    future = self._pending.pop(reply.get('id'), None)
                if future is not None:
                    future.set_result(reply)
        except (OSError, ConnectionError, ValueError) as error:
            self._core_lost(generation, f'connection to the core lost ({error})')

    def _deliver_events(self) -> None:
        """Hand each event to every listener, in order, off the reader thread."""
        while True:
            event = self._events.get()
            if event is None:
                return
            for listener in self._event_listeners:
                try:
                    listener(event)
                except Exception as error:  # a listener's bug must not stop the others' events
                    self._log.error(f'an event listener failed on {event.get("event")} event '
                                    f'of "{event.get("reference")}": {error!r}')

    def _watch_exit(self, process: subprocess.Popen, generation: int) -> None:
        code = process.wait()
        self._core_lost(generation, f'the knowledge core exited with code {code}')

    def _core_lost(self, generation: int, reason: str) -> None:
        with self._state:
            if generation != self._generation or self._lost == generation:
                return
            self._lost = generation
            # A core ended by stop() is no loss: the node is shutting down, and says nothing.
            quiet = self._stopping
            self._available = False
            self._fail_pending(reason)
            process, connection = self._process, self._socket
            restart = not self._stopping and not self._restarting
            self._restarting = self._restarting or restart
        if connection:
            connection.close()
        if process and process.poll() is None:
            process.kill()
        if process:
            # The next core must not start while this one can still write to the state directory.
            process.wait()
        if quiet:
            return
        self._log.error(reason)
        if restart:
            self._log.error('starting a new core')
            threading.Thread(target=self._restart, daemon=True, name='armor-core-restart').start()

    def _restart(self) -> None:
        """Start cores until one comes up; only one of these runs at a time."""
        delay_s = 0.5
        try:
            while not self._stopping:
                try:
                    self.start()
                    return
                except CoreUnavailable as error:
                    self._log.error(f'{error}; retrying in {delay_s:.1f} s')
                    time.sleep(delay_s)
                    delay_s = min(delay_s * 2, 10.0)
        finally:
            with self._state:
                self._restarting = False

    def _fail_pending(self, reason: str) -> None:
        """Answer every waiting request with the failure; the caller holds self._state."""
        pending, self._pending = self._pending, {}
        for future in pending.values():
            future.set_exception(CoreUnavailable(reason))


def _shows_debug(logger) -> bool:
    """Whether a logger (rclpy's or the standard library's) shows DEBUG lines."""
    if hasattr(logger, 'get_effective_level'):
        from rclpy.logging import LoggingSeverity
        return logger.get_effective_level() <= LoggingSeverity.DEBUG
    return logger.isEnabledFor(logging.DEBUG)
