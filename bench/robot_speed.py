# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Benchmark 6 (issue 15), reasoning at robot speed: what benchmark 3 does not cover.

    python bench/robot_speed.py [--smoke]

- The robot's cycle (bench/reasoning_cycle.py) at 100,000 individuals: load, first answer and
  cycle p50 of the modular reasoners, beside the whole-ontology Openllet the service used before.
- Readers that never wait: QUERY IND CLASS OccupiedRoom from a second client while the
  reference reasons for seconds (a schema change, which re-reasons every module), against the
  same query on the idle reference, and against a whole-ontology reference, where it waits.
- The core's peak memory at 10,000 individuals (the robot's mode) under several JVM option sets.
- The directions the issue names, in-process on the same cycle (ReasoningDirectionsBench):
  rebuilding, Openllet's incremental consistency, flushing HermiT and ELK, the modular reasoner;
  and Konclude realising the file from scratch.
"""

import json
import os
import pathlib
import shutil
import statistics
import subprocess
import threading
import time
from typing import Dict, List

from abox import RoboticsABox
from answers import short_names
from harness import BenchNode, CoreSnapshot, Deadline, script_scale_and_scratch
from reasoning_cycle import ROBOT_MODE, WHOLE_ONTOLOGY, _run_mode, summarise

MODULAR = ('PELLET', 'HERMIT')
WHOLE_LABEL, WHOLE_CLASS = next(iter(WHOLE_ONTOLOGY.items()))
JDK25 = pathlib.Path('/usr/lib/jvm/temurin-25-jdk-amd64/bin')
BASE_OPTIONS = ['-XX:+ExitOnOutOfMemoryError']
# label -> (java bin directory or None for the PATH's, options); the first is the node's default.
JVM_VARIANTS: Dict[str, tuple] = {
    '-Xmx4g (G1, the default before issue 15)': (None, ['-Xmx4g']),
    '-Xmx4g -XX:+UseSerialGC': (None, ['-Xmx4g', '-XX:+UseSerialGC']),
    '-Xmx4g -XX:+UseParallelGC': (None, ['-Xmx4g', '-XX:+UseParallelGC']),
    '-Xmx4g -XX:+UseStringDeduplication (G1)': (None, ['-Xmx4g', '-XX:+UseStringDeduplication']),
    '-Xmx512m (G1)': (None, ['-Xmx512m']),
    'JDK 25, -Xmx4g -XX:+UseSerialGC -XX:+UseCompactObjectHeaders':
        (JDK25, ['-Xmx4g', '-XX:+UseSerialGC', '-XX:+UseCompactObjectHeaders']),
}


def _jvm_parameter(options: List[str]) -> str:
    return json.dumps(options + BASE_OPTIONS)


def measure_large(scratch: pathlib.Path, snapshot: CoreSnapshot, individuals: int, cycles: int,
                  budget_s: float) -> Dict[str, dict]:
    """The cycle at a large ABox: each modular reasoner, then the whole-ontology reference."""
    abox_path = RoboticsABox(individuals).write(scratch / f'abox{individuals}.owl')
    results = {}
    for label, reasoner in [(r, r) for r in MODULAR] + [(WHOLE_LABEL, WHOLE_CLASS)]:
        node = BenchNode(scratch, snapshot)
        try:
            results[label] = _run_mode(node, abox_path, individuals, reasoner, ROBOT_MODE,
                                       cycles, budget_s)
        finally:
            node.stop()
    return results


def _busy_reads(node: BenchNode, abox_path: pathlib.Path, individuals: int, reasoner: str,
                idle_calls: int, writes: int, budget_s: float) -> dict:
    """Idle query latencies, then query latencies while schema changes keep the reference busy."""
    from armor_client import ArmorTransport
    reference = f'busy_{reasoner.rsplit(".", 1)[-1].lower()}'
    expected = RoboticsABox(individuals).occupied_rooms()
    deadline = Deadline(budget_s)
    loaded = node.call(reference, 'LOAD FILE', str(abox_path), '', 'false', reasoner, 'false',
                       timeout_s=budget_s)
    if not loaded.success:
        return {'note': f'LOAD failed: {loaded.error_description}'}
    reader = ArmorTransport(namespace=node.namespace, service_wait_s=120)
    samples: List[dict] = []
    writer_spans: List[tuple] = []
    writes_failed: List[str] = []

    def query():
        start = time.perf_counter()
        answer = reader.call(BenchNode.directive(reference, 'QUERY IND CLASS', 'OccupiedRoom'),
                             timeout_s=max(deadline.left(), 1.0))
        end = time.perf_counter()
        return {'start': start, 'end': end, 'ms': (end - start) * 1000,
                'right': answer.success and short_names(answer) == expected,
                'revision': 'revision' in answer.error_description}

    try:
        query()  # warm
        idle = [query() for _ in range(idle_calls)]
        stop = threading.Event()

        def write():
            # A schema change: every module is reasoned on again (the whole ontology, before).
            for i in range(writes):
                if deadline.expired():
                    break
                words = 'ADD CLASS CLASS' if i % 2 == 0 else 'REMOVE CLASS CLASS'
                start = time.perf_counter()
                answer = node.call(reference, words, 'Vehicle', 'Agent',
                                   timeout_s=max(deadline.left(), 1))
                writer_spans.append((start, time.perf_counter()))
                if not answer.success:
                    writes_failed.append(answer.error_description)
            stop.set()

        writer = threading.Thread(target=write, name='bench-writer')
        writer.start()
        while not stop.is_set() and not deadline.expired():
            samples.append(query())
        writer.join()
    finally:
        reader.close()
        node.call(reference, 'DROP', timeout_s=60)
    # A busy read started while a write was under way (after it had begun reasoning).
    busy = [s for s in samples if any(a + 0.05 < s['start'] < b for a, b in writer_spans)]
    return {
        'idle_p50_ms': statistics.median(s['ms'] for s in idle),
        'busy_p50_ms': statistics.median(s['ms'] for s in busy) if busy else None,
        'busy_max_ms': max((s['ms'] for s in busy), default=None),
        'busy_reads': len(busy),
        'marked': sum(s['revision'] for s in busy),
        'right': all(s['right'] for s in idle + busy) and not writes_failed,
        'write_p50_s': (statistics.median(b - a for a, b in writer_spans)
                        if writer_spans else None),
        'writes': len(writer_spans), 'note': ''}


def measure_busy_reads(scratch: pathlib.Path, snapshot: CoreSnapshot, individuals: int,
                       idle_calls: int, writes: int, budget_s: float) -> Dict[str, dict]:
    """Busy reads on the modular reasoner (Openllet) and on the whole-ontology reference."""
    abox_path = RoboticsABox(individuals).write(scratch / f'abox{individuals}.owl')
    results = {}
    for label, reasoner in (('PELLET', 'PELLET'), (WHOLE_LABEL, WHOLE_CLASS)):
        node = BenchNode(scratch, snapshot)
        try:
            results[label] = _busy_reads(node, abox_path, individuals, reasoner, idle_calls,
                                         writes, budget_s)
        finally:
            node.stop()
    return results


def measure_memory(scratch: pathlib.Path, snapshot: CoreSnapshot, individuals: int,
                   cycles: int, budget_s: float, variants: int) -> Dict[str, dict]:
    """Core peak memory and cycle of the robot's mode (modular Openllet) per JVM option set."""
    abox_path = RoboticsABox(individuals).write(scratch / f'abox{individuals}.owl')
    results = {}
    for label, (java_bin, options) in list(JVM_VARIANTS.items())[:variants]:
        if java_bin is not None and not (java_bin / 'java').exists():
            results[label] = {'note': f'{java_bin} not installed'}
            continue
        path = os.environ['PATH']
        if java_bin is not None:  # the node starts the core with the first java on PATH
            os.environ['PATH'] = f'{java_bin}:{path}'
        try:
            node = BenchNode(scratch, snapshot,
                             parameters={'jvm_options': _jvm_parameter(options)})
        finally:
            os.environ['PATH'] = path
        try:
            run = _run_mode(node, abox_path, individuals, 'PELLET', ROBOT_MODE, cycles, budget_s)
            results[label] = {'core_peak_mib': run['memory']['core']['peak_mib'],
                              'load_s': run['load_s'], **summarise(run), 'note': run['note']}
        finally:
            node.stop()
    return results


DIRECTIONS = ('rebuild:PELLET', 'rebuild:HERMIT', 'openllet-incremental', 'flush:HERMIT',
              'flush:ELK', 'modular:PELLET', 'modular:HERMIT')
DIRECTIONS_CLASS = 'io.github.armor.core.bench.ReasoningDirectionsBench'


def measure_directions(scratch: pathlib.Path, snapshot: CoreSnapshot, individuals: int,
                       cycles: int, budget_s: float) -> Dict[str, dict]:
    """The cycle kept up to date by each direction of issue 15, in-process, one JVM each."""
    workload = RoboticsABox(individuals)
    abox_path = workload.write(scratch / f'abox{individuals}.owl')
    moves = []
    for _ in range(min(cycles, workload.moves_left)):
        move = workload.next_move()
        moves.append([move.agent, move.new_room, move.old_room, workload.occupied_rooms()])
    moves_path = scratch / f'moves{individuals}.json'
    moves_path.write_text(json.dumps(moves))
    results = {}
    for direction in DIRECTIONS:
        try:
            done = subprocess.run(['java', '-Xmx4g', '-cp', snapshot.classpath, DIRECTIONS_CLASS,
                                   str(abox_path), str(moves_path), str(cycles), direction],
                                  capture_output=True, text=True, timeout=budget_s)
            lines = [line for line in done.stdout.splitlines() if line.startswith('{')]
            results[direction] = (json.loads(lines[-1]) if lines else
                                  {'note': f'failed: {done.stderr.strip()[-300:]}'})
        except subprocess.TimeoutExpired:
            results[direction] = {'note': f'did not finish within {budget_s:.0f} s'}
    results['Konclude'] = _konclude(abox_path, individuals, budget_s)
    return results


def _konclude(abox_path: pathlib.Path, individuals: int, budget_s: float) -> dict:
    """Konclude realising the same file from scratch, as an external backend would per change."""
    konclude = shutil.which('Konclude')
    if konclude is None:
        return {'note': 'Konclude not installed (Debian package konclude)'}
    output = abox_path.with_suffix('.konclude.xml')
    start = time.perf_counter()
    try:
        subprocess.run([konclude, 'realization', '-w', 'AUTO', '-i', str(abox_path), '-o',
                        str(output)], capture_output=True, timeout=budget_s, check=True)
    except (subprocess.TimeoutExpired, subprocess.CalledProcessError) as error:
        return {'note': f'Konclude failed: {error}'}
    seconds = time.perf_counter() - start
    occupied = output.read_text().count('OccupiedRoom"/>') - 1  # minus the declaration
    expected = len(RoboticsABox(individuals).occupied_rooms())
    return {'first_ms': seconds * 1000, 'cycle_p50_ms': seconds * 1000,
            'wrong': 0 if occupied == expected else 1, 'cycles': 1,
            'note': 'one realisation from the file; a change means another (no incremental ABox '
                    'updates from the command line)'}


def main():
    scale, scratch = script_scale_and_scratch(__doc__)
    snapshot = CoreSnapshot(scratch)
    for label, run in measure_large(scratch, snapshot, scale.large_abox, scale.cycles,
                                    scale.large_budget_s).items():
        print(scale.large_abox, label, 'load', run['load_s'], summarise(run), run['note'])
    print(measure_busy_reads(scratch, snapshot, scale.busy_abox, scale.busy_idle_calls,
                             scale.busy_writes, scale.busy_budget_s))
    print(measure_memory(scratch, snapshot, max(scale.abox_sizes), scale.cycles,
                         scale.cycle_budget_s[max(scale.abox_sizes)], scale.jvm_variants))
    print(measure_directions(scratch, snapshot, max(scale.abox_sizes), scale.cycles,
                             scale.cycle_budget_s[max(scale.abox_sizes)]))


if __name__ == '__main__':
    main()
