#!/usr/bin/env python3
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Round trips across hosts against the same host, and what discovery costs a new process.

    sudo python bench/fleet_latency.py [--calls 300]   (root: it makes network namespaces)

On the virtual hosts of tests/integration/hosts.py (network namespaces on one switch, veth
links), with the node on "server" and Fast DDS's UDP transport only (as test_fleet.py):
  1. round trips (query, change, atomic list of 10 changes; round_trips.py and its C++ twin
     armor_cpp_round_trips, which leave the ontology as they found it) from a client on the
     server's own host and from a client on "robot1", across the links, for both clients;
  2. the same-host figures with Fast DDS's default transports (shared memory) for reference,
     on a node of the ordinary host network;
  3. discovery: wall time of a new C++ process (query_rooms) until its first answer, by
     multicast (SIMPLE discovery) and through a Fast DDS discovery server with the switch's
     multicast blocked.
Prints p50/p99 per call and the ratio across-links / same-host.
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
sys.path.insert(0, str(REPO / 'tests' / 'integration'))
sys.path.insert(0, str(REPO / 'bench'))
from conftest import start_node  # noqa: E402  (reserves a DDS domain)
from harness import latency_summary  # noqa: E402
import hosts  # noqa: E402

KINDS = ('query', 'manipulation', 'list_of_10')
CPP = [str(REPO / 'build' / 'armor_cpp' / 'armor_cpp_round_trips')]
PYTHON = [sys.executable, str(REPO / 'bench' / 'round_trips.py')]
QUERY_ROOMS = str(REPO / 'build' / 'armor_cpp' / 'query_rooms')


def environment(**extra: str) -> dict:
    return {**os.environ, 'ROS_AUTOMATIC_DISCOVERY_RANGE': 'SUBNET',
            'FASTDDS_BUILTIN_TRANSPORTS': 'UDPv4', **extra}


def round_trips(prefix: list, program: list, calls: int, env: dict) -> dict:
    done = subprocess.run([*prefix, *program, '', 'robotics', str(calls)], env=env,
                          capture_output=True, text=True, timeout=1800)
    if done.returncode != 0:
        raise RuntimeError(f'{program[-1]} failed: {done.stderr}')
    return {line.split()[0]: [float(s) for s in line.split()[1:]]
            for line in done.stdout.splitlines()}


def first_answer_s(prefix: list, env: dict, runs: int) -> float:
    """Median wall time of a new C++ process until it has printed its answer."""
    walls = []
    for _ in range(runs):
        started = time.perf_counter()
        subprocess.run([*prefix, QUERY_ROOMS], env=env, check=True, capture_output=True,
                       timeout=120)
        walls.append(time.perf_counter() - started)
    return statistics.median(walls)


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument('--calls', type=int, default=300)
    options.add_argument('--starts', type=int, default=5)
    arguments = options.parse_args()
    why_not = hosts.unavailable()
    if why_not:
        sys.exit(f'fleet_latency: {why_not}')
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-fleet-bench-'))
    for run in ('local', 'fleet', 'server'):
        (scratch / run).mkdir()
    rows = {}
    discovery = {}
    # 2. Same host, default transports (shared memory): the ordinary host network.
    node = start_node(scratch / 'local')
    try:
        for client, program in (('C++', CPP), ('Python', PYTHON)):
            local = {**os.environ, 'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST'}
            rows[('same host, shared memory', client)] = round_trips([], program,
                                                                     arguments.calls, local)
    finally:
        node.stop()
    # 1 and 3 (multicast): the node on "server".
    virtual = hosts.VirtualHosts(['server', 'robot1'])
    try:
        node = start_node(scratch / 'fleet', command_prefix=virtual.command('server'),
                          env=environment())
        try:
            for placement, host in (('same host, UDP', 'server'), ('across veth, UDP', 'robot1')):
                for client, program in (('C++', CPP), ('Python', PYTHON)):
                    rows[(placement, client)] = round_trips(
                        virtual.command(host), program, arguments.calls, environment())
            discovery['multicast (SIMPLE)'] = first_answer_s(
                virtual.command('robot1'), environment(), arguments.starts)
        finally:
            node.stop()
    finally:
        virtual.remove()
    # 3 (discovery server): multicast blocked at the switch.
    virtual = hosts.VirtualHosts(['server', 'robot1'])
    try:
        virtual.block_multicast()
        with_server = environment(ROS_DISCOVERY_SERVER=f'{virtual.address["server"]}:11811')
        server = subprocess.Popen(virtual.command(
            'server', 'fast-discovery-server', '42', '-l', virtual.address['server'], '-p',
            '11811'), stdout=subprocess.DEVNULL, env=with_server)
        node = start_node(scratch / 'server', command_prefix=virtual.command('server'),
                          env=with_server)
        try:
            discovery['discovery server, multicast blocked'] = first_answer_s(
                virtual.command('robot1'), with_server, arguments.starts)
            rows[('across veth, discovery server', 'C++')] = round_trips(
                virtual.command('robot1'), CPP, arguments.calls, with_server)
        finally:
            node.stop()
            server.terminate()
            server.wait(timeout=20)
    finally:
        virtual.remove()
    print(f'Round trips, {arguments.calls} calls each, node on its own host (robotics.owl, '
          f'HermiT); load average {os.getloadavg()[0]:.2f}')
    print('| placement | client | call | p50 ms | p99 ms |')
    print('|---|---|---|---|---|')
    for (placement, client), samples in rows.items():
        for kind in KINDS:
            figures = latency_summary(samples[kind])
            print(f'| {placement} | {client} | {kind} | {figures["p50_ms"]:.3f} | '
                  f'{figures["p99_ms"]:.3f} |')
    print('\nAcross the veth links against the same host over UDP (p50 ratio):')
    for client in ('C++', 'Python'):
        for kind in KINDS:
            across = latency_summary(rows[('across veth, UDP', client)][kind])['p50_ms']
            same = latency_summary(rows[('same host, UDP', client)][kind])['p50_ms']
            print(f'  {client} {kind}: {across:.3f} / {same:.3f} ms = {across / same:.2f}x')
    print(f'\nFirst answer of a new C++ process (median of {arguments.starts}):')
    for how, seconds in discovery.items():
        print(f'  {how}: {seconds:.2f} s')


if __name__ == '__main__':
    main()
