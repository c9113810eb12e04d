# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Where the wall time of one `armor call` goes, and what the call relay saves.

  python bench/call_latency.py [--calls 20]

Starts a node in a namespace of its own, then measures side by side, in one run:
  1. the direct path (`armor call --no-relay`: a process that starts ROS itself), whole;
  2. its phases, measured inside one such process: Python and imports, node creation,
     discovery of the service, proving its response path, the directive itself;
  3. the relayed path (`armor call`, relay already running), whole.
Prints medians and the ratio; the relay's target is under 0.5 s a call.
"""

import argparse
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parents[1]
NAMESPACE = f'/armor_call_bench_{os.getpid()}'
WORDS = ['robotics', 'QUERY', 'IND', 'CLASS', '--', 'Room']
# What every measured call must answer (robotics.owl's rooms), as IRIs.
ROOMS = ['<http://www.example.org/robotics#bedroom>', '<http://www.example.org/robotics#kitchen>']
PHASES = r'''
import time, sys
t0 = time.monotonic()
import rclpy
from armor_client.transport import ArmorTransport, directive
from armor_msgs.srv import ArmorDirective
t1 = time.monotonic()
transport = ArmorTransport(namespace=sys.argv[1], service_wait_s=60)
t2 = time.monotonic()
transport._directive.wait_for_service(timeout_sec=60)
t3 = time.monotonic()
transport.call(directive('', '', 'GET', 'ALL', 'REFS'), timeout_s=60)
t4 = time.monotonic()
answer = transport.call(directive('bench', 'robotics', 'QUERY', 'IND', 'CLASS', ['Room']),
                        timeout_s=60)
t5 = time.monotonic()
transport.close()
assert sorted(answer.queried_objects) == sorted(sys.argv[2:]), answer
print(t1 - t0, t2 - t1, t3 - t2, t4 - t3, t5 - t4)
'''


def wall(argv, env):
    """Seconds one `armor call` took; it must have printed the rooms."""
    started = time.monotonic()
    done = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=120)
    seconds = time.monotonic() - started
    assert done.returncode == 0, done.stderr
    assert sorted(line for line in done.stdout.splitlines() if line.startswith('<')) == ROOMS, \
        done.stdout
    return seconds


def main():
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument('--calls', type=int, default=20)
    calls = options.parse_args().calls
    sys.path.insert(0, str(REPO / 'tests' / 'integration'))
    from conftest import start_node  # reserves a DDS domain of its own
    from armor_client.cli import call_relay
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-call-bench-'))
    node = start_node(scratch, namespace=NAMESPACE)
    env = {**os.environ, 'ARMOR_CALL_RELAY_IDLE_S': '120'}
    cli = [sys.executable, '-m', 'armor_client.cli', 'call', '--namespace', NAMESPACE,
           '--wait', '120']
    try:
        wall([*cli, '--no-relay', *WORDS], env)  # the node is up and answering
        direct = [wall([*cli, '--no-relay', *WORDS], env) for _ in range(calls)]
        phases = []
        for _ in range(max(3, calls // 4)):
            done = subprocess.run([sys.executable, '-c', PHASES, NAMESPACE, *ROOMS], env=env,
                                  capture_output=True, text=True, timeout=120)
            assert done.returncode == 0, done.stderr
            phases.append([float(x) for x in done.stdout.split()])
        wall([*cli, *WORDS], env)  # starts the relay
        wall([*cli, *WORDS], env)  # the relay discovers the service
        relayed = [wall([*cli, *WORDS], env) for _ in range(calls)]
    finally:
        call_relay.stop()
        node.stop()
    median = statistics.median
    print(f'armor call, {calls} calls each, node answering (namespace {NAMESPACE})')
    print(f'| path | median | p90 |\n|---|---|---|')
    for name, samples in (('direct (--no-relay)', direct), ('relayed', relayed)):
        print(f'| {name} | {median(samples) * 1000:.0f} ms | '
              f'{sorted(samples)[int(0.9 * len(samples))] * 1000:.0f} ms |')
    print(f'\nrelayed / direct: {median(relayed) / median(direct):.2f}')
    names = ('imports (rclpy, messages, client)', 'node creation', 'service discovery',
             'proving the response path', 'the directive')
    print('\nphases of the direct path, inside the process (median):')
    for index, name in enumerate(names):
        print(f'  {name:36} {median(p[index] for p in phases) * 1000:7.1f} ms')
    print('  (the rest of the direct wall time: interpreter start, CLI, ROS shutdown and exit)')


if __name__ == '__main__':
    main()
