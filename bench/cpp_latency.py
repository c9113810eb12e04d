#!/usr/bin/env python3
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Round trips of the C++ client (armor_cpp) against the Python client's, on the same calls.

    python bench/cpp_latency.py [--calls 200] [--rounds 3]

Starts a node in a namespace of its own, loads robotics.owl twice (one copy per client),
then, in alternating rounds so that the machine's noise falls on both alike, times with each
client: a query (instances of Room), a manipulation (an individual added to a class) and an
atomic list of 10 such changes. The C++ side is build/armor_cpp/armor_cpp_round_trips (make
setup builds it), a process of its own as any C++ program; the Python side runs here.
Prints p50/p99 per call and client, and the ratio of the p50s.
"""

import argparse
import os
import pathlib
import subprocess
import sys
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parents[1]
ROUND_TRIPS = REPO / 'build' / 'armor_cpp' / 'armor_cpp_round_trips'
NAMESPACE = f'/armor_cpp_bench_{os.getpid()}'
KINDS = ('query', 'manipulation', 'list_of_10')


def python_round_trips(reference, calls: int, round_number: int) -> dict:
    """The same calls as armor_cpp_round_trips, from the Python client."""
    samples = {kind: [] for kind in KINDS}
    for _ in range(20):
        reference.instances('Room')
    for i in range(calls):
        started = time.perf_counter()
        reference.instances('Room')
        samples['query'].append(time.perf_counter() - started)
    for i in range(calls):
        started = time.perf_counter()
        reference.add_individual_to_class(f'py_box{round_number}_{i}', 'Box')
        samples['manipulation'].append(time.perf_counter() - started)
    for i in range(calls):
        started = time.perf_counter()
        with reference.batch() as batch:
            for j in range(10):
                batch.add_individual_to_class(f'py_item{round_number}_{i}_{j}', 'Box')
        samples['list_of_10'].append(time.perf_counter() - started)
    return samples


def cpp_round_trips(reference: str, calls: int) -> dict:
    done = subprocess.run([str(ROUND_TRIPS), NAMESPACE, reference, str(calls)],
                          capture_output=True, text=True, timeout=1800)
    if done.returncode != 0:
        raise RuntimeError(f'armor_cpp_round_trips failed: {done.stderr}')
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
        sys.exit(f'{ROUND_TRIPS} is missing: run make setup')
    sys.path.insert(0, str(REPO / 'tests' / 'integration'))
    sys.path.insert(0, str(REPO / 'bench'))
    from conftest import ONTOLOGIES, start_node  # reserves a DDS domain of its own
    from harness import latency_summary
    from armor_client import Armor
    node = start_node(pathlib.Path(tempfile.mkdtemp(prefix='armor-cpp-bench-')),
                      namespace=NAMESPACE)
    try:
        with Armor('bench_py', namespace=NAMESPACE, service_wait_s=120) as armor:
            python_ref = armor.load_file('bench_py', str(ONTOLOGIES / 'robotics.owl'))
            armor.load_file('bench_cpp', str(ONTOLOGIES / 'robotics.owl'))
            samples = {'C++': {k: [] for k in KINDS}, 'Python': {k: [] for k in KINDS}}
            for round_number in range(arguments.rounds):
                for kind, values in cpp_round_trips('bench_cpp', arguments.calls).items():
                    samples['C++'][kind] += values
                python = python_round_trips(python_ref, arguments.calls, round_number)
                for kind, values in python.items():
                    samples['Python'][kind] += values
    finally:
        node.stop()
    print(f'C++ client (armor_cpp over rcl) vs Python client (rclpy), same node, same calls; '
          f'{arguments.rounds} alternating rounds of {arguments.calls} calls, load average '
          f'{os.getloadavg()[0]:.2f}')
    print(f'| call | C++ p50 ms | C++ p99 ms | Python p50 ms | Python p99 ms | '
          f'Python p50 / C++ p50 |')
    print('|---|---|---|---|---|---|')
    for kind in KINDS:
        cpp = latency_summary(samples['C++'][kind])
        python = latency_summary(samples['Python'][kind])
        print(f'| {kind} | {cpp["p50_ms"]:.3f} | {cpp["p99_ms"]:.3f} | {python["p50_ms"]:.3f} | '
              f'{python["p99_ms"]:.3f} | {python["p50_ms"] / cpp["p50_ms"]:.2f}x |')


if __name__ == '__main__':
    main()
