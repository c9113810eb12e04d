# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Time to the first justification (issue 31, docs/explanations.md).

    python bench/explanations.py [--smoke] [--json]

On the robotics benchmark ABox (bench/abox.py: a fifth rooms in one corridor chain, so the whole
ABox is one connected part, the rest agents two or more to a room) at 1,000 and 10,000
individuals (100,000 in the full run), with HermiT, it times EXPLAIN ... 1 in the core
(ExplanationBench, an ArmorCore in a JVM with no ROS), on facts that hold and are not asserted:

- a class assertion: ``roomK OccupiedRoom`` (needs the inverse of isIn, the agent's isIn and type);
- a property assertion: ``roomK contains agent`` (needs the inverse);
- a subsumption on the same TBox: ``RobotInRoom SubClassOf Agent``.

Different rooms are asked in turn, so no answer is a cache hit. Targets (issue 31): p50 <= 100 ms
at 10,000 individuals, <= 1 s at 100,000. The description of each answer says how many axioms
were searched; the table shows the largest.
"""

import argparse
import json
import pathlib
import re
import subprocess
import sys
import tempfile
from typing import Dict, List

from abox import RoboticsABox
from harness import CoreSnapshot, latency_summary

BENCH_CLASS = 'io.github.armor.core.bench.ExplanationBench'
TARGETS_MS = {10_000: 100, 100_000: 1000}
SIZES = {'full': {'sizes': [1000, 10_000, 100_000], 'samples': 20},
         'quick': {'sizes': [1000, 10_000], 'samples': 20},
         'smoke': {'sizes': [1000], 'samples': 3}}
SEARCHED = re.compile(r'searched (\d+) of (\d+) axioms')


def _questions(abox: RoboticsABox) -> Dict[str, List[str]]:
    """Facts that hold and are not asserted: occupied rooms, whom they contain."""
    pairs = [(abox.location[agent], agent) for agent in abox.agents[:20]]
    return {'class': [f'{room},OccupiedRoom' for room, _ in pairs],
            'property': [f'contains,{room},{agent}' for room, agent in pairs],
            'subsumption': ['RobotInRoom,Agent']}


def measure(scratch: pathlib.Path, snapshot: CoreSnapshot, scale_name: str) -> Dict:
    """Runs every size and kind; returns the figures by size then kind."""
    plan = SIZES[scale_name]
    results: Dict = {'samples': plan['samples'], 'sizes': {}}
    for size in plan['sizes']:
        abox = RoboticsABox(size)
        ontology = abox.write(scratch / f'explain{size}.owl')
        questions = _questions(abox)
        by_kind = {}
        for kind, words in (('class', 'EXPLAIN+IND+CLASS'), ('property', 'EXPLAIN+OBJECTPROP+IND'),
                            ('subsumption', 'EXPLAIN+CLASS+CLASS')):
            if not questions[kind]:
                by_kind[kind] = {'error': 'no question found in the generated ABox'}
                continue
            run = subprocess.run(['java', '-Xss64m', '-cp', snapshot.classpath, BENCH_CLASS,
                                  str(ontology), 'HERMIT', str(plan['samples']), words,
                                  *questions[kind]],
                                 capture_output=True, text=True, timeout=1800)
            if run.returncode != 0:
                by_kind[kind] = {'error': (run.stderr.strip().splitlines() or ['?'])[-1]}
                continue
            figures = json.loads(run.stdout.strip().splitlines()[-1])
            searched = [SEARCHED.search(d) for d in figures['descriptions']]
            by_kind[kind] = {'load_s': figures['load_s'], **latency_summary(figures['seconds']),
                             'first_ms': figures['seconds'][0] * 1000,
                             'searched_axioms': max(int(m.group(1)) for m in searched if m),
                             'ontology_axioms': max(int(m.group(2)) for m in searched if m)}
        results['sizes'][size] = by_kind
    return results


def render(results: Dict) -> str:
    """The section's table (markdown)."""
    lines = [__doc__.split('\n\n', 2)[2].strip(), '',
             '| individuals | fact | p50 ms | p99 ms | first ms | axioms searched / in the ontology'
             ' | target |',
             '|---|---|---|---|---|---|---|']
    for size, by_kind in results['sizes'].items():
        for kind, row in by_kind.items():
            target = TARGETS_MS.get(int(size))
            if 'error' in row:
                lines.append(f'| {int(size):,} | {kind} | - | - | - | {row["error"]} | |')
                continue
            verdict = '' if target is None or kind == 'subsumption' else (
                f'<= {target} ms: {"met" if row["p50_ms"] <= target else "missed"}')
            lines.append(f'| {int(size):,} | {kind} | {row["p50_ms"]:.1f} | {row["p99_ms"]:.1f} | '
                         f'{row["first_ms"]:.1f} | {row["searched_axioms"]:,} / '
                         f'{row["ontology_axioms"]:,} | {verdict} |')
    return '\n'.join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--smoke', action='store_true', help='1,000 individuals, 3 samples')
    parser.add_argument('--full', action='store_true', help='up to 100,000 individuals')
    parser.add_argument('--json', action='store_true', help='print the raw figures')
    args = parser.parse_args()
    scale = 'smoke' if args.smoke else 'full' if args.full else 'quick'
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-explain-'))
    results = measure(scratch, CoreSnapshot(scratch), scale)
    print(json.dumps(results, indent=2) if args.json else render(results))


if __name__ == '__main__':
    sys.exit(main())
