# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A per-user background process that keeps one ROS 2 node discovered for ``armor call``.

Most of an ``armor call``'s wall time is not the directive (the node answers in milliseconds)
but ROS start-up in a fresh process: importing rclpy, creating a node, DDS discovery of the
ARMOR service and proving its response path (measured in docs/python-client.md). Like the
ros2 daemon, the first ``armor call`` starts this relay; later calls hand their directive to
it over a Unix socket and get the answer back without starting ROS at all.

One relay serves one ROS environment: its socket name is a hash of every ROS_*, RMW_* and
DDS vendor variable, so a call with another ROS_DOMAIN_ID (or RMW, discovery range...) gets a
relay of its own. It exits after ARMOR_CALL_RELAY_IDLE_S seconds without a call (default 600).
ARMOR_CALL_RELAY=0 turns it off. ``armor serve`` starts one as soon as its node is ready,
prepared for that node (discovered and its response path proven), so that even the first
``armor call`` takes a fraction of a second.

Protocol: one JSON request line per connection; answers are JSON lines, ``{"state":
"discovering"}`` while the service has not answered this relay yet, then ``{"response": {...}}``
or ``{"error": "..."}``.

The socket lies in $XDG_RUNTIME_DIR/armor-call, else in <temp dir>/armor-<uid>/armor-call. Each
folder on the way is made 0700 or, if it exists, must be a real folder (not a link) of this user
(closed to 0700 if it was looser), and the socket a socket of this user: another user who made
/tmp/armor-<uid> first could otherwise swap the socket, read every directive and answer it. What
fails is refused (RelayRefused, saying why) and the call goes without the relay.
"""

import hashlib
import json
import os
import socket
import stat
import subprocess
import sys
import tempfile
import threading
import time
from typing import Any, Callable, Dict, Optional, Set, Tuple

_ENV_PREFIXES = ('ROS_', 'RMW_', 'FASTDDS', 'FASTRTPS', 'CYCLONEDDS', 'CONNEXT', 'ZENOH')
_RESPONSE_FIELDS = ('success', 'timeout', 'exit_code', 'error_description', 'is_consistent')
# How long a call waits for the service to appear unless told (armor call --wait): the relay
# keeps one transport per namespace and wait, and prepares this one.
DEFAULT_WAIT_S = 5.0


def enabled() -> bool:
    return os.environ.get('ARMOR_CALL_RELAY', '1') != '0'


def socket_path() -> str:
    """The socket of the relay for this user and this ROS environment."""
    environment = sorted((k, v) for k, v in os.environ.items() if k.startswith(_ENV_PREFIXES))
    key = json.dumps([sys.executable, __file__, os.stat(__file__).st_mtime, environment])
    runtime = os.environ.get('XDG_RUNTIME_DIR')
    runtime = _private_folder(runtime) if runtime else _private_folder(
        os.path.join(tempfile.gettempdir(), f'armor-{os.getuid()}'))
    folder = _private_folder(os.path.join(runtime, 'armor-call'))
    return os.path.join(folder, hashlib.sha256(key.encode()).hexdigest()[:20] + '.sock')


class RelayUnavailable(Exception):
    """No relay answered before the request was sent: calling directly is safe."""


class RelayRefused(RelayUnavailable):
    """The relay's folder is not this user's alone: no relay is used or started there."""


def _private_folder(path: str) -> str:
    """path, a folder only this user can reach: made 0700 if missing, else checked as it is."""
    try:
        os.mkdir(path, 0o700)
    except FileExistsError:
        pass
    except OSError as error:
        raise RelayRefused(f'not using the call relay: cannot make {path}: {error}') from error
    info = os.lstat(path)
    uid = os.getuid()
    why = ''
    if stat.S_ISLNK(info.st_mode):
        why = 'is a symbolic link'
    elif not stat.S_ISDIR(info.st_mode):
        why = 'is not a folder'
    elif info.st_uid != uid:
        why = f'belongs to uid {info.st_uid}, not to you (uid {uid})'
    elif info.st_mode & 0o077:
        # The user's own folder, made looser by an older armor call (0755): closed now; what
        # another user might have put in it is checked below it (owners, the socket's too).
        os.chmod(path, 0o700)
    if why:
        raise RelayRefused(f'not using the call relay: {path} {why}; another user could read and '
                           'answer your directives there (remove it, or set XDG_RUNTIME_DIR)')
    return path


def call(request: dict, on_state: Callable[[str], None], connect_s: float = 0.0) -> dict:
    """Send one request to the relay and return its final answer line.

    connect_s: how long to keep trying to reach a relay that is starting.
    Raises RelayUnavailable when no relay took the request, so nothing was sent to ARMOR.
    """
    path = socket_path()
    _refuse_foreign_socket(path)
    deadline = time.monotonic() + connect_s
    while True:
        connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        try:
            connection.settimeout(0.5)
            connection.connect(path)
            connection.sendall(json.dumps(request).encode() + b'\n')
            connection.settimeout(None)
            break
        except OSError as error:
            connection.close()
            if time.monotonic() >= deadline:
                raise RelayUnavailable(str(error)) from error
            time.sleep(0.02)
    with connection, connection.makefile('rb') as lines:
        for line in lines:
            message = json.loads(line)
            if 'state' in message:
                on_state(message['state'])
            else:
                return message
    return {'error': 'the call relay ended before answering; the directive may have run'}


def start_in_background(prepare: Optional[str] = None) -> None:
    """Start a relay for this environment, detached; it gives way if another one is up.

    prepare: a namespace whose ARMOR service the relay discovers right away, before any call.
    """
    subprocess.Popen([sys.executable, '-m', 'armor_client.cli.call_relay', socket_path()]
                     + ([] if prepare is None else ['--prepare', prepare]),
                     stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                     stderr=subprocess.DEVNULL, start_new_session=True, close_fds=True)


def prepare(namespace: str) -> bool:
    """Have this environment's relay discover the ARMOR service of namespace now (start one).

    Returns whether the relay had already proven that service's response path.
    """
    try:
        return call({'prepare': namespace}, lambda state: None)['ready']
    except RelayUnavailable:
        start_in_background(prepare=namespace)
        return False


def stop() -> bool:
    """Ask the relay of this environment to exit; whether one was there."""
    try:
        return 'stopped' in call({'stop': True}, lambda state: None)
    except RelayUnavailable:
        return False


class _Relay:
    def __init__(self, path: str, idle_s: float, prepare: Optional[str] = None):
        self._path = path
        self._prepare_first = prepare
        self._idle_s = idle_s
        self._last = time.monotonic()
        self._transports: Dict[Tuple[str, float], Any] = {}
        self._proven: Set[str] = set()
        self._lock = threading.Lock()
        self._server: Optional[socket.socket] = None

    def serve(self) -> None:
        self._server = _bind(self._path)
        if self._server is None:
            return  # another relay serves this environment
        import rclpy
        from rclpy.signals import SignalHandlerOptions
        # No rclpy signal handlers: SIGTERM and SIGINT end the relay as they end any process.
        rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
        try:
            threading.Thread(target=self._exit_when_idle, daemon=True).start()
            if self._prepare_first is not None:
                self._start_preparing(self._prepare_first)
            while True:
                connection, _ = self._server.accept()
                threading.Thread(target=self._handle, args=(connection,), daemon=True).start()
        except OSError:
            pass  # the socket was closed: idle or stopped
        finally:
            self._close_socket()
            with self._lock:
                for transport in self._transports.values():
                    transport.close()
            rclpy.try_shutdown()

    def _transport(self, namespace: str, wait_s: float):
        from armor_client.transport import ArmorTransport
        with self._lock:
            key = (namespace, wait_s)
            if key not in self._transports:
                self._transports[key] = ArmorTransport(namespace=namespace, service_wait_s=wait_s)
            return self._transports[key]

    def _handle(self, connection: socket.socket) -> None:
        self._last = time.monotonic()
        with connection, connection.makefile('rwb') as stream:
            def send(message: dict) -> None:
                stream.write(json.dumps(message).encode() + b'\n')
                stream.flush()
            try:
                request = json.loads(stream.readline())
                if request.get('stop'):
                    # Gone before it says so: a caller told 'stopped' finds no socket left.
                    self._close_socket()
                    send({'stopped': True})
                    return
                if 'prepare' in request:
                    self._start_preparing(request['prepare'])
                    send({'preparing': request['prepare'],
                          'ready': request['prepare'] in self._proven})
                    return
                send(self._answer(request, send))
            except Exception as error:  # the relay outlives any one bad call
                try:
                    send({'error': str(error)})
                except OSError:
                    pass
            finally:
                self._last = time.monotonic()

    def _answer(self, request: dict, send: Callable[[dict], None]) -> dict:
        from armor_client.commands import find_on
        from armor_client.errors import ArmorServiceCallError
        from armor_client.transport import directive
        namespace, wait_s = request.get('namespace', ''), float(request['wait_s'])
        transport = self._transport(namespace, wait_s)
        if namespace not in self._proven:
            send({'state': 'discovering'})
        fields = request['directive']
        words = (fields['command'], fields['primary'], fields['secondary'])
        try:
            find_on(transport, *words)  # a plugin's command: which of its arguments are paths
            # Relative paths are the caller's: resolved against its directory, not the relay's.
            response = transport.call(directive(fields['client'], fields['reference'], *words,
                                                fields['args'], cwd=request.get('cwd')),
                                      timeout_s=request.get('timeout_s'))
        except ArmorServiceCallError as error:
            return {'error': str(error), 'unreachable': True}
        self._proven.add(namespace)
        answer = {name: getattr(response, name) for name in _RESPONSE_FIELDS}
        answer['queried_objects'] = list(response.queried_objects)
        answer['sparql_queried_objects'] = [{'key': i.key, 'value': i.value}
                                            for i in response.sparql_queried_objects]
        return {'response': answer}

    def _start_preparing(self, namespace: str) -> None:
        if namespace not in self._proven:
            threading.Thread(target=self._prepare, args=(namespace,), daemon=True).start()

    def _prepare(self, namespace: str) -> None:
        """Discover the service of namespace and prove its response path, as a call would.

        The node may still be starting: tries until it answers or the relay ends.
        """
        from armor_client.errors import ArmorServiceCallError
        from armor_client.transport import directive
        transport = self._transport(namespace, DEFAULT_WAIT_S)
        while self._server is not None and namespace not in self._proven:
            try:
                transport.call(directive('armor_cli', '', 'GET', 'ALL', 'REFS'),
                               timeout_s=DEFAULT_WAIT_S)
                self._proven.add(namespace)
            except ArmorServiceCallError:
                pass

    def _exit_when_idle(self) -> None:
        while self._server is not None:
            time.sleep(min(5.0, self._idle_s))
            if time.monotonic() - self._last > self._idle_s:
                self._close_socket()

    def _close_socket(self) -> None:
        server, self._server = self._server, None
        if server is not None:
            try:
                os.unlink(self._path)
            except OSError:
                pass
            try:
                server.shutdown(socket.SHUT_RDWR)  # wakes the accept() in serve()
            except OSError:
                pass
            server.close()


def _refuse_foreign_socket(path: str) -> None:
    """Refuse a socket file that is not a socket of this user's (another user planted it)."""
    try:
        info = os.lstat(path)
    except FileNotFoundError:
        return
    if not stat.S_ISSOCK(info.st_mode) or info.st_uid != os.getuid():
        raise RelayRefused(f'not using the call relay: {path} is not a socket of yours (uid '
                           f'{info.st_uid}); another user could read and answer your directives '
                           'there (remove it)')


def _bind(path: str) -> Optional[socket.socket]:
    """Listen on path, replacing a stale socket; None if a relay has it, or another user can."""
    try:
        _private_folder(os.path.dirname(path))
    except RelayRefused:
        return None
    probe = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    try:
        probe.connect(path)
        probe.close()
        return None
    except OSError:
        probe.close()
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass
    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    server.bind(path)
    os.chmod(path, 0o600)
    server.listen(64)
    return server


def main() -> None:
    arguments = sys.argv[1:]
    namespace = None
    if '--prepare' in arguments:
        at = arguments.index('--prepare')
        namespace = arguments[at + 1]
        del arguments[at:at + 2]
    path = arguments[0] if arguments else socket_path()
    _Relay(path, float(os.environ.get('ARMOR_CALL_RELAY_IDLE_S', '600')), namespace).serve()


if __name__ == '__main__':
    main()
