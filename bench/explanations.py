# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Time to the first justification (issue 31, docs/explanations.md).

    python bench/explanations.py [--smoke] [--full] [--sizes N,...] [--json] [--baseline-jar JAR]

EXPLAIN ... 1 is timed in the core (ExplanationBench, an ArmorCore in a JVM with no ROS) with
HermiT, on facts that hold and are not asserted, different ones in turn (no answer is a cache hit):

- robotics benchmark ABox (bench/abox.py: a fifth rooms in one corridor chain, so the whole ABox
  is one connected part, the rest agents two or more to a room): a class assertion
  ``roomK OccupiedRoom`` (the inverse of isIn, the agent's isIn and type), a property assertion
  ``roomK contains agent`` (the inverse), a subsumption on its small TBox
  ``RobotInRoom SubClassOf Agent``;
- part-of map (bench/real_shapes.py's shape (b): places in a transitive part-of tree, agents
  located at rooms, BusyPlace = Place and inverse(locatedAt) some Agent): a class assertion
  ``roomK BusyPlace`` and a property assertion ``roomK partOf building`` (transitivity, three links);
- a large TBox, SOMA-HOME with its whole import closure (SOMA and DUL, `shared/data/soma`):
  subsumptions through SOMA into DUL (``Cup SubClassOf PhysicalObject`` and others).

Every justification answered is checked after the timing, as ExplanationsTest checks them: its
axioms are the ontology's, it entails the fact (HermiT, on it alone), it is minimal. Targets (issue
31): p50 <= 100 ms at 10,000 individuals, <= 1 s at 100,000. The description of each answer says
how many axioms were searched; the table shows the largest. --baseline-jar times another build of
the core (an armor-core.jar with its lib/ beside it) on the same files, each case in turn with
this one, so a change is measured side by side.
"""

import argparse
import json
import pathlib
import re
import subprocess
import sys
import tempfile
from typing import Dict, List, Optional

from abox import RoboticsABox
from answers import wrong_in
from harness import REPO, CoreSnapshot, latency_summary
from real_shapes import PartOfMap

sys.path.insert(0, str(REPO / 'tests' / 'integration'))
from soma_kitchen import soma_data  # noqa: E402

BENCH_CLASS = 'io.github.armor.core.bench.ExplanationBench'
TARGETS_MS = {10_000: 100, 100_000: 1000}
SIZES = {'full': {'sizes': [1000, 10_000, 100_000], 'samples': 20},
         'quick': {'sizes': [1000, 10_000], 'samples': 20},
         'smoke': {'sizes': [1000], 'samples': 3}}
SEARCHED = re.compile(r'searched (\d+) of (\d+) axioms')
WORDS = {'class': 'EXPLAIN+IND+CLASS', 'property': 'EXPLAIN+OBJECTPROP+IND',
         'subsumption': 'EXPLAIN+CLASS+CLASS'}
SOMA = 'http://www.ease-crc.org/ont/SOMA.owl#'
DUL = 'http://www.ontologydesignpatterns.org/ont/dul/DUL.owl#'
# Inferred through SOMA-HOME's and SOMA-OBJ's hierarchies into DUL's, none asserted.
SOMA_SUBSUMPTIONS = [f'{SOMA}Cup,{DUL}PhysicalObject', f'{SOMA}Crockery,{DUL}PhysicalObject',
                     f'{SOMA}Cup,{DUL}DesignedArtifact', f'{SOMA}Crockery,{DUL}Object']


def _robotics(size: int, path: pathlib.Path):
    """The file and the questions by kind: occupied rooms, whom they contain."""
    abox = RoboticsABox(size)
    pairs = [(abox.location[agent], agent) for agent in abox.agents[:20]]
    return abox.write(path.with_suffix('.owl')), {
        'class': [f'{room},OccupiedRoom' for room, _ in pairs],
        'property': [f'contains,{room},{agent}' for room, agent in pairs],
        'subsumption': ['RobotInRoom,Agent']}


def _part_of(size: int, path: pathlib.Path):
    """The file and the questions by kind: busy rooms, rooms part of the building."""
    shape = PartOfMap(size, functional=False)
    rooms = list(dict.fromkeys(shape.at[agent] for agent in shape.agents))[:20]
    return shape.write(path.with_suffix('.ofn')), {
        'class': [f'{room},BusyPlace' for room in rooms],
        'property': [f'partOf,{room},building' for room in rooms]}


def _cases(scale_name: str, sizes: List[int], tbox: bool) -> List[tuple]:
    """(map, size or None for a TBox alone, how to write it) in the order they run."""
    cases = [('robotics', size, _robotics) for size in sizes]
    cases += [('part-of map', size, _part_of) for size in sizes]
    if tbox and scale_name != 'smoke':  # its classification alone takes longer than make test's smoke run should
        soma = soma_data() / 'SOMA-HOME.owl'
        cases.append(('SOMA-HOME (TBox)', None, lambda size, path: (soma, {'subsumption': SOMA_SUBSUMPTIONS})))
    return cases


def _run(classpath: str, ontology: pathlib.Path, samples: int, kind: str, questions: List[str]) -> Dict:
    run = subprocess.run(['java', '-Xss64m', '-cp', classpath, BENCH_CLASS, str(ontology), 'HERMIT',
                          str(samples), WORDS[kind], *questions],
                         capture_output=True, text=True, timeout=3600)
    if run.returncode != 0:
        # The harness's own "failed: <code> ..." line, or the exception's first line (a stack
        # trace ends in "... N more", which says nothing).
        lines = run.stderr.strip().splitlines()
        said = [line for line in lines if line.startswith('failed:') or 'Exception' in line or 'Error' in line]
        return {'error': (said or lines or ['exit code ' + str(run.returncode)])[0][:300]}
    figures = json.loads(run.stdout.strip().splitlines()[-1])
    searched = [SEARCHED.search(d) for d in figures['descriptions']]
    return {'load_s': figures['load_s'], **latency_summary(figures['seconds']),
            'first_ms': figures['seconds'][0] * 1000,
            'searched_axioms': max(int(m.group(1)) for m in searched if m),
            'ontology_axioms': max(int(m.group(2)) for m in searched if m),
            'right': figures['right'], 'wrong': figures['wrong']}


def measure(scratch: pathlib.Path, snapshot: CoreSnapshot, scale_name: str,
            baseline: Optional[pathlib.Path] = None, sizes: Optional[List[int]] = None) -> Dict:
    """Runs every case (the maps at `sizes` only, and no TBox, when given); returns a row per map,
    size and kind of fact (with the baseline's beside)."""
    plan = SIZES[scale_name]
    results: Dict = {'samples': plan['samples'], 'rows': []}
    for label, size, write in _cases(scale_name, sizes or plan['sizes'], tbox=sizes is None):
        ontology, questions = write(size, scratch / f'explain_{label.split()[0]}_{size}')
        for kind, asked in questions.items():
            row = {'map': label, 'individuals': size, 'kind': kind,
                   **_run(snapshot.classpath, ontology, plan['samples'], kind, asked)}
            if baseline is not None:
                # This build's bench class over the other build's core and libraries.
                row['baseline'] = _run(f'{snapshot.root / "test-classes"}:{baseline}:{baseline.parent / "lib"}/*',
                                       ontology, plan['samples'], kind, asked)
            results['rows'].append(row)
    return results


def render(results: Dict) -> str:
    """The section's table (markdown)."""
    baseline = any('baseline' in row for row in results['rows'])
    lines = [__doc__.split('\n\n', 2)[2].rsplit('\n\n', 1)[0].strip(), '',
             f'{results["samples"]} answers per row (one JVM per row; the first answer, which warms '
             'it, counts in p50/p99 and is shown apart).', '',
             '| map | individuals | fact | p50 ms | p99 ms | first ms | axioms searched / in the ontology'
             ' | justifications right | target |' + (' baseline p50 / p99 ms | p50 ratio |' if baseline else ''),
             '|---|---|---|---|---|---|---|---|---|' + ('---|---|' if baseline else '')]
    for row in results['rows']:
        size = f'{row["individuals"]:,}' if row['individuals'] else 'TBox'
        if 'error' in row:
            lines.append(f'| {row["map"]} | {size} | {row["kind"]} | - | - | - | {row["error"]} | | |'
                         + (' | |' if baseline else ''))
            continue
        target = TARGETS_MS.get(row['individuals'] or 0)
        verdict = '' if target is None or row['kind'] == 'subsumption' else (
            f'<= {target} ms: {"met" if row["p50_ms"] <= target else "missed"}')
        right = (f'{row["right"]} of {row["right"] + len(row["wrong"])}' if not row['wrong']
                 else f'**{len(row["wrong"])} wrong** of {row["right"] + len(row["wrong"])}')
        line = (f'| {row["map"]} | {size} | {row["kind"]} | {row["p50_ms"]:.1f} | {row["p99_ms"]:.1f} | '
                f'{row["first_ms"]:.1f} | {row["searched_axioms"]:,} / {row["ontology_axioms"]:,} | {right} | '
                f'{verdict} |')
        if baseline:
            base = row.get('baseline', {})
            line += (f' {base["p50_ms"]:.1f} / {base["p99_ms"]:.1f} | {row["p50_ms"] / base["p50_ms"]:.2f} |'
                     if 'p50_ms' in base else f' {base.get("error", "-")} | |')
        lines.append(line)
    return '\n'.join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--smoke', action='store_true', help='1,000 individuals, 3 samples')
    parser.add_argument('--full', action='store_true', help='up to 100,000 individuals')
    parser.add_argument('--json', action='store_true', help='print the raw figures')
    parser.add_argument('--sizes', type=lambda text: [int(n) for n in text.split(',')],
                        help='only the maps at these sizes (no TBox), e.g. 100000')
    parser.add_argument('--baseline-jar', type=pathlib.Path,
                        help='another core build (armor-core.jar, lib/ beside it) to time beside this one')
    args = parser.parse_args()
    if args.baseline_jar and not (args.baseline_jar.is_file() and (args.baseline_jar.parent / 'lib').is_dir()):
        parser.error(f'--baseline-jar: {args.baseline_jar} with a lib/ folder beside it is missing')
    scale = 'smoke' if args.smoke else 'full' if args.full else 'quick'
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-explain-'))
    results = measure(scratch, CoreSnapshot(scratch), scale,
                      args.baseline_jar.resolve() if args.baseline_jar else None, args.sizes)
    print(json.dumps(results, indent=2) if args.json else render(results))
    wrong = wrong_in({'explanations': results})
    if wrong:
        sys.exit('wrong justifications:\n' + '\n'.join(wrong))


if __name__ == '__main__':
    sys.exit(main())
