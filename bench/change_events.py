# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Change events and subscriptions (issue 12): latency, completeness, cost, leaks.

    python bench/change_events.py [--smoke] [--json FILE]

Four measurements, each against a node of its own, through the client library over ROS 2:

1. Notification latency: from the core's acknowledgement of a change (the stamp of its
   ArmorChange) to this process receiving (a) the ArmorChange on armor_changes and (b) the
   ArmorAnswer of a subscription whose inferred answer the change moved, p50/p99, on ABoxes of
   1,000 and 10,000 individuals (bench/abox.py). ELK, subscribed to the defined class
   RobotInRoom (Robot and isIn some Room), each change removing one robot's isIn; at 1,000 also
   HermiT, subscribed to OccupiedRoom (needs isIn's inverse), each change moving a person in or
   out of an empty room. HermiT at 10,000 is not measured: one realisation takes minutes.
2. Completeness: 10,000 acknowledged changes (from 4 client threads; every tenth an atomic
   list of two, every 25th a list that fails and makes no revision) watched on armor_changes:
   revisions lost and duplicated (both must be 0), and whether a subscription's answer built
   from its messages ends equal to the query's answer.
3. Cost on the directive path: round trips of a change (HermiT, 1,000 individuals, a person
   moved in and out of a room, so every change moves the subscribed answers) with 20
   subscriptions open against none, in alternating blocks so both see the same machine noise;
   sequential back to back, and paced at one change a second. Twenty typical subscriptions
   (instances of classes, values and types of individuals); then the same with two of them
   replaced by a SPARQL SELECT and a DL query, whose every evaluation costs seconds at this
   size (SPARQL materialises every inference) and holds the reference meanwhile.
4. Leaks: resident memory of the node and of the core before and after 1,000 and 10,000
   subscribe/unsubscribe cycles, and the answer topics left on the node (must be 0).
"""

import argparse
import json
import pathlib
import queue
import re
import subprocess
import sys
import tempfile
import threading
import time
from typing import Any, Dict, List

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

from abox import RoboticsABox  # noqa: E402
from harness import BenchNode, CoreSnapshot, latency_summary  # noqa: E402

FULL = {'sizes': [1000, 10000], 'samples': 300, 'hermit_samples': 100, 'changes': 10000,
        'round_trips': {'back_to_back': 200, 'paced': 60, 'heavy': 30}, 'pace_s': 1.0,
        'cycles': [1000, 10000]}
SMOKE = {'sizes': [50], 'samples': 10, 'hermit_samples': 5, 'changes': 200,
         'round_trips': {'back_to_back': 10, 'paced': 5, 'heavy': 5}, 'pace_s': 0.2,
         'cycles': [20, 50]}


def _session(node: BenchNode):
    from armor_client import Armor
    return Armor('bench_events', transport=node.transport, timeout_s=600)


def _load(node: BenchNode, name: str, path: pathlib.Path, reasoner: str,
          buffered_reasoner: bool = False) -> None:
    loaded = node.call(name, 'LOAD FILE', str(path), '', 'false', reasoner,
                       str(buffered_reasoner).lower(), timeout_s=1800)
    if not loaded.success:
        raise RuntimeError(f'LOAD {path.name}: {loaded.exit_code} {loaded.error_description}')


class _Received:
    """Messages handed over by callbacks, each with the wall time it arrived."""

    def __init__(self):
        self._queue: 'queue.Queue[Any]' = queue.Queue()

    def put(self, item: Any) -> None:
        self._queue.put((time.time_ns(), item))

    def until(self, accept, timeout_s: float = 120.0):
        """The arrival time and the first item accept() takes; earlier ones are dropped."""
        deadline = time.monotonic() + timeout_s
        while True:
            arrived, item = self._queue.get(timeout=max(0.0, deadline - time.monotonic()))
            if accept(item):
                return arrived, item


def _join_change_topic(session, changes: _Received, reference: str, change) -> None:
    """Change until the watch has received one: it has joined armor_changes."""
    deadline = time.monotonic() + 60
    while True:
        change()
        try:
            changes.until(lambda c: c.reference == reference, timeout_s=1.0)
            return
        except queue.Empty:
            if time.monotonic() > deadline:
                raise RuntimeError('armor_changes never reached the watch')


def notification_latency(scratch: pathlib.Path, snapshot: CoreSnapshot, size: int,
                         reasoner: str, samples: int) -> Dict[str, Any]:
    """Figures of measurement 1 for one ABox size and reasoner."""
    abox = RoboticsABox(size)
    path = abox.write(scratch / f'abox{size}.owl')
    node = BenchNode(scratch, snapshot)
    try:
        session = _session(node)
        started = time.monotonic()
        _load(node, 'abox', path, reasoner)
        load_s = time.monotonic() - started
        reference = session.reference('abox')
        changes, answers = _Received(), _Received()
        if reasoner == 'ELK':
            robots = [a for a in abox.agents if a.startswith('bot')]
            query = 'QUERY IND CLASS RobotInRoom'

            def change(i):
                robot = robots[i]
                reference.remove_object_value('isIn', robot, abox.location[robot])
        else:
            person = next(a for a in abox.agents if a.startswith('person'))
            home, empty = abox.location[person], abox.next_move().new_room
            query = 'QUERY IND CLASS OccupiedRoom'

            def change(i):
                new, old = (empty, home) if i % 2 == 0 else (home, empty)
                reference.replace_object_value('isIn', person, new, old)
        counter = iter(range(len(abox.agents)))
        with session.changes(changes.put, 'abox'):
            _join_change_topic(session, changes, 'abox', lambda: change(next(counter)))
            with reference.subscribe(query, answers.put):
                _, initial = answers.until(lambda a: a.initial)
                change_ms, answer_ms = [], []
                for k in range(1, samples + 1):
                    change(next(counter))
                    revision = initial.revision + k
                    arrived, message = changes.until(lambda c, r=revision: c.revision == r)
                    change_ms.append((arrived - message.stamp_ns) / 1e9)
                    answered, answer = answers.until(lambda a, r=revision: a.revision >= r)
                    if answer.revision != revision or not (answer.added or answer.removed):
                        raise RuntimeError(f'revision {revision} moved no answer: {answer}')
                    answer_ms.append((answered - message.stamp_ns) / 1e9)
        return {'individuals': size, 'reasoner': reasoner, 'query': query,
                'load_s': round(load_s, 1), 'change_topic': latency_summary(change_ms),
                'inferred_answer': latency_summary(answer_ms)}
    finally:
        node.stop()


def completeness(scratch: pathlib.Path, snapshot: CoreSnapshot, changes_wanted: int,
                 threads: int = 4) -> Dict[str, Any]:
    """Figures of measurement 2."""
    from armor_client import directive
    node = BenchNode(scratch, snapshot)
    try:
        session = _session(node)
        # A buffered reasoner keeps the directives cheap; events do not depend on reasoning.
        _load(node, 'burst', REPO_ROBOTICS, 'HERMIT', buffered_reasoner=True)
        reference = session.reference('burst')
        received: List[Any] = []
        lock = threading.Lock()

        def record(change):
            with lock:
                received.append(change)
        answers: List[Any] = []
        counts = {'acknowledged': 0, 'failed_lists': 0}
        errors: List[BaseException] = []
        with session.changes(record, 'burst'):
            deadline = time.monotonic() + 60
            probe = 0
            while not received:  # the watch joins armor_changes in a moment
                reference.add_individual(f'probe{probe}')
                probe += 1
                time.sleep(0.2)
                if time.monotonic() > deadline:
                    raise RuntimeError('armor_changes never reached the watch')
            time.sleep(1.0)
            with lock:
                first_counted = received[-1].revision
            with reference.subscribe('QUERY IND CLASS Robot', answers.append) as robots:
                def write(worker: int):
                    try:
                        for i in range(worker, changes_wanted, threads):
                            if i % 25 == 5:
                                failed = node.transport.call_list([
                                    directive('bench', 'burst', 'ADD', 'IND', 'CLASS',
                                              [f'never{i}', 'Robot']),
                                    directive('bench', 'burst', 'ADD', 'IND', 'CLASS',
                                              [f'wrong-arity{i}'])], timeout_s=600)
                                assert not failed.success
                                with lock:
                                    counts['failed_lists'] += 1
                            if i % 10 == 0:
                                with reference.batch() as batch:
                                    batch.add_individual_to_class(f'pair{i}a', 'Robot')
                                    batch.add_individual_to_class(f'pair{i}b', 'Robot')
                            else:
                                reference.add_individual_to_class(f'robot{i}', 'Robot')
                            with lock:
                                counts['acknowledged'] += 1
                    except BaseException as error:  # reported after the join
                        errors.append(error)
                started = time.monotonic()
                workers = [threading.Thread(target=write, args=(w,)) for w in range(threads)]
                for worker in workers:
                    worker.start()
                for worker in workers:
                    worker.join()
                elapsed = time.monotonic() - started
                if errors:
                    raise errors[0]
                reference.reason()  # a buffered reasoner answers the subscription after REASON
                last = first_counted + counts['acknowledged'] + 1
                deadline = time.monotonic() + 120
                while time.monotonic() < deadline:
                    with lock:
                        if received[-1].revision >= last:
                            break
                    time.sleep(0.1)
                time.sleep(1.0)  # anything wrongly published arrives meanwhile
                expected_answer = sorted(reference.instances('Robot'))
                deadline = time.monotonic() + 120
                while robots.answer != expected_answer and time.monotonic() < deadline:
                    time.sleep(0.1)
                answer_agrees = robots.answer == expected_answer
        with lock:
            revisions = [c.revision for c in received if c.revision > first_counted]
            reported_missed = sum(len(c.missed) for c in received)
        wanted = set(range(first_counted + 1, last + 1))
        return {'acknowledged_changes': len(wanted), 'failed_lists': counts['failed_lists'],
                'received': len(revisions), 'lost': len(wanted - set(revisions)),
                'duplicated': len(revisions) - len(set(revisions)),
                'unexpected': len(set(revisions) - wanted),
                'missed_reported_by_client': reported_missed,
                'changes_per_s': round(counts['acknowledged'] / elapsed, 1),
                'subscription_messages': len(answers),
                'subscription_answer_agrees': answer_agrees,
                'subscription_answer_size': len(expected_answer)}
    finally:
        node.stop()


def directive_cost(scratch: pathlib.Path, snapshot: CoreSnapshot, size: int,
                   round_trips: Dict[str, int], pace_s: float) -> Dict[str, Any]:
    """Figures of measurement 3."""
    abox = RoboticsABox(size)
    path = abox.write(scratch / f'cost{size}.owl')
    node = BenchNode(scratch, snapshot)
    try:
        session = _session(node)
        _load(node, 'cost', path, 'HERMIT')
        reference = session.reference('cost')
        person = next(a for a in abox.agents if a.startswith('person'))
        home, empty = abox.location[person], abox.next_move().new_room
        moves = iter(range(10 ** 9))

        def move() -> float:
            i = next(moves)
            new, old = (empty, home) if i % 2 == 0 else (home, empty)
            started = time.perf_counter()
            reference.replace_object_value('isIn', person, new, old)
            return time.perf_counter() - started

        for _ in range(5):
            move()
        typical, heavy = _typical_queries(abox), _heavy_queries(abox)
        figures: Dict[str, Any] = {'individuals': size, 'reasoner': 'HERMIT',
                                   'subscriptions': len(typical), 'pace_s': pace_s}
        for label, queries, pause, count in (
                ('back_to_back', typical, 0.0, round_trips['back_to_back']),
                ('paced', typical, pace_s, round_trips['paced']),
                ('heavy_back_to_back', heavy, 0.0, round_trips['heavy'])):
            samples: Dict[str, List[float]] = {'none': [], 'open': []}
            block = max(5, count // 5)
            while len(samples['open']) < count:
                for state in ('none', 'open'):
                    opened = ([reference.subscribe(q, lambda change: None) for q in queries]
                              if state == 'open' else [])
                    time.sleep(max(pause, 0.5))
                    for _ in range(block):
                        samples[state].append(move())
                        time.sleep(pause)
                    for subscription in opened:
                        subscription.close()
                    # A query waits for an evaluation still running: the next block starts clean.
                    reference.instances('Room')
            none, opened_ = latency_summary(samples['none']), latency_summary(samples['open'])
            figures[label] = {'none': none, 'open': opened_,
                              'p50_ratio': round(opened_['p50_ms'] / none['p50_ms'], 3),
                              'p99_ratio': round(opened_['p99_ms'] / none['p99_ms'], 3),
                              'mean_ratio': round(opened_['mean_ms'] / none['mean_ms'], 3)}
        return figures
    finally:
        node.stop()


def _typical_queries(abox: RoboticsABox) -> List[str]:
    """Twenty standing queries a robot might hold: members of classes, values, types."""
    agents = abox.agents
    return [
        'QUERY IND CLASS OccupiedRoom', 'QUERY IND CLASS RobotInRoom', 'QUERY IND CLASS Room',
        'QUERY IND CLASS Robot', 'QUERY IND CLASS Person', 'QUERY IND CLASS Agent',
        'QUERY IND CLASS Location', 'QUERY IND CLASS Corridor',
        *[f'QUERY OBJECTPROP IND isIn {agent}' for agent in agents[:8]],
        f'QUERY IND - {agents[0]}', f'QUERY IND OBJECTPROP {agents[1]}',
        f'QUERY CLASS IND {abox.rooms[0]} true', f'QUERY DATAPROP IND batteryLevel {agents[2]}',
    ]


def _heavy_queries(abox: RoboticsABox) -> List[str]:
    """The typical twenty with two replaced by a SPARQL SELECT and a DL query."""
    return _typical_queries(abox)[:18] + [
        'SELECT ?who WHERE { ?who :isIn :kitchen }', 'QUERY IND DL "Person and isIn some Room"']


def leaks(scratch: pathlib.Path, snapshot: CoreSnapshot,
          checkpoints: List[int]) -> Dict[str, Any]:
    """Figures of measurement 4."""
    node = BenchNode(scratch, snapshot, preload_robotics=True)
    try:
        session = _session(node)
        reference = session.reference('robotics')
        sink = []

        def cycle():
            with reference.subscribe('QUERY IND CLASS OccupiedRoom', sink.append):
                pass
        for _ in range(100):
            cycle()
        time.sleep(2)
        figures: Dict[str, Any] = {'warm-up cycles': 100, 'before': _memory(node)}
        done = 0
        started = time.monotonic()
        for checkpoint in checkpoints:
            while done < checkpoint:
                cycle()
                done += 1
            time.sleep(2)
            figures[f'after {checkpoint}'] = _memory(node)
        figures['cycles_per_s'] = round(done / (time.monotonic() - started), 1)
        figures['answer_topics_left'] = _answer_topics(node)
        figures['initial_answers_delivered'] = len(sink)
        last = figures[f'after {checkpoints[-1]}']
        for process in ('node', 'core'):
            figures[f'{process}_growth_mib'] = round(
                last[process]['rss_mib'] - figures['before'][process]['rss_mib'], 1)
        if last['core_live_heap_mib'] is not None:
            figures['core_live_heap_growth_mib'] = round(
                last['core_live_heap_mib'] - figures['before']['core_live_heap_mib'], 1)
        return figures
    finally:
        node.stop()


def _memory(node: BenchNode) -> Dict[str, Any]:
    """Resident memory of node and core, and the core's live heap after a full collection.

    The JVM keeps heap it has grown into, so the core's resident memory says little about a
    leak; what a full collection leaves alive does.
    """
    figures: Dict[str, Any] = node.memory()
    pid = str(node.process.core_pid())
    try:
        subprocess.run(['jcmd', pid, 'GC.run'], capture_output=True, timeout=120, check=True)
        info = subprocess.run(['jcmd', pid, 'GC.heap_info'], capture_output=True, text=True,
                              timeout=120, check=True).stdout
        used = re.search(r'used (\d+)K', info)
        figures['core_live_heap_mib'] = round(int(used.group(1)) / 1024, 1) if used else None
    except (OSError, subprocess.SubprocessError):
        figures['core_live_heap_mib'] = None  # jcmd comes with a JDK, not with every JRE
    return figures


def _answer_topics(node: BenchNode) -> int:
    """Answer topics the node still publishes (an ended subscription leaves none)."""
    names = node.transport.node.get_publisher_names_and_types_by_node(
        'armor_service', node.namespace)
    return sum('/armor_answers/' in name for name, _ in names)


REPO_ROBOTICS = pathlib.Path(__file__).resolve().parents[1] / 'ontologies' / 'robotics.owl'


def measure(scale: Dict[str, Any], only: str = '', log=print) -> Dict[str, Any]:
    """Runs the measurements (or only one of them) and returns their figures."""
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-events-bench-'))
    snapshot = CoreSnapshot(scratch)
    results: Dict[str, Any] = {'latency': []}
    for size in (scale['sizes'] if only in ('', 'latency') else []):
        log(f'1. notification latency, {size} individuals, ELK ...')
        results['latency'].append(notification_latency(scratch, snapshot, size, 'ELK',
                                                       scale['samples']))
        if size <= 1000:
            log(f'1. notification latency, {size} individuals, HERMIT ...')
            results['latency'].append(notification_latency(scratch, snapshot, size, 'HERMIT',
                                                           scale['hermit_samples']))
    if only in ('', 'completeness'):
        log(f'2. completeness over {scale["changes"]} changes ...')
        results['completeness'] = completeness(scratch, snapshot, scale['changes'])
    if only in ('', 'cost'):
        log('3. round trips with 20 subscriptions open and none ...')
        results['directive_cost'] = directive_cost(scratch, snapshot,
                                                   min(scale['sizes'][0], 1000),
                                                   scale['round_trips'], scale['pace_s'])
    if only in ('', 'leaks'):
        log(f'4. memory over {scale["cycles"][-1]} subscribe/unsubscribe cycles ...')
        results['leaks'] = leaks(scratch, snapshot, scale['cycles'])
    return results


def report(results: Dict[str, Any]) -> str:
    lines = ['Change events and subscriptions (issue 12)', '',
             '1. change acknowledged -> notification received',
             f'   {"individuals":>11}  {"reasoner":8}  {"query":30}  {"topic p50/p99 ms":>17}'
             f'  {"answer p50/p99 ms":>17}']
    for row in results['latency']:
        topic, answer = row['change_topic'], row['inferred_answer']
        lines.append(f'   {row["individuals"]:>11,}  {row["reasoner"]:8}  {row["query"][16:]:30}  '
                     f'{topic["p50_ms"]:>8.2f}/{topic["p99_ms"]:<8.2f}  '
                     f'{answer["p50_ms"]:>8.2f}/{answer["p99_ms"]:<8.2f}'
                     f'  ({topic["calls"]} changes)')
    if 'completeness' in results:
        lines += _completeness_lines(results['completeness'])
    if 'directive_cost' in results:
        lines += _cost_lines(results['directive_cost'])
    if 'leaks' in results:
        lines += _leak_lines(results['leaks'])
    return '\n'.join(lines)


def _completeness_lines(c: Dict[str, Any]) -> List[str]:
    return ['', f'2. over {c["acknowledged_changes"]:,} acknowledged changes '
            f'({c["changes_per_s"]}/s, 4 clients, {c["failed_lists"]} failed lists): '
            f'lost {c["lost"]}, duplicated {c["duplicated"]}, unexpected {c["unexpected"]}, '
            f'reported missed {c["missed_reported_by_client"]}; subscription answer agrees '
            f'with the query: {c["subscription_answer_agrees"]} ({c["subscription_answer_size"]}'
            f' answers, {c["subscription_messages"]} messages)']


def _cost_lines(d: Dict[str, Any]) -> List[str]:
    lines = ['', f'3. change round trip, {d["individuals"]:,} individuals, {d["reasoner"]}, '
             f'{d["subscriptions"]} subscriptions open vs none (paced: one change every '
             f'{d["pace_s"]} s; heavy: with a SPARQL SELECT and a DL query among the 20)']
    for label in ('back_to_back', 'paced', 'heavy_back_to_back'):
        row = d[label]
        none, opened = row['none'], row['open']
        lines.append(f'   {label:18} p50/p99/mean ms: none {none["p50_ms"]:.1f}/'
                     f'{none["p99_ms"]:.1f}/{none["mean_ms"]:.1f}, open {opened["p50_ms"]:.1f}/'
                     f'{opened["p99_ms"]:.1f}/{opened["mean_ms"]:.1f}; open/none p50 '
                     f'{row["p50_ratio"]:.3f}, p99 {row["p99_ratio"]:.3f}, mean '
                     f'{row["mean_ratio"]:.3f} ({opened["calls"]} calls each)')
    return lines


def _leak_lines(m: Dict[str, Any]) -> List[str]:
    lines = ['', '4. resident memory (MiB) over subscribe/unsubscribe cycles '
             f'({m["cycles_per_s"]} cycles/s)']
    for key, value in m.items():
        if isinstance(value, dict) and 'node' in value:
            lines.append(f'   {key:14} node {value["node"]["rss_mib"]:8.1f}   core '
                         f'{value["core"]["rss_mib"]:8.1f}   core live heap after a full GC '
                         f'{value["core_live_heap_mib"]}')
    lines.append(f'   growth: node {m["node_growth_mib"]} MiB, core {m["core_growth_mib"]} MiB '
                 f'(live heap {m.get("core_live_heap_growth_mib")} MiB); answer topics left on '
                 f'the node: {m["answer_topics_left"]}')
    return lines


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--smoke', action='store_true', help='tiny sizes: proves it runs')
    parser.add_argument('--json', type=pathlib.Path, help='also write the raw figures here')
    parser.add_argument('--only', choices=['latency', 'completeness', 'cost', 'leaks'],
                        help='one measurement only')
    parser.add_argument('--cycles', help='checkpoints of measurement 4, e.g. 1000,10000,30000')
    args = parser.parse_args()
    scale = dict(SMOKE if args.smoke else FULL)
    if args.cycles:
        scale['cycles'] = [int(n) for n in args.cycles.split(',')]
    results = measure(scale, args.only or '',
                      log=lambda text: print(text, file=sys.stderr, flush=True))
    print(report(results))
    if args.json:
        args.json.write_text(json.dumps(results, indent=2))
    return 0


if __name__ == '__main__':
    sys.exit(main())
