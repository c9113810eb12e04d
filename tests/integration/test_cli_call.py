# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""armor call without a service says where it looked, and later calls go through the relay
(issue 11 item 8). Its speed is measured by bench/call_latency.py, not here."""

import os
import subprocess
import sys
import time

from armor_client.cli import call_relay


def armor_cli(*words, env=None):
    return subprocess.run([sys.executable, '-m', 'armor_client.cli', *words], capture_output=True,
                          text=True, timeout=120, env=env)


def test_no_service_says_what_it_waits_for_and_where_it_looked():
    started = time.monotonic()
    result = armor_cli('call', '--namespace', '/nobody_here', '--wait', '3', '-', 'GET', 'ALL',
                       'REFS')
    elapsed = time.monotonic() - started
    assert result.returncode == 3, result.stdout + result.stderr  # not 2: a usage error
    domain = os.environ['ROS_DOMAIN_ID']
    waiting, failure = result.stderr.strip().splitlines()[-2:]
    assert waiting.startswith('armor call: waiting for service /nobody_here/armor_interface_srv '
                              f'(ROS_DOMAIN_ID={domain}, namespace /nobody_here)'), result.stderr
    assert 'no ARMOR service /nobody_here/armor_interface_srv' in failure, result.stderr
    assert f'ROS_DOMAIN_ID={domain}' in failure and 'within 3 s' in failure, result.stderr
    assert elapsed < 30, elapsed


def test_later_calls_go_through_the_relay_with_the_same_answers(armor):
    words = ('call', 'robotics', 'QUERY', 'IND', 'CLASS', '--', 'Room')
    direct = armor_cli(*words[:1], '--no-relay', *words[1:])
    assert direct.returncode == 0, direct.stderr
    call_relay.stop()
    first = armor_cli(*words)
    deadline = time.monotonic() + 60
    while not os.path.exists(call_relay.socket_path()) and time.monotonic() < deadline:
        time.sleep(0.2)
    try:
        assert os.path.exists(call_relay.socket_path()), 'the first call started no relay'
        relayed = [armor_cli(*words) for _ in range(3)]
        failed = armor_cli('call', 'nowhere', 'QUERY', 'IND', 'CLASS', '--', 'Room')
    finally:
        assert call_relay.stop(), 'the relay was not running'
    assert first.stdout == direct.stdout
    for result in relayed:
        assert result.returncode == 0 and result.stdout == direct.stdout, result.stderr
    assert failed.returncode == 1 and 'error 206' in failed.stderr, failed.stderr
    assert not os.path.exists(call_relay.socket_path())


# An ARMOR service that proves its response path (GET ALL REFS) and then never answers.
SILENT_SERVICE = '''
import sys, threading
import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from armor_msgs.srv import ArmorDirective
rclpy.init()
node = rclpy.create_node('silent_armor', namespace=sys.argv[1])
def serve(request, response):
    if request.armor_request.command != 'GET':
        print('received', request.armor_request.command, flush=True)
        threading.Event().wait()
    response.armor_response.success = True
    return response
node.create_service(ArmorDirective, 'armor_interface_srv', serve,
                    callback_group=ReentrantCallbackGroup())
print('serving', flush=True)
executor = MultiThreadedExecutor(num_threads=4)
executor.add_node(node)
executor.spin()
'''


def test_call_ends_on_sigterm_while_it_waits_for_an_answer():
    """`timeout 300 armor call ... LOAD ...` must end at 300 s, as Ctrl-C ends it (issue 36)."""
    import signal
    namespace = f'/silent_armor_{os.getpid()}'
    service = subprocess.Popen([sys.executable, '-c', SILENT_SERVICE, namespace],
                               stdout=subprocess.PIPE, text=True)
    try:
        assert service.stdout.readline().strip() == 'serving'
        call = subprocess.Popen(
            [sys.executable, '-m', 'armor_client.cli', 'call', '--no-relay', '--namespace',
             namespace, '--wait', '60', 'kitchen', 'LOAD', 'FILE', '--', '/nowhere.owl'],
            stderr=subprocess.DEVNULL)
        try:
            assert service.stdout.readline().strip() == 'received LOAD'
            call.send_signal(signal.SIGTERM)
            returncode = call.wait(timeout=20)
        finally:
            if call.poll() is None:
                call.kill()
                call.wait()
        assert returncode == 128 + signal.SIGTERM, returncode
    finally:
        service.kill()
        service.wait()
