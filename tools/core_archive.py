# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Write the core's class data archive (AppCDS): python3 tools/core_archive.py JAR ARCHIVE.

Every start of the core spends a few CPU-seconds loading and verifying the same few thousand
classes of the OWL API, the reasoners and Jena. A JVM that maps them from an archive made for
this jar skips that work (CoreProcess passes the archive found beside the jar; a JVM that
cannot use it, because the jar or the JDK changed since, ignores it). The archive holds the
classes one short run used: this script starts the core with -XX:ArchiveClassesAtExit, has it
load robotics.owl with the default reasoner and with HermiT, change, reason, query and save,
then closes its stdin; the JVM writes the archive as it exits.

Standard library only: it runs during set-up, before anything is sourced.
"""

import itertools
import json
import os
import pathlib
import socket
import struct
import subprocess
import sys
import tempfile
from typing import Callable

# The core's socket operations (stdlib only, so importable before the venv and messages exist).
REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / 'armor_service' / 'armor_service'))
import core_ops  # noqa: E402

ROBOTICS = REPO / 'ontologies' / 'robotics.owl'
# The node's default options (armor_service/parameters.py, jvm_options): an archive is made
# for one garbage collector's layout of the classes it holds.
JVM_OPTIONS = ['-Xmx4g', '-XX:+UseSerialGC', '-XX:+ExitOnOutOfMemoryError']
# What a short session does: each command loads the classes its answer needs.
SESSION = [
    ('robotics', 'LOAD', 'FILE', '', [str(ROBOTICS), '', 'false', '', 'false']),
    ('robotics', 'ADD', 'IND', 'CLASS', ['probe', 'Robot']),
    ('robotics', 'ADD', 'OBJECTPROP', 'IND', ['isIn', 'probe', 'kitchen']),
    ('robotics', 'REASON', '', '', []),
    ('robotics', 'QUERY', 'IND', 'CLASS', ['OccupiedRoom']),
    ('robotics', 'QUERY', 'OBJECTPROP', 'IND', ['isIn', 'probe']),
    ('robotics', 'QUERY', 'SPARQL', '',
     ['SELECT ?x WHERE { ?x a <http://www.example.org/robotics#Robot> }']),
    ('hermit', 'LOAD', 'FILE', '', [str(ROBOTICS), '', 'true', 'HERMIT', 'true']),
    ('hermit', 'ADD', 'CLASS', 'CLASS', ['Charger', 'Location']),
    ('hermit', 'REASON', '', '', []),
    ('hermit', 'QUERY', 'CLASS', 'CLASS', ['Location']),
    ('hermit', 'QUERY', 'IND', 'DL', ['Agent and isIn some Room']),
    ('hermit', 'SAVE', '', '', ['{scratch}/robotics.ttl', 'turtle']),
]


def sender(connection: socket.socket) -> Callable[[dict], dict]:
    """core_ops' ``send`` over the core's framed socket (a 4-byte length, then JSON: wire.py,
    which needs the built messages this step does not wait for)."""
    request_ids = itertools.count(1)

    def send(frame: dict) -> dict:
        request_id = next(request_ids)
        data = json.dumps({'id': request_id, **frame}).encode()
        connection.sendall(struct.pack('>I', len(data)) + data)
        while True:
            (length,) = struct.unpack('>I', connection.recv(4, socket.MSG_WAITALL))
            reply = json.loads(connection.recv(length, socket.MSG_WAITALL))
            if reply.get('id') == request_id:  # events (no id) are not what we wait for
                return reply
    return send


def main(jar: str, archive: str) -> None:
    scratch = tempfile.mkdtemp(prefix='armor-archive-')
    socket_path = os.path.join(scratch, 'core.sock')
    config = {'allowed_dirs': [str(ROBOTICS.parent)], 'write_dirs': [scratch],
              'state_dir': os.path.join(scratch, 'state'), 'restore_state': False}
    # C1 alone: the session is too short for the optimising JIT to pay back (10 instead of 13
    # CPU-s), and an archive holds classes, not compiled code, so any JIT may map it.
    core = subprocess.Popen(
        ['java', *JVM_OPTIONS, '-XX:TieredStopAtLevel=1', f'-XX:ArchiveClassesAtExit={archive}',
         '-jar', jar, socket_path,
         json.dumps(config)], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    try:
        for line in core.stdout:
            if line.startswith(b'ARMOR core ready on '):
                break
        else:
            raise SystemExit(f'the core exited with {core.wait()} before it was ready')
        connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        connection.connect(socket_path)
        send = sender(connection)
        for reference, command, primary, secondary, args in SESSION:
            answer = core_ops.answer(send, core_ops.directive(
                'archive', reference, command, primary, secondary,
                [arg.replace('{scratch}', scratch) for arg in args]))
            if not answer['success']:
                raise SystemExit(f'{reference} {command} {primary} {secondary}: '
                                 f'{answer["exit_code"]} {answer["error_description"]}')
        connection.close()
        core.stdin.close()  # the core halts; its JVM writes the archive on the way out
        if core.wait(timeout=300) != 0:
            raise SystemExit(f'the core exited with {core.returncode}')
    finally:
        if core.poll() is None:
            core.kill()
        subprocess.run(['rm', '-rf', scratch], check=False)
    if not os.path.isfile(archive):
        raise SystemExit(f'the JVM wrote no archive at {archive}')


if __name__ == '__main__':
    main(*sys.argv[1:])
