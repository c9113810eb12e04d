# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Benchmark 6, SPARQL on LUBM: the 14 queries through the service, in the core, on bare Jena.

    python bench/lubm.py [--smoke]

One department (Department0 of University0, bench/data/lubm, Openllet, after REASON):
- the 14-query mean end to end over ROS 2 (QUERY SPARQL through the node, every row checked
  against the published count);
- the same queries in a separate JVM through ArmorCore.execute, and with plain Jena ARQ over a
  plain copy of the same graph, the floor (core/src/test/.../command/LubmBench.java);
- the first query after a one-fact change (ADD IND CLASS of a new graduate student; query 6 must
  grow by one), with the graph's own share: reasoner brought up to date, realisation,
  derivation, against a fresh build;
- the rows again with a second reasoner (HermiT).
Ten departments (bench/lubm_generator.py, expected rows counted from the generated data): LOAD,
REASON, first query (the graph is built), the 14-query mean over ROS 2 and in the core, rows
checked with both reasoners. Where a target is missed, a flight recording of the core while it
repeats that workload shows what stands in the way.
"""

import argparse
import dataclasses
import json
import pathlib
import shutil
import statistics
import subprocess
import tempfile
import time
from typing import Dict, List, Optional

import core_profile
from harness import REPO, BenchNode, CoreSnapshot, Deadline, percentile
import lubm_generator

LUBM = REPO / 'bench' / 'data' / 'lubm'
DEPARTMENT = 'http://www.Department0.University0.edu'
UB = 'http://swat.cse.lehigh.edu/onto/univ-bench.owl#'
GROWING_QUERY = 6  # all students: a new graduate student is one by inference
BENCH_CLASS = 'io.github.armor.core.sparql.LubmBench'

TARGETS_MS = {'service': 3.0, 'in_process': 1.4, 'first_after_change': 50.0, 'departments': 10.0}

COMPONENTS = (  # (component, frame prefixes); the first match on a sample's stack wins
    ('reasoner (realisation after a change)',
     ('org.semanticweb.HermiT', 'openllet', 'uk.ac.manchester.cs.jfact', 'org.semanticweb.elk')),
    ('OWL API ontology changes (ADD)',
     ('uk.ac.manchester.cs.owl.owlapi.OWLOntologyManagerImpl.applyChanges',
      'uk.ac.manchester.cs.owl.owlapi.OWLImmutableOntologyImpl',
      'uk.ac.manchester.cs.owl.owlapi.Internals')),
    ('SPARQL graph: build or derive', ('io.github.armor.core.sparql.InferredGraph',
                                       'io.github.armor.core.sparql.SparqlGraphs',
                                       'io.github.armor.core.sparql.ReasonerAnswers')),
    ('query parsing', ('org.apache.jena.sparql.lang',)),
    ('graph lookups (Jena in-memory graph)', ('org.apache.jena.mem', 'org.apache.jena.graph',
                                              'io.github.armor.core.sparql.LayeredGraph')),
    ('ARQ evaluation (joins, iterators)', ('org.apache.jena',)),
    ('rows: rendering and response', ('io.github.armor.core.sparql.Sparql.render',
                                      'io.github.armor.core.sparql.Sparql.rowText',
                                      'io.github.armor.core.answers.Rendering',
                                      'io.github.armor.core.api')),
    ('wire: socket and JSON', ('com.google.gson', 'io.github.armor.core.server.WireCodec',
                               'io.github.armor.core.server.CoreServer.readFrame',
                               'io.github.armor.core.server.CoreServer.writeFrame')),
    ('other ARMOR core code', ('io.github.armor.core',)),
)


@dataclasses.dataclass
class LubmScale:
    """How much benchmark 6 measures."""

    size: str              # lubm_generator size of the generated departments
    department: str        # 'published' (bench/data/lubm) or 'generated' (one generated one)
    departments: int       # the larger data set
    rounds: int            # measured rounds of the 14 queries, one department
    warmup_rounds: int
    changes: int           # one-fact changes, each followed by the first query
    rounds_large: int      # measured rounds on the larger data set
    in_process_large: bool  # the larger data set in the core and with the second reasoner too
    profile: bool          # record profiles where a target is missed


SCALES = {
    'full': LubmScale('full', 'published', 10, rounds=200, warmup_rounds=30, changes=30,
                      rounds_large=20, in_process_large=True, profile=True),
    'smoke': LubmScale('tiny', 'generated', 2, rounds=2, warmup_rounds=1, changes=2,
                       rounds_large=1, in_process_large=False, profile=False),
}


@dataclasses.dataclass
class DataSet:
    name: str
    ontology: pathlib.Path
    queries: pathlib.Path

    def load_queries(self) -> List[dict]:
        return json.loads(self.queries.read_text())


def data_sets(scale: LubmScale, scratch: pathlib.Path) -> Dict[str, DataSet]:
    """The one-department and the larger data set, as files the benchmark node may read."""
    folder = scratch / 'lubm'
    folder.mkdir(exist_ok=True)
    if scale.department == 'published':
        one = DataSet('Department0 of University0 (UBA; rows as published)',
                      folder / 'university0-department0.owl', folder / 'queries.json')
        shutil.copy2(LUBM / 'university0-department0.owl', one.ontology)
        shutil.copy2(LUBM / 'queries.json', one.queries)
    else:
        one = DataSet(f'1 generated department ({scale.size}; rows counted from the data)',
                      folder / 'lubm-1.owl', folder / 'lubm-1-queries.json')
        lubm_generator.generate(1, one.ontology, one.queries, size=scale.size)
    many = DataSet(f'{scale.departments} generated departments ({scale.size}; rows counted '
                   'from the data)',
                   folder / f'lubm-{scale.departments}.owl',
                   folder / f'lubm-{scale.departments}-queries.json')
    lubm_generator.generate(scale.departments, many.ontology, many.queries, size=scale.size)
    return {'one': one, 'many': many}


def in_process(snapshot: CoreSnapshot, data: DataSet, reasoner: str, rounds: int,
               warmup_rounds: int, changes: int, timeout_s: float = 1800) -> dict:
    """LubmBench in its own JVM: ArmorCore, bare Jena, the change cycle, the graph's costs."""
    completed = subprocess.run(
        ['java', '-Xmx4g', '-Xss16m', '-cp', snapshot.classpath, BENCH_CLASS, str(data.ontology),
         str(data.queries), reasoner, str(rounds), str(warmup_rounds), str(changes)],
        capture_output=True, text=True, timeout=timeout_s)
    if completed.returncode != 0:
        raise RuntimeError(f'LubmBench failed: {completed.stderr[-3000:]}')
    return json.loads(completed.stdout.strip().splitlines()[-1])


def _ok(answer, what: str):
    if not answer.success:
        raise RuntimeError(f'{what} failed: {answer.exit_code} {answer.error_description}')
    return answer


def _timed(call):
    start = time.perf_counter()
    answer = call()
    return (time.perf_counter() - start) * 1000, answer


def service_queries(node: BenchNode, reference: str, queries: List[dict], rounds: int,
                    warmup_rounds: int, budget_s: float = 600) -> dict:
    """The 14 queries through the node, round after round; rows checked every time.

    After each query, `ASK {}` on the same reference: the round trip of a SPARQL query with
    nothing to find and one value to return (the floor for this path, with the same noise).
    """
    samples: List[List[float]] = [[] for _ in queries]
    floor: List[float] = []
    deadline = Deadline(budget_s)
    measured = 0
    for round_number in range(-warmup_rounds, rounds):
        if round_number >= 0 and measured and deadline.expired():
            break
        for index, query in enumerate(queries):
            elapsed, answer = _timed(lambda: node.call(reference, 'QUERY SPARQL', query['sparql'],
                                                       timeout_s=600))
            _ok(answer, f'query {query["query"]}')
            if len(answer.queried_objects) != query['expected_rows']:
                raise RuntimeError(f'query {query["query"]} answered '
                                   f'{len(answer.queried_objects)} rows, expected '
                                   f'{query["expected_rows"]}')
            if round_number >= 0:
                samples[index].append(elapsed)
            elapsed, _ = _timed(lambda: _ok(node.call(reference, 'QUERY SPARQL', 'ASK {}'), 'ASK'))
            if round_number >= 0:
                floor.append(elapsed)
        measured += round_number >= 0
    per_query = [statistics.fmean(values) for values in samples]
    return {'rounds': measured, 'per_query_ms': per_query, 'mean_ms': statistics.fmean(per_query),
            'ask_floor_ms': statistics.fmean(floor)}


def service_changes(node: BenchNode, reference: str, growing: dict, changes: int,
                    added_before: int = 0) -> dict:
    """ADD IND CLASS of a new graduate student, then the growing query twice.

    The students stay (a removal makes Openllet start afresh, seconds on this data): the growing
    query's expected rows count the `added_before` ones of earlier calls.
    """
    add_ms, first_ms, next_ms = [], [], []
    for k in range(changes):
        student = f'<{DEPARTMENT}/ServiceStudent{added_before + k}>'
        elapsed, _ = _timed(lambda: _ok(node.call(reference, 'ADD IND CLASS', student,
                                                  f'<{UB}GraduateStudent>'), 'ADD'))
        add_ms.append(elapsed)
        elapsed, answer = _timed(lambda: _ok(node.call(reference, 'QUERY SPARQL',
                                                       growing['sparql']), 'query'))
        if len(answer.queried_objects) != growing['expected_rows'] + added_before + k + 1:
            raise RuntimeError(f'the first query after change {k} missed the change: '
                               f'{len(answer.queried_objects)} rows')
        first_ms.append(elapsed)
        elapsed, _ = _timed(lambda: node.call(reference, 'QUERY SPARQL', growing['sparql']))
        next_ms.append(elapsed)
    return {'changes': changes, 'add_ms': add_ms, 'first_query_ms': first_ms,
            'next_query_ms': next_ms}


def load(node: BenchNode, reference: str, data: DataSet, reasoner: str = 'PELLET') -> dict:
    """LOAD (non-buffered reasoner), REASON, the first query (it builds the graph)."""
    figures = {}
    figures['load_ms'], _ = _timed(lambda: _ok(node.call(
        reference, 'LOAD FILE', str(data.ontology), '', 'false', reasoner, 'false',
        timeout_s=1800), 'LOAD'))
    figures['reason_ms'], _ = _timed(lambda: _ok(node.call(reference, 'REASON', timeout_s=1800),
                                                 'REASON'))
    first = data.load_queries()[0]
    figures['first_query_ms'], _ = _timed(lambda: _ok(node.call(
        reference, 'QUERY SPARQL', first['sparql'], timeout_s=1800), 'first query'))
    return figures


class Recording:
    """A flight recording of a running core, started and stopped around one workload."""

    def __init__(self, node: BenchNode, path: pathlib.Path):
        self.pid = node.process.core_pid()
        self.path = path

    def __enter__(self):
        subprocess.run(['jcmd', str(self.pid), 'JFR.start', 'name=lubm', 'settings=profile'],
                       check=True, capture_output=True, timeout=120)
        return self

    def __exit__(self, *exc):
        subprocess.run(['jcmd', str(self.pid), 'JFR.stop', 'name=lubm', f'filename={self.path}'],
                       check=True, capture_output=True, timeout=120)

    def summary(self, workload: str) -> dict:
        return {'workload': workload,
                **core_profile.summarise(core_profile.samples(self.path), components=COMPONENTS)}


def summarise_ms(values: List[float]) -> dict:
    if not values:
        return {'p50_ms': None, 'p90_ms': None, 'mean_ms': None}
    return {'p50_ms': statistics.median(values), 'p90_ms': percentile(values, 0.9),
            'mean_ms': statistics.fmean(values)}


def measure(scale: LubmScale, scratch: pathlib.Path, snapshot: CoreSnapshot) -> dict:
    """Every figure of benchmark 6 (see the module comment)."""
    sets = data_sets(scale, scratch)
    one, many = sets['one'], sets['many']
    results = {'data': {key: data.name for key, data in sets.items()}, 'targets_ms': TARGETS_MS}
    queries = one.load_queries()
    growing = queries[GROWING_QUERY - 1]

    results['in_process'] = in_process(snapshot, one, 'PELLET', scale.rounds,
                                       scale.warmup_rounds, scale.changes)
    results['second_reasoner'] = in_process(snapshot, one, 'HERMIT', 1, 0, 0)
    if scale.in_process_large:
        results['in_process_many'] = in_process(snapshot, many, 'PELLET', scale.rounds_large,
                                                min(scale.warmup_rounds, 5), 0)
        results['second_reasoner_many'] = in_process(snapshot, many, 'HERMIT', 1, 0, 0)

    node = BenchNode(scratch, snapshot, parameters={
        'jvm_options': '["-Xmx4g", "-XX:+ExitOnOutOfMemoryError", '
                       '"-XX:FlightRecorderOptions=stackdepth=512"]'})
    profiles = {}
    try:
        results['service_load'] = load(node, 'lubm', one)
        results['service'] = service_queries(node, 'lubm', queries, scale.rounds,
                                             scale.warmup_rounds)
        results['service_change'] = service_changes(node, 'lubm', growing, scale.changes)
        results['service_many_load'] = load(node, 'lubm_many', many)
        results['service_many'] = service_queries(node, 'lubm_many', many.load_queries(),
                                                  scale.rounds_large, min(scale.warmup_rounds, 5))
        if scale.profile:
            profiles = _profiles(node, scratch, results, queries, growing, many)
        _ok(node.call('lubm_many', 'DROP', timeout_s=600), 'DROP')
        _ok(node.call('lubm', 'DROP', timeout_s=600), 'DROP')
    finally:
        node.stop()
    results['profiles'] = profiles
    results['met'] = targets_met(results)
    return results


def first_after_change_ms(results: dict) -> Optional[float]:
    return summarise_ms(results['service_change']['first_query_ms'])['p50_ms']


def targets_met(results: dict) -> Dict[str, bool]:
    first = first_after_change_ms(results)
    core = results['in_process']['armor_core']['mean_ms']
    return {'service': results['service']['mean_ms'] <= TARGETS_MS['service'],
            'in_process': core <= TARGETS_MS['in_process'],
            'first_after_change': first is not None and first <= TARGETS_MS['first_after_change'],
            'departments': results['service_many']['mean_ms'] <= TARGETS_MS['departments']}


def _profiles(node: BenchNode, scratch: pathlib.Path, results: dict, queries: List[dict],
              growing: dict, many: DataSet) -> dict:
    """The core recorded while it repeats each workload whose target was missed."""
    met = targets_met(results)
    profiles = {}
    added = results['service_change']['changes']
    if not (met['service'] and met['in_process']):
        grown = [dict(q, expected_rows=q['expected_rows'] + added) if q['query'] == GROWING_QUERY
                 else q for q in queries]
        with Recording(node, scratch / 'lubm-queries.jfr') as recording:
            rounds = service_queries(node, 'lubm', grown, 300, 0, budget_s=60)['rounds']
        profiles['one department, 14 queries'] = recording.summary(
            f'{rounds} rounds of the 14 queries on one department through the service')
    if not met['first_after_change']:
        with Recording(node, scratch / 'lubm-change.jfr') as recording:
            service_changes(node, 'lubm', growing, 40, added_before=added)
        profiles['first query after a change'] = recording.summary(
            '40 cycles of ADD IND CLASS (a new graduate student), the query that grows by it, '
            'the same query again')
    if not met['departments']:
        with Recording(node, scratch / 'lubm-many.jfr') as recording:
            rounds = service_queries(node, 'lubm_many', many.load_queries(), 40, 0,
                                     budget_s=60)['rounds']
        profiles['more departments, 14 queries'] = recording.summary(
            f'{rounds} rounds of the 14 queries on {many.name} through the service')
    return profiles


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--smoke', action='store_true', help='tiny data, a few rounds')
    options = parser.parse_args()
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-'))
    results = measure(SCALES['smoke' if options.smoke else 'full'], scratch,
                      CoreSnapshot(scratch))
    print(json.dumps(results, indent=2, default=str))


if __name__ == '__main__':
    main()
