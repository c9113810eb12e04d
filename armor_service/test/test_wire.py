# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Frames and message conversion, without a core or ROS graph."""

import socket
import threading

from armor_msgs.msg import ArmorDirectiveReq
from armor_service import wire
import pytest


def test_frames_round_trip_including_unicode_and_large_payloads():
    left, right = socket.socketpair()
    with left, right:
        payload = {'id': 7, 'args': ['Küche', '机器人', 'x' * 300_000]}
        # Larger than the socket buffer: the sender must run while the receiver reads.
        sender = threading.Thread(target=wire.send_frame, args=(left, payload))
        sender.start()
        assert wire.receive_frame(right) == payload
        sender.join()


def test_a_closed_peer_is_a_connection_error():
    left, right = socket.socketpair()
    left.close()
    with right, pytest.raises(ConnectionError):
        wire.receive_frame(right)


def test_directive_fields_are_copied_by_name():
    request = ArmorDirectiveReq(client_name='c', reference_name='r', command='QUERY',
                                primary_command_spec='IND', secondary_command_spec='CLASS',
                                args=['Room'])
    assert wire.directive_to_json(request) == {
        'client_name': 'c', 'reference_name': 'r', 'command': 'QUERY',
        'primary_command_spec': 'IND', 'secondary_command_spec': 'CLASS', 'args': ['Room']}


def test_response_fields_are_copied_by_name():
    response = wire.response_from_json({
        'success': False, 'timeout': True, 'exit_code': 211, 'error_description': 'slow',
        'is_consistent': True, 'queried_objects': ['a'],
        'sparql_queried_objects': [{'key': 'x', 'value': '1'}, {'key': '', 'value': ''}]})
    assert (response.success, response.timeout, response.exit_code) == (False, True, 211)
    assert response.error_description == 'slow' and response.is_consistent
    assert list(response.queried_objects) == ['a']
    assert [(i.key, i.value) for i in response.sparql_queried_objects] == [('x', '1'), ('', '')]


def test_a_frame_the_core_would_not_read_is_refused_before_sending(monkeypatch):
    monkeypatch.setattr(wire, 'MAX_FRAME_BYTES', 1000)
    left, right = socket.socketpair()
    with left, right:
        with pytest.raises(wire.FrameTooLarge, match='limit is 1,000'):
            wire.send_frame(left, {'id': 1, 'args': ['x' * 2000]})
        right.setblocking(False)
        with pytest.raises(BlockingIOError):
            right.recv(1)
