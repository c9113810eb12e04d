# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Benchmark 3 (and 4), reasoning under updates: the robot's cycle through the service, per
reasoner and mode, against owlready2 doing the same cycle; peak memory of the node.

    python bench/reasoning_cycle.py [--smoke]

The cycle: "agent X moved" (REPLACE OBJECTPROP IND isIn X new old), REASON, then the inferred
question QUERY IND CLASS OccupiedRoom, whose right answer bench/abox.py knows, so every cycle
is also checked: every other move empties a room, which must leave the answer. A wrong answer
of a complete reasoner fails the suite (bench/answers.py).
Modes of a reference (LOAD's buffered_reasoner argument):
- buffered: the reasoner sees changes only at REASON;
- non-buffered: it is brought up to date after every change; REASON then adds realisation;
- non-buffered, no REASON: the same without the REASON step, the query alone asks the reasoner.
Each (reasoner, ABox size) gets a node of its own, so the memory figures are that reasoner's;
each mode a wall-clock budget. A mode that runs out of time is reported as not finished, and
its node is replaced, since the core goes on reasoning for a request nobody waits for.
"""

import json
import os
import pathlib
import signal
import statistics
import subprocess
import sys
import threading
import time

from abox import RoboticsABox
from answers import short_names
from harness import REPO, BenchNode, CoreSnapshot, Deadline, script_scale_and_scratch

REASONERS = ('HERMIT', 'PELLET', 'JFACT', 'ELK')
OWLREADY_REASONERS = ('hermit', 'pellet')
# Non-buffered first: the core's peak memory after it is that of the robot's mode alone.
MODES = {  # name -> (buffered reasoner, REASON in the cycle)
    'non-buffered, no REASON': (False, False),
    'non-buffered': (False, True),
    'buffered': (True, True),
}
# How the service reasoned before issue 15, in the same run: a reasoner named by its factory
# class is used as it is, on the whole ontology (the modular reasoner takes the named ones).
WHOLE_ONTOLOGY = {'PELLET, whole ontology': 'openllet.owlapi.OpenlletReasonerFactory'}
ROBOT_MODE = 'non-buffered, no REASON'


class OutOfTime(Exception):
    """A stage did not finish within the budget."""


def _timed_call(node: BenchNode, deadline: Deadline, stage: str, reference: str, words: str,
                *args):
    from armor_client.errors import ArmorServiceCallError
    start = time.perf_counter()
    try:
        answer = node.call(reference, words, *args, timeout_s=max(deadline.left(), 0.5))
    except ArmorServiceCallError as error:  # no answer within the time left
        raise OutOfTime(f'{stage} did not finish within the {deadline.seconds:.0f} s budget') \
            from error
    if not answer.success:
        raise RuntimeError(f'{stage}: {words} failed: {answer.exit_code} '
                           f'{answer.error_description}')
    return time.perf_counter() - start, answer


def _run_mode(node: BenchNode, abox_path: pathlib.Path, individuals: int, reasoner: str,
              mode: str, cycles: int, budget_s: float) -> dict:
    buffered, with_reason = MODES[mode]
    workload = RoboticsABox(individuals)
    deadline = Deadline(budget_s)
    reference = f'abox_{reasoner.rsplit(".", 1)[-1].lower()}_{"buffered" if buffered else "live"}'
    result = {'load_s': None, 'first_s': None, 'cycles': [], 'finished': True, 'note': ''}
    try:
        result['load_s'], _ = _timed_call(node, deadline, 'LOAD', reference, 'LOAD FILE',
                                          str(abox_path), '', 'false', reasoner,
                                          str(buffered).lower())
        # The first answer realises the whole ABox: reported apart from the steady state.
        first = ('REASON',) if with_reason else ('QUERY IND CLASS', 'OccupiedRoom')
        result['first_s'], _ = _timed_call(node, deadline, f'first {first[0]}', reference, *first)
        for _ in range(min(cycles, workload.moves_left)):
            if deadline.expired():
                break
            move = workload.next_move()
            change, _ = _timed_call(node, deadline, 'a cycle', reference, 'REPLACE OBJECTPROP IND',
                                    'isIn', move.agent, move.new_room, move.old_room)
            reason = 0.0
            if with_reason:
                reason, _ = _timed_call(node, deadline, 'a cycle', reference, 'REASON')
            query, answer = _timed_call(node, deadline, 'a cycle', reference, 'QUERY IND CLASS',
                                        'OccupiedRoom')
            rooms, right = short_names(answer), workload.occupied_rooms()
            # Sound: no room the agents have left (an incomplete reasoner may miss some).
            result['cycles'].append({'change': change, 'reason': reason, 'query': query,
                                     'total': change + reason + query, 'correct': rooms == right,
                                     'sound': set(rooms) <= set(right)})
        result['memory'] = node.memory()
        _timed_call(node, Deadline(60), 'DROP', reference, 'DROP')
    except (OutOfTime, RuntimeError) as error:  # out of time, or a directive failed
        result['finished'] = False
        result['note'] = str(error)
        result['memory'] = node.memory()
    return result


def _run_reasoner(scratch: pathlib.Path, snapshot: CoreSnapshot, abox_path: pathlib.Path,
                  individuals: int, reasoner: str, cycles: int, budget_s: float) -> dict:
    results = {}
    node = BenchNode(scratch, snapshot)
    try:
        for mode in MODES:
            results[mode] = _run_mode(node, abox_path, individuals, reasoner, mode, cycles,
                                      budget_s)
            if not results[mode]['finished']:
                node.stop()
                node = BenchNode(scratch, snapshot)
    finally:
        node.stop()
    return results


def _run_owlready(abox_path: pathlib.Path, individuals: int, reasoner: str, cycles: int,
                  budget_s: float) -> dict:
    """owlready2's cycle in a child process (its JVMs included), stopped at the budget."""
    try:
        import owlready2  # noqa: F401 (only whether it is there)
    except ImportError:
        return {'finished': False, 'note': 'owlready2 not installed (make bench installs it)',
                'load_s': None, 'first_s': None, 'cycles': []}
    result = {'load_s': None, 'first_s': None, 'cycles': [], 'finished': True, 'note': ''}
    process = subprocess.Popen(
        [sys.executable, str(REPO / 'bench' / 'owlready_cycle.py'), str(abox_path),
         str(individuals), reasoner, str(cycles)],
        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, start_new_session=True)
    # The child prints after every stage; a stage longer than the budget is ended by the
    # killer, which closes the pipe and so ends the loop below.
    killer = _Killer(process, Deadline(budget_s))
    try:
        for line in process.stdout:
            fields = json.loads(line)
            stage = fields.pop('stage')
            if stage == 'cycle':
                result['cycles'].append(fields)
            else:
                result[f'{stage}_s'] = fields['seconds']
    finally:
        killed = killer.finish()
    if killed:
        result['finished'] = False
        stage = 'load' if result['load_s'] is None else (
            'first sync_reasoner' if result['first_s'] is None else 'a cycle')
        result['note'] = f'{stage} did not finish within the {budget_s:.0f} s budget'
    elif process.returncode != 0:
        result['finished'] = False
        result['note'] = f'owlready2 failed (exit code {process.returncode})'
    return result


class _Killer:
    """Ends a child's whole process group (owlready2's JVMs too) when the deadline passes."""

    def __init__(self, process: subprocess.Popen, deadline: Deadline):
        self._process = process
        self._killed = False
        self._timer = threading.Timer(deadline.left(), self._kill)
        self._timer.start()

    def _kill(self):
        if self._process.poll() is None:
            self._killed = True
            os.killpg(self._process.pid, signal.SIGKILL)

    def finish(self) -> bool:
        self._timer.cancel()
        self._process.wait()
        return self._killed


def summarise(result: dict) -> dict:
    """The figures of one run: cycle p50/max in ms, cycles done, all answers right."""
    totals = [c['total'] for c in result['cycles']]
    return {'cycles': len(totals),
            'cycle_p50_ms': statistics.median(totals) * 1000 if totals else None,
            'cycle_max_ms': max(totals) * 1000 if totals else None,
            'reason_p50_ms': (statistics.median(c['reason'] for c in result['cycles']) * 1000
                              if totals else None),
            'correct': all(c['correct'] for c in result['cycles']) if totals else None}


def measure(abox_sizes, cycles: int, budgets: dict, owlready_budgets: dict,
            scratch: pathlib.Path, snapshot: CoreSnapshot) -> dict:
    """results[N]['service'][reasoner][mode] and results[N]['owlready2'][reasoner]."""
    results = {}
    for individuals in abox_sizes:
        abox_path = RoboticsABox(individuals).write(scratch / f'abox{individuals}.owl')
        service = {reasoner: _run_reasoner(scratch, snapshot, abox_path, individuals, reasoner,
                                           cycles, budgets[individuals])
                   for reasoner in REASONERS}
        for label, factory_class in WHOLE_ONTOLOGY.items():
            node = BenchNode(scratch, snapshot)
            try:
                service[label] = {ROBOT_MODE: _run_mode(node, abox_path, individuals,
                                                        factory_class, ROBOT_MODE, cycles,
                                                        budgets[individuals])}
            finally:
                node.stop()
        owlready = {reasoner: _run_owlready(abox_path, individuals, reasoner, cycles,
                                            owlready_budgets[individuals])
                    for reasoner in OWLREADY_REASONERS}
        results[individuals] = {'service': service, 'owlready2': owlready}
    return results


def main():
    scale, scratch = script_scale_and_scratch(__doc__)
    results = measure(scale.abox_sizes, scale.cycles, scale.cycle_budget_s,
                      scale.owlready_budget_s, scratch, CoreSnapshot(scratch))
    for individuals, sides in results.items():
        for reasoner, modes in sides['service'].items():
            for mode, result in modes.items():
                print(individuals, reasoner, mode, summarise(result), result['note'])
        for reasoner, result in sides['owlready2'].items():
            print(individuals, 'owlready2', reasoner, summarise(result), result['note'])


if __name__ == '__main__':
    main()
