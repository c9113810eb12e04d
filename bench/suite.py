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
import subprocess
import sys
import tempfile
import time

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


def run(scale_name: str, report_path: pathlib.Path) -> dict:
    """Runs every benchmark, writes the report, and returns the raw results."""
    scale = SCALES[scale_name]
    started = time.monotonic()
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-'))
    snapshot = CoreSnapshot(scratch)
    results = {'scale': scale_name,
               'date': datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC'),
               'commit': _command_output('git', '-C', str(REPO), 'describe', '--always',
                                         '--dirty'),
               'machine': machine(), 'versions': versions(snapshot)}

    def stage(name):
        print(f'[bench {time.monotonic() - started:6.0f} s] {name}', file=sys.stderr, flush=True)

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
    stage('6. reasoning at robot speed (issue 15)')
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
    results['lubm'] = lubm.measure(lubm.SCALES[scale_name], scratch, snapshot)
    stage('8. plain rclpy clients with the default QoS (issue 20)')
    results['default_clients'] = default_clients.measure(
        scratch, snapshot, **default_clients.SUITE_SIZES[scale_name])
    stage('9. the ontologies robots really use (issue 28)')
    results['real_shapes'] = real_shapes.measure(scratch, snapshot, scale_name)
    if scale_name == 'full':
        stage('10. scenes by demonstration (issue 32)')
        results['scenes'] = scenes.measure(scratch, snapshot, scale_name)
        stage("11. KnowRob's upper ontology, SOMA and DUL (issue 36)")
        results['soma'] = soma.measure(scratch, snapshot, scale_name, sizes=[100, 1000])
    stage('12. explanations: time to the first justification (issue 31)')
    results['explanations'] = explanations.measure(scratch, snapshot,
                                                   'full' if scale_name == 'full' else 'smoke')
    results['duration_s'] = time.monotonic() - started
    (scratch / 'results.json').write_text(json.dumps(results, indent=2, default=str))
    report_path.write_text(report.render(results) + '\n\n'
                           + '## 8. Plain rclpy clients with the default QoS (issue 20)\n\n'
                           + default_clients.render(results['default_clients']) + '\n\n'
                           + '## 9. The ontologies robots really use (issue 28)\n\n'
                           + real_shapes.__doc__.split('\n\n', 2)[2].strip() + '\n\n'
                           + real_shapes.render(results['real_shapes']) + '\n'
                           + ('\n## 10. Scenes by demonstration (issue 32)\n\n'
                              + scenes.render(results['scenes']) if 'scenes' in results else '')
                           + ("\n\n## 11. KnowRob's upper ontology, SOMA and DUL (issue 36)\n\n"
                              + soma.render(results['soma']) if 'soma' in results else '')
                           + '\n\n## 12. Explanations: time to the first justification (issue 31)\n\n'
                           + explanations.render(results['explanations']) + '\n')
    stage(f'report written to {report_path} (raw figures: {scratch / "results.json"})')
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--scale', choices=sorted(SCALES),
                        default=os.environ.get('ARMOR_BENCH_SCALE', 'full'))
    parser.add_argument('--report', type=pathlib.Path, default=REPO / 'bench' / 'REPORT.md')
    options = parser.parse_args()
    wrong = wrong_in(run(options.scale, options.report))
    if wrong:
        sys.exit('wrong answers behind these figures:\n  ' + '\n  '.join(wrong))
    print('every checked answer was right', file=sys.stderr)


if __name__ == '__main__':
    main()
