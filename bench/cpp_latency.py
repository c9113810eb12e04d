#!/usr/bin/env python3
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Round trips of the C++ client (armor_cpp) against the Python client's, on the same calls.

    python bench/cpp_latency.py [--calls 200] [--rounds 3]

Starts a node in a namespace of its own, loads robotics.owl twice (one copy per client),
then, in alternating rounds so that the machine's noise falls on both alike, times with each
client: a query (instances of Room), a manipulation (an individual added to a class) and an
atomic list of 10 such changes. Each client is a process of its own with the same arguments
and output: build/armor_cpp/armor_cpp_round_trips (tools/setup.sh test builds it) and
bench/round_trips.py.
The node runs with journal_fsync:=false, so that a change's time is the clients' and the
node's, not that of this machine's shared disk. Prints p50/p99 per call and client, and the
ratio of the p50s.
"""

import argparse
import os
import pathlib
import subprocess
import sys
import tempfile

REPO = pathlib.Path(__file__).resolve().parents[1]
ROUND_TRIPS = REPO / 'build' / 'armor_cpp' / 'armor_cpp_round_trips'
NAMESPACE = f'/armor_cpp_bench_{os.getpid()}'
KINDS = ('query', 'manipulation', 'list_of_10')


def round_trips(program: list, reference: str, calls: int) -> dict:
    """Run a round-trip program (C++ or Python, same arguments); kind -> seconds."""
    done = subprocess.run([*program, NAMESPACE, reference, str(calls)],
                          capture_output=True, text=True, timeout=1800)
    if done.returncode != 0:
        raise RuntimeError(f'{program[-1]} failed: {done.stderr}')
    samples = {}
    for line in done.stdout.splitlines():
        kind, *seconds = line.split()
        samples[kind] = [float(s) for s in seconds]
    return samples


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument('--calls', type=int, default=200)
    options.add_argument('--rounds', type=int, default=3)
    arguments = options.parse_args()
    if not ROUND_TRIPS.exists():
        sys.exit(f'{ROUND_TRIPS} is missing: run bash tools/setup.sh test')
    sys.path.insert(0, str(REPO / 'tests' / 'integration'))
    sys.path.insert(0, str(REPO / 'bench'))
    from conftest import ONTOLOGIES, start_node  # reserves a DDS domain of its own
    from harness import latency_summary
    from armor_client import Armor
    # Without journal_fsync: the clients are compared, not this machine's shared disk.
    node = start_node(pathlib.Path(tempfile.mkdtemp(prefix='armor-cpp-bench-')),
                      '-p', 'journal_fsync:=false', namespace=NAMESPACE)
    try:
        with Armor('bench_py', namespace=NAMESPACE, service_wait_s=120) as armor:
            armor.load_file('bench_py', str(ONTOLOGIES / 'robotics.owl'))
            armor.load_file('bench_cpp', str(ONTOLOGIES / 'robotics.owl'))
        python = [sys.executable, str(REPO / 'bench' / 'round_trips.py')]
        programs = {'C++': ([str(ROUND_TRIPS)], 'bench_cpp'), 'Python': (python, 'bench_py')}
        samples = {client: {k: [] for k in KINDS} for client in programs}
        for _ in range(arguments.rounds):
            for client, (program, reference) in programs.items():
                for kind, values in round_trips(program, reference, arguments.calls).items():
                    samples[client][kind] += values
    finally:
        node.stop()
    print(f'C++ client (armor_cpp over rcl) vs Python client (rclpy), same node (journal_fsync '
          f'off), same calls; '
          f'{arguments.rounds} alternating rounds of {arguments.calls} calls, load average '
          f'{os.getloadavg()[0]:.2f}')
    print('| call | C++ p50 ms | C++ p99 ms | Python p50 ms | Python p99 ms | '
          'Python p50 / C++ p50 |')
    print('|---|---|---|---|---|---|')
    for kind in KINDS:
        cpp = latency_summary(samples['C++'][kind])
        python = latency_summary(samples['Python'][kind])
        print(f'| {kind} | {cpp["p50_ms"]:.3f} | {cpp["p99_ms"]:.3f} | {python["p50_ms"]:.3f} | '
              f'{python["p99_ms"]:.3f} | {python["p50_ms"] / cpp["p50_ms"]:.2f}x |')


if __name__ == '__main__':
    main()
