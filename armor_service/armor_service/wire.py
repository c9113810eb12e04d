# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The framed protocol between the node and the Java core.

A frame is a 4-byte big-endian length followed by that many bytes of UTF-8 JSON. Directives
and responses are JSON objects whose keys are the armor_msgs field names, so converting
between a ROS message and a frame is a field-by-field copy with no knowledge of commands.
"""

import json
import socket
import struct

from armor_msgs.msg import (ArmorAnswer, ArmorChange, ArmorDirectiveReq, ArmorDirectiveRes,
                            QueryItem)
from builtin_interfaces.msg import Time

_HEADER = struct.Struct('>I')
# The largest frame either side reads (SizeLimits.FRAME_BYTES in the core, which answers 221 for
# an answer or a list's answers that would not fit): a larger one means a broken connection.
MAX_FRAME_BYTES = 256 << 20

_REQUEST_FIELDS = ('client_name', 'reference_name', 'command', 'primary_command_spec',
                   'secondary_command_spec')


class FrameTooLarge(ValueError):
    """A request whose frame the core would not read: refused before it is sent."""


def encode_frame(payload: dict) -> bytes:
    data = json.dumps(payload, ensure_ascii=False).encode('utf-8')
    if len(data) > MAX_FRAME_BYTES:
        raise FrameTooLarge(f'the request is {len(data):,} bytes as a frame to the core; the '
                            f'limit is {MAX_FRAME_BYTES:,} (docs/commands.md#size-limits)')
    return _HEADER.pack(len(data)) + data


def send_frame(sock: socket.socket, payload: dict) -> None:
    sock.sendall(encode_frame(payload))


def receive_frame(sock: socket.socket) -> dict:
    (length,) = _HEADER.unpack(_receive_exactly(sock, _HEADER.size))
    if length > MAX_FRAME_BYTES:
        raise ConnectionError(f'frame of {length} bytes exceeds the limit')
    return json.loads(_receive_exactly(sock, length).decode('utf-8'))


def _receive_exactly(sock: socket.socket, count: int) -> bytes:
    chunks = []
    while count:
        chunk = sock.recv(min(count, 1 << 20))
        if not chunk:
            raise ConnectionError('the core closed the connection')
        chunks.append(chunk)
        count -= len(chunk)
    return b''.join(chunks)


def directive_to_json(request: ArmorDirectiveReq) -> dict:
    fields = {name: getattr(request, name) for name in _REQUEST_FIELDS}
    fields['args'] = list(request.args)
    return fields


def directive_from_json(fields: dict) -> ArmorDirectiveReq:
    request = ArmorDirectiveReq(**{name: fields.get(name, '') for name in _REQUEST_FIELDS})
    request.args = list(fields.get('args', []))
    return request


def stamp_from_ns(nanoseconds: int) -> Time:
    return Time(sec=nanoseconds // 1_000_000_000, nanosec=nanoseconds % 1_000_000_000)


def change_from_json(event: dict) -> ArmorChange:
    """An ArmorChange from the core's change event (core_process.py describes its keys)."""
    return ArmorChange(
        reference_name=event['reference'], revision=int(event['revision']),
        client_name=event['client_name'],
        directives=[directive_from_json(d) for d in event['directives']],
        exit_code=int(event['exit_code']), is_consistent=bool(event['is_consistent']),
        stamp=stamp_from_ns(int(event['stamp_ns'])))


def answer_from_json(subscription_id: str, sequence: int, event: dict) -> ArmorAnswer:
    """An ArmorAnswer from the core's answer event, numbered by the node."""
    return ArmorAnswer(
        subscription_id=subscription_id, reference_name=event['reference'],
        revision=int(event['revision']), sequence=sequence, added=list(event['added']),
        removed=list(event['removed']), exit_code=int(event['exit_code']),
        error_description=event['error_description'],
        stamp=stamp_from_ns(int(event['stamp_ns'])))


def response_from_json(fields: dict) -> ArmorDirectiveRes:
    response = ArmorDirectiveRes()
    response.success = bool(fields['success'])
    response.timeout = bool(fields['timeout'])
    response.exit_code = int(fields['exit_code'])
    response.error_description = fields['error_description']
    response.is_consistent = bool(fields['is_consistent'])
    response.queried_objects = list(fields['queried_objects'])
    response.sparql_queried_objects = [QueryItem(key=item['key'], value=item['value'])
                                       for item in fields['sparql_queried_objects']]
    return response


def error_response(exit_code: int, description: str) -> ArmorDirectiveRes:
    """A response for failures the node detects itself (the core is unreachable)."""
    response = ArmorDirectiveRes()
    response.success = False
    response.exit_code = exit_code
    response.error_description = description
    return response
