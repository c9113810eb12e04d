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
ARMOR_CALL_RELAY=0 turns it off.

Protocol: one JSON request line per connection; answers are JSON lines, ``{"state":
"discovering"}`` while the service has not answered this relay yet, then ``{"response": {...}}``
or ``{"error": "..."}``.
"""

import hashlib
import json
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time
from typing import Any, Callable, Dict, Optional, Set, Tuple

_ENV_PREFIXES = ('ROS_', 'RMW_', 'FASTDDS', 'FASTRTPS', 'CYCLONEDDS', 'CONNEXT', 'ZENOH')
_RESPONSE_FIELDS = ('success', 'timeout', 'exit_code', 'error_description', 'is_consistent')


def enabled() -> bool:
    return os.environ.get('ARMOR_CALL_RELAY', '1') != '0'


def socket_path() -> str:
    """The socket of the relay for this user and this ROS environment."""
    environment = sorted((k, v) for k, v in os.environ.items() if k.startswith(_ENV_PREFIXES))
    key = json.dumps([sys.executable, __file__, os.stat(__file__).st_mtime, environment])
    runtime = os.environ.get('XDG_RUNTIME_DIR') or os.path.join(tempfile.gettempdir(),
                                                                f'armor-{os.getuid()}')
    folder = os.path.join(runtime, 'armor-call')
    os.makedirs(folder, mode=0o700, exist_ok=True)
    return os.path.join(folder, hashlib.sha256(key.encode()).hexdigest()[:20] + '.sock')


class RelayUnavailable(Exception):
    """No relay answered before the request was sent: calling directly is safe."""


def call(request: dict, on_state: Callable[[str], None]) -> dict:
    """Send one request to the relay and return its final answer line.

    Raises RelayUnavailable when no relay took the request, so nothing was sent to ARMOR.
    """
    connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    try:
        connection.settimeout(0.5)
        connection.connect(socket_path())
        connection.sendall(json.dumps(request).encode() + b'\n')
        connection.settimeout(None)
    except OSError as error:
        connection.close()
        raise RelayUnavailable(str(error)) from error
    with connection, connection.makefile('rb') as lines:
        for line in lines:
            message = json.loads(line)
            if 'state' in message:
                on_state(message['state'])
            else:
                return message
    return {'error': 'the call relay ended before answering; the directive may have run'}


def start_in_background() -> None:
    """Start a relay for this environment, detached; it gives way if another one is up."""
    subprocess.Popen([sys.executable, '-m', 'armor_client.cli.call_relay', socket_path()],
                     stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                     stderr=subprocess.DEVNULL, start_new_session=True, close_fds=True)


def stop() -> bool:
    """Ask the relay of this environment to exit; whether one was there."""
    try:
        return 'stopped' in call({'stop': True}, lambda state: None)
    except RelayUnavailable:
        return False


class _Relay:
    def __init__(self, path: str, idle_s: float):
        self._path = path
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


def _bind(path: str) -> Optional[socket.socket]:
    """Listen on path, replacing a stale socket; None when a live relay has it."""
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
    path = sys.argv[1] if len(sys.argv) > 1 else socket_path()
    _Relay(path, float(os.environ.get('ARMOR_CALL_RELAY_IDLE_S', '600'))).serve()


if __name__ == '__main__':
    main()
