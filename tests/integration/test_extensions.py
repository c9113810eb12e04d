# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Python extensions: packages whose entry points (group armor_service.extensions) the node
loads at start when its `extensions` parameter names them.

The repository's example (examples/plugins/hello_extension) is installed here with pip, as a
user installs it (into a directory of its own on the node's PYTHONPATH), and called over ROS 2
from this process: its service, and its directive topic, whose directives meet the core's
rules (a foreign mount answers 102) because they take armor_interface_srv's path. A test-only
package shows that an extension failing at start, or in a callback, does not stop the node.
"""

import os
import pathlib
import shutil
import subprocess
import sys
import time

from armor_client import ArmorTransport, directive
from armor_msgs.msg import ArmorDirectiveReq, ArmorDirectiveRes
from conftest import iris, REPO, start_node
import pytest
import rclpy
from std_srvs.srv import Trigger

BROKEN = '''
class FailsAtStart:
    def __init__(self, context):
        raise RuntimeError('cannot start')


def failing_service(context):
    def answer(request, response):
        raise ValueError('bug in a callback')
    context.create_service(__import__('std_srvs.srv').srv.Trigger, 'broken/service', answer)
    return None
'''


def install(site: pathlib.Path) -> None:
    """pip-install the example into `site`, and write a test-only extension package beside it."""
    # From a copy: building in place would leave build/ and egg-info in the repository.
    source = shutil.copytree(REPO / 'examples' / 'plugins' / 'hello_extension',
                             site.parent / 'hello_extension')
    subprocess.run([sys.executable, '-m', 'pip', 'install', '--quiet', '--no-deps',
                    '--no-build-isolation', '--target', str(site), str(source)],
                   check=True, timeout=300, capture_output=True)
    (site / 'broken_extension.py').write_text(BROKEN)
    info = site / 'broken_extension-0.1.dist-info'
    info.mkdir()
    (info / 'METADATA').write_text('Metadata-Version: 2.1\nName: broken-extension\nVersion: 0.1\n')
    (info / 'entry_points.txt').write_text(
        '[armor_service.extensions]\nfails_at_start = broken_extension:FailsAtStart\n'
        'failing_service = broken_extension:failing_service\n')


@pytest.fixture(scope='module')
def extended(tmp_path_factory):
    scratch = tmp_path_factory.mktemp('extended')
    site = scratch / 'site'
    install(site)
    saved = os.environ.get('PYTHONPATH', '')
    os.environ['PYTHONPATH'] = os.pathsep.join(filter(None, [str(site), saved]))
    try:
        node = start_node(scratch, '-p', 'extensions:=hello, fails_at_start, failing_service',
                          namespace='/extended')
    finally:
        os.environ['PYTHONPATH'] = saved
    transport = ArmorTransport(namespace='/extended', service_wait_s=90.0)
    assert transport.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=120).success, \
        node.log()
    probe = rclpy.create_node('extension_probe', namespace='/extended')
    yield node, transport, probe, site
    probe.destroy_node()
    transport.close()
    node.stop()


def call_service(node, kind, name, request):
    client = node.create_client(kind, name)
    assert client.wait_for_service(timeout_sec=60), name
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future, timeout_sec=60)
    node.destroy_client(client)
    return future.result()


def over_the_topic(probe, request: ArmorDirectiveReq) -> ArmorDirectiveRes:
    """Publish a directive on the extension's topic and wait for its answer."""
    answers = []
    subscription = probe.create_subscription(ArmorDirectiveRes, 'armor_hello/answers',
                                             answers.append, 10)
    publisher = probe.create_publisher(ArmorDirectiveReq, 'armor_hello/directives', 10)
    deadline = time.monotonic() + 60
    while publisher.get_subscription_count() == 0 or subscription.get_publisher_count() == 0:
        assert time.monotonic() < deadline, 'the extension topic was never matched'
        rclpy.spin_once(probe, timeout_sec=0.1)
    publisher.publish(request)
    while not answers:
        assert time.monotonic() < deadline, 'no answer on armor_hello/answers'
        rclpy.spin_once(probe, timeout_sec=0.1)
    probe.destroy_publisher(publisher)
    probe.destroy_subscription(subscription)
    return answers[0]


def test_the_example_extension_serves_its_own_service(extended):
    node, _, probe, _ = extended
    answer = call_service(probe, Trigger, 'armor_hello/references', Trigger.Request())
    assert answer.success and answer.message.split() == ['robotics'], node.log()
    assert 'extension hello started' in node.log()


def test_directives_over_the_extension_topic_meet_the_cores_rules(extended):
    _, armor, probe, _ = extended
    added = over_the_topic(probe, ArmorDirectiveReq(
        client_name='sensor', reference_name='robotics', command='ADD',
        primary_command_spec='IND', secondary_command_spec='CLASS', args=['robot8', 'Robot']))
    assert added.success, added.error_description
    robots = armor.call(directive('t', 'robotics', 'QUERY', 'IND', 'CLASS', ['Robot']),
                        timeout_s=120)
    assert robots.queried_objects == iris('robot1', 'robot8')
    assert armor.call(directive('holder', 'robotics', 'MOUNT'), timeout_s=120).success
    try:
        refused = over_the_topic(probe, ArmorDirectiveReq(
            client_name='sensor', reference_name='robotics', command='REMOVE',
            primary_command_spec='IND', secondary_command_spec='CLASS', args=['robot8', 'Robot']))
        assert refused.exit_code == 102, refused.error_description
    finally:
        assert armor.call(directive('holder', 'robotics', 'UNMOUNT'), timeout_s=120).success
    unknown = over_the_topic(probe, ArmorDirectiveReq(
        client_name='sensor', reference_name='nowhere', command='QUERY',
        primary_command_spec='IND', secondary_command_spec='CLASS', args=['Robot']))
    assert unknown.exit_code == 206, unknown.error_description


def test_an_extension_failing_at_start_or_in_a_callback_does_not_stop_the_node(extended):
    node, armor, probe, _ = extended
    assert 'extension fails_at_start failed to start and is left out' in node.log()
    assert 'RuntimeError: cannot start' in node.log()
    answer = call_service(probe, Trigger, 'broken/service', Trigger.Request())
    assert not answer.success and answer.message == ''
    assert 'ValueError: bug in a callback' in node.log()
    assert node.process.poll() is None
    assert armor.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=120).success


def test_an_extension_nobody_installed_stops_the_node_naming_the_installed(extended, tmp_path):
    site = extended[3]
    saved = os.environ.get('PYTHONPATH', '')
    os.environ['PYTHONPATH'] = os.pathsep.join(filter(None, [str(site), saved]))
    try:
        node = start_node(tmp_path, '-p', 'extensions:=[helo]', namespace='/extended_typo')
    finally:
        os.environ['PYTHONPATH'] = saved
    try:
        assert node.process.wait(timeout=120) != 0
    finally:
        node.stop()
    assert 'extension(s) not installed: helo; installed: failing_service, fails_at_start, hello' \
        in node.log()
