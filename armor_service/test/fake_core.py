# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A stand-in for the Java core, speaking its socket protocol, for CoreProcess's unit tests.

Started as ``fake_core.py SOCKET_PATH CONFIG_JSON`` (through a fake ``java`` that drops
``-jar``). It appends a line to CONFIG_JSON's ``starts_file`` at every start, prints the ready
line, answers each request on its own thread, and exits when stdin closes, as the core does.
The directive's command says what to do:
  ECHO arg      answer at once with [arg]
  BARRIER n     answer only once n BARRIER requests are waiting (so n must be in flight at once)
  HANG          never answer
  DIE           exit at once with code 9 (the core dying mid-request)
  EVENTS n      push n change events (revisions 1..n of reference r, frames without an id),
                then answer
"""

import json
import os
import socket
import sys
import threading

from armor_service import wire


def main() -> None:
    socket_path, config = sys.argv[1], json.loads(sys.argv[2])
    with open(config['starts_file'], 'a') as starts:
        starts.write(f'{os.getpid()}\n')
    if config.get('refuse_to_start'):
        print('ARMOR core cannot start: told to refuse', flush=True)
        sys.exit(3)
    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    server.bind(socket_path)
    server.listen()
    threading.Thread(target=lambda: (sys.stdin.read(), os._exit(0)), daemon=True).start()
    print(f'ARMOR core ready on {socket_path}', flush=True)
    barrier = threading.Condition()
    waiting = [0]
    while True:
        connection, _ = server.accept()
        threading.Thread(target=serve, args=(connection, barrier, waiting), daemon=True).start()


def serve(connection: socket.socket, barrier: threading.Condition, waiting: list) -> None:
    send_lock = threading.Lock()
    while True:
        request = wire.receive_frame(connection)
        threading.Thread(target=answer, args=(connection, send_lock, request, barrier, waiting),
                         daemon=True).start()


def answer(connection, send_lock, request, barrier, waiting) -> None:
    if request.get('op') != 'directive':
        reply = {'id': request['id'], 'pong': True}
    else:
        directive = request['directive']
        command, args = directive['command'], directive['args']
        if command == 'DIE':
            os._exit(9)
        if command == 'HANG':
            return
        if command == 'EVENTS':
            for revision in range(1, int(args[0]) + 1):
                with send_lock:
                    wire.send_frame(connection, {
                        'event': 'change', 'reference': 'r', 'revision': revision,
                        'client_name': 't', 'directives': [directive], 'exit_code': 0,
                        'is_consistent': True, 'stamp_ns': 0})
        if command == 'BARRIER':
            with barrier:
                waiting[0] += 1
                barrier.notify_all()
                barrier.wait_for(lambda: waiting[0] >= int(args[0]))
        reply = {'id': request['id'], 'response': {
            'success': True, 'timeout': False, 'exit_code': 0, 'error_description': '',
            'is_consistent': True, 'queried_objects': list(args), 'sparql_queried_objects': []}}
    with send_lock:
        wire.send_frame(connection, reply)


if __name__ == '__main__':
    main()
