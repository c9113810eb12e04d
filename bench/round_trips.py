#!/usr/bin/env python3
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Round trips of the Python client: the twin of armor_cpp_round_trips, same calls, same output.

    python bench/round_trips.py NAMESPACE REFERENCE CALLS

Against the node in NAMESPACE with REFERENCE loaded from robotics.owl: after a warm-up,
CALLS round trips of each kind (a query; a change; an atomic list of 10 changes, the changes
moving robot1 back and forth so that every call finds the same ontology); prints one line per
kind, ``kind s1 s2 ...`` in seconds, and leaves the ontology as it found it. Every answer is
checked (the rooms; where robot1 is after the changes): a wrong one stops it. Used by
cpp_latency.py and fleet_latency.py, which start one process per client so both are measured
alike.
"""

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


ROOMS = ('kitchen', 'bedroom')


def expect(answer, right, what):
    """Stops the run when an answer is not the one its figure assumes."""
    if answer != right:
        raise SystemExit(f'round_trips: wrong answer to {what}: {answer}, not {right}')


def move(target, i):
    """robot1 from one room to the other: calls i and i + 1 undo each other."""
    target.replace_object_value('isIn', 'robot1', ROOMS[(i + 1) % 2], ROOMS[i % 2])


def move_ten_times(reference, i):
    with reference.batch() as batch:
        for j in range(10):
            move(batch, j)


def main():
    namespace, name, calls = sys.argv[1], sys.argv[2], int(sys.argv[3])
    with Armor('bench_py', namespace=namespace, service_wait_s=120) as armor:
        reference = armor.reference(name)
        for _ in range(20):
            reference.instances('Room')
        kinds = {
            'query': lambda i: expect(reference.instances('Room'), ['bedroom', 'kitchen'],
                                      'a query'),
            'manipulation': lambda i: move(reference, i),
            'list_of_10': lambda i: move_ten_times(reference, i),
        }
        for kind, call in kinds.items():
            print(kind, *timed(calls, call), flush=True)
            if kind == 'manipulation':
                expect(reference.object_values('isIn', 'robot1'), [ROOMS[calls % 2]],
                       'where robot1 went')
                if calls % 2:
                    move(reference, 1)  # back to the kitchen before the lists start from there
        expect(reference.object_values('isIn', 'robot1'), ['kitchen'],
               'where the lists left robot1')


if __name__ == '__main__':
    main()
