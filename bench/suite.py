# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The benchmark suite: every benchmark in one run, written to a Markdown report.

    python bench/suite.py [--scale full|smoke] [--report bench/REPORT.md]

`make bench` runs it at full scale (about 15 minutes on 2 cores) and writes bench/REPORT.md.
`--scale smoke` runs every benchmark on tiny sizes in a few minutes
(tests/integration/test_bench_smoke.py), so the suite cannot rot. The scale can also be set
with the environment variable ARMOR_BENCH_SCALE. Each benchmark is also a script of its own
(query_latency.py, batch_throughput.py, reasoning_cycle.py, robot_speed.py,
core_profile.py, lubm.py, default_clients.py, real_shapes.py, scenes.py, soma.py,
explanations.py). Sections 10
(scenes) and 11 (SOMA) run at full scale only; `python bench/scenes.py --smoke` and
`python bench/soma.py --smoke` are their small runs (tests/integration/test_bench_smoke.py,
tests/integration/test_soma.py).
Section 11 stops each reasoner's run at its budget (bench/soma.py BUDGET_S, WHOLE_BUDGET_S):
up to about 80 minutes for 100 and 1,000 individuals; 10,000 is `python bench/soma.py --sizes
10000`.

`--sections 9,12` reruns only the named sections and rewrites only them in an existing report
(sections 1 to 7 share the summary, so any of them reruns all seven). Sections 8 to 12 each say
when, at which commit and under which load they were measured.

Every figure stands on checked answers (bench/answers.py): a benchmark stops at a wrong answer
of ARMOR's, or records it where it also measures alternatives; the suite then writes the report
and fails, naming each ARMOR figure whose answers were wrong.
"""

import argparse
import datetime
import json
import os
import pathlib
import platform
import re
import subprocess
import sys
import tempfile
import time
from typing import Callable, Dict, List, NamedTuple, Optional, Tuple

from answers import wrong_in
from harness import REPO, SCALES, CoreSnapshot
import batch_throughput
import core_profile
import default_clients
import explanations
import lubm
import query_latency
import real_shapes
import reasoning_cycle
import report
import robot_speed
import scenes
import soma


def _command_output(*command: str) -> str:
    try:
        completed = subprocess.run(command, capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return 'unknown'
    return (completed.stdout + completed.stderr).strip()


def machine() -> dict:
    cpu = next((line.split(':', 1)[1].strip() for line in
                pathlib.Path('/proc/cpuinfo').read_text().splitlines()
                if line.startswith('model name')), platform.processor() or 'unknown')
    memory_kib = next(int(line.split()[1]) for line in
                      pathlib.Path('/proc/meminfo').read_text().splitlines()
                      if line.startswith('MemTotal'))
    return {'CPU': cpu, 'cores (nproc)': os.cpu_count(),
            'memory': f'{memory_kib / 1024 / 1024:.1f} GiB', 'kernel': platform.release(),
            'load average at the start': ', '.join(f'{v:.2f}' for v in os.getloadavg())}


def versions(snapshot: CoreSnapshot) -> dict:
    from importlib import metadata

    def package(name):
        try:
            return metadata.version(name)
        except metadata.PackageNotFoundError:
            return 'not installed'

    found = {'Java': _command_output('java', '-version').splitlines()[0],
             'Python': platform.python_version(), 'rclpy': package('rclpy'),
             'Fast DDS': package('ros-fastdds'), 'owlready2': package('owlready2')}
    found.update(snapshot.library_versions())
    return found


class Section(NamedTuple):
    """A section that renders from its own results alone, so it can be rerun by itself."""
    number: int
    heading: str
    key: str
    measure: Callable[[pathlib.Path, CoreSnapshot, str], object]
    render: Callable[[object], str]
    scales: Tuple[str, ...] = ('full', 'smoke')


def _real_shapes_text(results) -> str:
    return (real_shapes.__doc__.split('\n\n', 2)[2].strip() + '\n\n'
            + real_shapes.render(results))


# Rendered together by report.render, with the title, the summary and the machine.
JOINT_SECTIONS = (1, 2, 3, 4, 5, 6, 7)
STANDALONE_SECTIONS = (
    Section(8, 'Plain rclpy clients with the default QoS (issue 20)', 'default_clients',
            lambda scratch, snapshot, scale: default_clients.measure(
                scratch, snapshot, **default_clients.SUITE_SIZES[scale]),
            default_clients.render),
    Section(9, 'The ontologies robots really use (issue 28)', 'real_shapes',
            real_shapes.measure, _real_shapes_text),
    Section(10, 'Scenes by demonstration (issue 32)', 'scenes', scenes.measure, scenes.render,
            scales=('full',)),
    Section(11, "KnowRob's upper ontology, SOMA and DUL (issue 36)", 'soma',
            lambda scratch, snapshot, scale: soma.measure(scratch, snapshot, scale,
                                                          sizes=[100, 1000]),
            soma.render, scales=('full',)),
    Section(12, 'Explanations: time to the first justification (issue 31)', 'explanations',
            lambda scratch, snapshot, scale: explanations.measure(
                scratch, snapshot, 'full' if scale == 'full' else 'smoke'),
            explanations.render),
)


def _standalone_text(section: Section, results, provenance: str) -> str:
    return (f'## {section.number}. {section.heading}\n\n{provenance}'
            f'{section.render(results).strip()}\n')


def _replace_sections(report_text: str, texts: Dict[int, str], head: Optional[str] = None) -> str:
    """The report with each numbered section in texts put in place of the old one (or added in
    number order when the report has none yet), every other section kept as it was; with head,
    the title, summary and sections 1 to 7 (rendered together) replaced by it."""
    parts = re.split(r'(?m)^(?=## )', report_text)

    def number(part):
        found = re.match(r'## (\d+)\. ', part)
        return int(found.group(1)) if found else None

    if head is not None:
        parts = re.split(r'(?m)^(?=## )', head) + [
            part for part in parts[1:] if (number(part) or 0) > JOINT_SECTIONS[-1]]
    kept = [part for part in parts[1:] if number(part) not in texts]
    for wanted, text in sorted(texts.items()):
        at = next((i for i, part in enumerate(kept)
                   if number(part) is not None and number(part) > wanted), len(kept))
        kept.insert(at, text)
    return '\n\n'.join(part.strip('\n') for part in [parts[0]] + kept) + '\n'


def _commit() -> str:
    return _command_output('git', '-C', str(REPO), 'describe', '--always', '--dirty')


def _measure_joint(scale, scratch: pathlib.Path, snapshot: CoreSnapshot, stage) -> dict:
    """Sections 1 to 7: measured and rendered together (the summary and the recommended
    reasoner draw on all of them)."""
    results = {}
    stage('1. transport overhead')
    results['transport'] = {'calls': scale.latency_calls,
                            **query_latency.measure(scale.latency_calls, scratch, snapshot)}
    stage('2. batch throughput')
    results['batch'] = batch_throughput.measure(scale.batch_lists, scale.batch_budget_s,
                                                scratch, snapshot, scale.warmup_lists)
    stage('3 and 4. reasoning under updates, memory')
    results['reasoning'] = reasoning_cycle.measure(
        scale.abox_sizes, scale.cycles, scale.cycle_budget_s, scale.owlready_budget_s, scratch,
        snapshot)
    stage('7. reasoning at robot speed (issue 15)')
    results['robot_speed'] = {
        'large_individuals': scale.large_abox, 'busy_individuals': scale.busy_abox,
        'large': robot_speed.measure_large(scratch, snapshot, scale.large_abox, scale.cycles,
                                           scale.large_budget_s),
        'busy': robot_speed.measure_busy_reads(scratch, snapshot, scale.busy_abox,
                                               scale.busy_idle_calls, scale.busy_writes,
                                               scale.busy_budget_s),
        'memory': robot_speed.measure_memory(scratch, snapshot, max(scale.abox_sizes),
                                             scale.cycles,
                                             scale.cycle_budget_s[max(scale.abox_sizes)],
                                             scale.jvm_variants),
        'directions': robot_speed.measure_directions(
            scratch, snapshot, max(scale.abox_sizes), scale.cycles,
            scale.cycle_budget_s[max(scale.abox_sizes)]),
    }
    stage('5. profiles')
    choice, _ = report.recommend(results['reasoning'])
    reasoner, mode = choice or ('HERMIT', 'non-buffered')
    buffered, with_reason = reasoning_cycle.MODES[mode]
    largest = max(scale.abox_sizes)
    results['profiles'] = {
        'Single ADDs': core_profile.profile_single_adds(scratch, snapshot, scale.profile_s),
        'Batch': core_profile.profile_batch(scratch, snapshot, scale.profile_s,
                                            max(scale.batch_lists)),
        'Reasoning cycle': core_profile.profile_cycle(
            scratch, snapshot, scratch / f'abox{largest}.owl', largest, reasoner, buffered,
            with_reason, scale.profile_s),
    }
    stage('6. SPARQL on LUBM')
    results['lubm'] = lubm.measure(lubm.SCALES[scale.name], scratch, snapshot)
    return results


def run(scale_name: str, report_path: pathlib.Path,
        sections: Optional[List[int]] = None) -> dict:
    """Runs the benchmarks (all, or the numbered sections: any of 1 to 7 reruns those seven
    together), writes or rewrites the report, and returns the raw results."""
    scale = SCALES[scale_name]
    numbers = set(sections) if sections else None
    known = set(JOINT_SECTIONS) | {section.number for section in STANDALONE_SECTIONS}
    if numbers and not numbers <= known:
        sys.exit(f'--sections: no section {sorted(numbers - known)}')
    joint = numbers is None or bool(numbers & set(JOINT_SECTIONS))
    standalone = [section for section in STANDALONE_SECTIONS
                  if (section.number in numbers if numbers else scale_name in section.scales)]
    for section in standalone:
        if scale_name not in section.scales:
            sys.exit(f'--sections: section {section.number} runs at scale '
                     + ' or '.join(section.scales) + ' only')
    started = time.monotonic()
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-'))
    snapshot = CoreSnapshot(scratch)
    results = {'scale': scale_name,
               'date': datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC'),
               'commit': _commit(), 'machine': machine(), 'versions': versions(snapshot)}

    def stage(name):
        print(f'[bench {time.monotonic() - started:6.0f} s] {name}', file=sys.stderr, flush=True)

    if joint:
        results.update(_measure_joint(scale, scratch, snapshot, stage))
        results['duration_s'] = time.monotonic() - started
    texts = {}
    for section in standalone:
        section_started = time.monotonic()
        load = ', '.join(f'{value:.2f}' for value in os.getloadavg())
        stage(f'{section.number}. {section.heading}')
        results[section.key] = section.measure(scratch, snapshot, scale_name)
        provenance = (
            f'*Measured by `python bench/suite.py --sections {section.number}` or `make bench` '
            f'(scale `{scale_name}`) on '
            f'{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, commit '
            f'`{results["commit"]}`, in {(time.monotonic() - section_started) / 60:.1f} minutes; '
            f'load average at its start {load}.*\n\n')
        texts[section.number] = _standalone_text(section, results[section.key], provenance)
    (scratch / 'results.json').write_text(json.dumps(results, indent=2, default=str))
    head = report.render(results) if joint else None
    if numbers is None or not report_path.exists():
        old = head or '# ARMOR for ROS 2: benchmark report\n'
    else:
        old = report_path.read_text()
    report_path.write_text(_replace_sections(old, texts, head))
    stage(f'report written to {report_path} (raw figures: {scratch / "results.json"})')
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--scale', choices=sorted(SCALES),
                        default=os.environ.get('ARMOR_BENCH_SCALE', 'full'))
    parser.add_argument('--report', type=pathlib.Path, default=REPO / 'bench' / 'REPORT.md')
    parser.add_argument('--sections', type=lambda text: [int(n) for n in text.split(',')],
                        help='comma-separated section numbers: run only these and rewrite only '
                             'them in the report (any of 1 to 7 reruns those seven together)')
    options = parser.parse_args()
    wrong = wrong_in(run(options.scale, options.report, options.sections))
    if wrong:
        sys.exit('wrong answers behind these figures:\n  ' + '\n  '.join(wrong))
    print('every checked answer was right', file=sys.stderr)


if __name__ == '__main__':
    main()
