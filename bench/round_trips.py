#!/usr/bin/env python3
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Round trips of the Python client: the twin of armor_cpp_round_trips, same calls, same output.

    python bench/round_trips.py NAMESPACE REFERENCE CALLS

Against the node in NAMESPACE with REFERENCE loaded from robotics.owl: after a warm-up,
CALLS round trips of each kind (a query, a manipulation, an atomic list of 10 changes);
prints one line per kind, ``kind s1 s2 ...`` in seconds. Used by cpp_latency.py and
fleet_latency.py, which start one process per client so both are measured alike.
"""

import os
import sys
import time

from armor_client import Armor


def timed(calls, call):
    seconds = []
    for i in range(calls):
        started = time.perf_counter()
        call(i)
        seconds.append(time.perf_counter() - started)
    return seconds


def add_ten(reference, i):
    with reference.batch() as batch:
        for j in range(10):
            batch.add_individual_to_class(f'py_item{os.getpid()}_{i}_{j}', 'Box')


def main():
    namespace, name, calls = sys.argv[1], sys.argv[2], int(sys.argv[3])
    with Armor('bench_py', namespace=namespace, service_wait_s=120) as armor:
        reference = armor.reference(name)
        for _ in range(20):
            reference.instances('Room')
        kinds = {
            'query': lambda i: reference.instances('Room'),
            'manipulation': lambda i: reference.add_individual_to_class(
                f'py_box{os.getpid()}_{i}', 'Box'),
            'list_of_10': lambda i: add_ten(reference, i),
        }
        for kind, call in kinds.items():
            print(kind, *timed(calls, call), flush=True)


if __name__ == '__main__':
    main()
