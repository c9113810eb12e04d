# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Node parameters: declared once and typed, taken in the forms users type, misspellings refused.

Each test starts a node of its own (in its own namespace) with the parameters under test.
"""

import json
import pathlib
import shutil
import subprocess
import time

from armor_client import ArmorTransport
from armor_service.parameters import NODE_PARAMETERS
from conftest import call_words, ONTOLOGIES, start_node, TEST_ONTOLOGIES

PATH_NOT_ALLOWED = 213


def _started(node, namespace):
    transport = ArmorTransport(namespace=namespace, service_wait_s=90.0)
    response = call_words(transport, '', 'GET ALL REFS')
    assert response.success, node.log()
    return transport


def _exit_of(node, timeout_s=60.0) -> int:
    try:
        return node.process.wait(timeout=timeout_s)
    finally:
        node.stop()


def _jvm_arguments(node) -> list:
    return pathlib.Path(f'/proc/{node.core_pid()}/cmdline').read_bytes().decode().split('\0')


def test_allowed_dirs_as_a_colon_list_and_jvm_options_as_one_string(tmp_path):
    node = start_node(tmp_path, '-p', f'allowed_dirs:={tmp_path}:{ONTOLOGIES}',
                      '-p', 'jvm_options:=-Xmx1g -XX:+ExitOnOutOfMemoryError',
                      namespace='/param_forms')
    try:
        transport = _started(node, '/param_forms')
        assert call_words(transport, 'robotics', 'SAVE', str(tmp_path / 'copy.owl')).success
        refused = call_words(transport, 'robotics', 'SAVE', str(TEST_ONTOLOGIES / 'copy.owl'))
        assert refused.exit_code == PATH_NOT_ALLOWED, refused.error_description
        arguments = _jvm_arguments(node)
        assert '-Xmx1g' in arguments and '-XX:+ExitOnOutOfMemoryError' in arguments
        assert '-Xmx4g' not in arguments
        transport.close()
    finally:
        node.stop()


def test_allowed_dirs_as_one_path(tmp_path):
    shutil.copy(ONTOLOGIES / 'robotics.owl', tmp_path / 'robotics.owl')
    node = start_node(tmp_path, '-p', f'allowed_dirs:={tmp_path}',
                      '-p', f'preload_file:={tmp_path / "robotics.owl"}', namespace='/param_one')
    try:
        transport = _started(node, '/param_one')
        assert call_words(transport, 'robotics', 'SAVE', str(tmp_path / 'copy.owl')).success
        outside = call_words(transport, 'other', 'LOAD FILE', str(ONTOLOGIES / 'robotics.owl'),
                             '', 'false', '', 'false')
        assert outside.exit_code == PATH_NOT_ALLOWED, outside.error_description
        transport.close()
    finally:
        node.stop()


def test_a_misspelt_parameter_stops_the_node_naming_the_right_one(tmp_path):
    node = start_node(tmp_path, '-p', 'lock_wait:=5000', namespace='/param_misspelt')
    assert _exit_of(node) != 0
    assert 'unknown parameter(s): lock_wait (did you mean lock_wait_ms?)' in node.log()


def test_a_value_of_the_wrong_type_stops_the_node_naming_the_parameter(tmp_path):
    node = start_node(tmp_path, '-p', 'allowed_dirs:=5', namespace='/param_mistyped')
    assert _exit_of(node) != 0
    assert 'parameter allowed_dirs must be a string array or one string' in node.log()
    node = start_node(tmp_path, '-p', 'lock_wait_ms:=soon', namespace='/param_mistyped')
    assert _exit_of(node) != 0
    assert 'parameter lock_wait_ms must be of type integer' in node.log()


def test_the_node_declares_exactly_the_cores_settings_and_its_own_parameters(armor_node, armor):
    from rcl_interfaces.srv import DescribeParameters, ListParameters
    import rclpy
    core = json.loads(subprocess.run(
        ['java', '-jar', _core_jar(), '--catalogue'], check=True, capture_output=True,
        text=True).stdout)
    expected = {s['key'] for s in core['settings']} | {p.name for p in NODE_PARAMETERS}
    node = rclpy.create_node('parameter_probe')
    try:
        names = _service(node, ListParameters, '/armor_service/list_parameters',
                          ListParameters.Request()).result.names
        assert set(names) - {'use_sim_time', 'start_type_description_service'} == expected
        described = _service(node, DescribeParameters, '/armor_service/describe_parameters',
                             DescribeParameters.Request(names=sorted(expected))).descriptors
        read_only = {d.name for d in described if d.read_only}
        changeable = {p.name for p in NODE_PARAMETERS if not p.read_only}
        assert {'request_timeout_s', 'subscription_idle_s', 'subscriptions_per_client',
                'sit_position_threshold', 'sit_axis_threshold'} <= changeable
        assert read_only == expected - changeable
    finally:
        node.destroy_node()


def _core_jar() -> str:
    import os
    return os.environ['ARMOR_CORE_JAR']


def _service(node, kind, name, request):
    import rclpy
    client = node.create_client(kind, name)
    assert client.wait_for_service(timeout_sec=30), name
    future = client.call_async(request)
    deadline = time.monotonic() + 30
    while not future.done() and time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.1)
    assert future.done(), name
    return future.result()
