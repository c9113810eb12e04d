# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Benchmark 2, batch throughput: directive lists through the service against in-process limits.

    python bench/batch_throughput.py [--smoke]

The same lists (pairs of "ADD IND CLASS agentL_I Robot" and "ADD OBJECTPROP IND isIn agentL_I
room") go through armor_interface_serialized_srv and, in a separate JVM, through
ArmorCore.executeList and through the bare OWL API (InProcessBatchBench.java). Each
configuration starts from robotics.owl freshly loaded, runs the same warm-up lists, then
measures lists until its count or its time budget (measured lists only) runs out. Configurations:
- buffered reasoner: what manipulation itself costs (the reasoner sees changes at REASON);
- non-buffered reasoner (the LOAD default): HermiT is brought up to date after every change.
Every list must succeed, and after a configuration's lists (untimed) its reference must hold
exactly the agents they added, each a RobotInRoom (an inference from both kinds of directive);
InProcessBatchBench checks its two paths the same way.
"""

import json
import pathlib
import statistics
import subprocess
import time

from answers import checked, WrongAnswer
from harness import (REPO, BenchNode, CoreSnapshot, Deadline, HARNESS_CLASS,
                     script_scale_and_scratch)

ROBOTICS = REPO / 'ontologies' / 'robotics.owl'
ROOMS = ('kitchen', 'bedroom')


def configurations(lists_by_size: dict) -> list:
    """(label, list size, measured lists, buffered reasoner) of every measured configuration."""
    result = [(f'{size} directives, buffered reasoner', size, lists, True)
              for size, lists in lists_by_size.items()]
    # Synchronising the reasoner after every change makes long lists take minutes: 100 only.
    smallest = min(lists_by_size)
    result.append((f'{smallest} directives, non-buffered reasoner (LOAD default)', smallest,
                   lists_by_size[smallest], False))
    return result


def robots_in_rooms(lists: int, size: int) -> list:
    """The RobotInRoom members after `lists` lists of `size` (InProcessBatchBench counts them)."""
    return ['robot1', *(f'agent{n}_{i}' for n in range(lists) for i in range(size // 2))]


def directive_list(reference: str, list_number: int, size: int) -> list:
    """The same list InProcessBatchBench.directives() builds."""
    directives = []
    for i in range(size):
        agent = f'agent{list_number}_{i // 2}'
        directives.append(
            BenchNode.directive(reference, 'ADD IND CLASS', agent, 'Robot') if i % 2 == 0 else
            BenchNode.directive(reference, 'ADD OBJECTPROP IND', 'isIn', agent,
                                ROOMS[(i // 2) % 2]))
    return directives


def _service(node: BenchNode, reference: str, size: int, lists: int, buffered: bool,
             budget_s: float, warmup_lists: int) -> dict:
    checked(node.call(reference, 'LOAD FILE', str(ROBOTICS), '', 'false', 'HERMIT',
                      str(buffered).lower(), timeout_s=120), 'LOAD')
    seconds = []
    deadline = Deadline(budget_s)
    list_number = 0
    while not seconds or (len(seconds) < lists and not deadline.expired()):
        directives = directive_list(reference, list_number, size)
        start = time.perf_counter()
        answer = node.transport.call_list(directives, timeout_s=max(budget_s, 60) * 4)
        elapsed = time.perf_counter() - start
        if not answer.success:
            failed = [r for r in answer.armor_responses if r.exit_code not in (0, 212)]
            raise WrongAnswer(f'list {list_number} failed: {failed[:1]}')
        if list_number >= warmup_lists:
            seconds.append(elapsed)
        else:
            deadline = Deadline(budget_s)  # the budget counts measured lists only
        list_number += 1
    checked(node.call(reference, 'REASON', timeout_s=600), 'REASON')
    checked(node.call(reference, 'QUERY IND CLASS', 'RobotInRoom', timeout_s=600),
            f'{reference}: robots in rooms after {list_number} lists',
            robots_in_rooms(list_number, size))
    node.call(reference, 'DROP', timeout_s=120)
    return {'path': 'service', 'list_size': size, 'lists': len(seconds),
            'directives': size * len(seconds), 'seconds': sum(seconds),
            'per_s': size * len(seconds) / sum(seconds),
            'list_ms_p50': statistics.median(seconds) * 1000}


def _in_process(snapshot: CoreSnapshot, size: int, lists: int, buffered: bool,
                budget_s: float, warmup_lists: int) -> list:
    completed = subprocess.run(
        ['java', '-Xmx4g', '-cp', snapshot.classpath, HARNESS_CLASS, str(ROBOTICS), str(size),
         str(lists), str(warmup_lists), 'HERMIT', str(buffered).lower(), str(budget_s)],
        capture_output=True, text=True, timeout=budget_s * 8 + 120)
    if completed.returncode != 0:
        raise RuntimeError(f'InProcessBatchBench failed: {completed.stderr[-2000:]}')
    return [json.loads(line) for line in completed.stdout.splitlines() if line.startswith('{')]


def measure(lists_by_size: dict, budget_s: float, scratch: pathlib.Path,
            snapshot: CoreSnapshot, warmup_lists: int) -> list:
    """One row per configuration: the service, ArmorCore in-process and the bare OWL API."""
    node = BenchNode(scratch, snapshot)
    rows = []
    try:
        for number, (label, size, lists, buffered) in enumerate(configurations(lists_by_size)):
            service = _service(node, f'batch{number}', size, lists, buffered, budget_s,
                               warmup_lists)
            limits = {r['path']: r for r in _in_process(snapshot, size, lists, buffered, budget_s,
                                                        warmup_lists)}
            rows.append({'configuration': label, 'service': service, **limits})
    finally:
        node.stop()
    return rows


def main():
    scale, scratch = script_scale_and_scratch(__doc__)
    print(json.dumps(measure(scale.batch_lists, scale.batch_budget_s, scratch,
                             CoreSnapshot(scratch), scale.warmup_lists), indent=2))


if __name__ == '__main__':
    main()
