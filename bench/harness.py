# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""What every benchmark of the suite shares: an isolated node, a frozen core, statistics, budgets.

Isolation matters on this machine: other engineers run nodes, load tests and core rebuilds at
the same time. So a benchmark node lives in a namespace of its own (a DDS domain shared by
accident cannot reach it), keeps its journal in a scratch directory, and runs a copy of the
core taken when the suite starts (a rebuild of core/target cannot change it mid-run).
"""

import dataclasses
import json
import os
import pathlib
import random
import shutil
import statistics
import subprocess
import sys
import time
from typing import Dict, List, Optional, Sequence

REPO = pathlib.Path(__file__).resolve().parents[1]
CORE_TARGET = REPO / 'core' / 'target'
HARNESS_CLASS = 'io.github.armor.core.bench.InProcessBatchBench'
# Main classes of the in-process benchmarks, compiled with the core's tests.
HARNESS_CLASSES = (HARNESS_CLASS, 'io.github.armor.core.sparql.LubmBench')

# Chosen before rclpy starts in this process; children inherit it.
os.environ.setdefault('ROS_DOMAIN_ID', str(random.SystemRandom().randint(1, 100)))


def percentile(samples: Sequence[float], fraction: float) -> float:
    ordered = sorted(samples)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


def latency_summary(samples: Sequence[float]) -> Dict[str, float]:
    """p50/p99/mean in milliseconds and the sample count."""
    return {'calls': len(samples), 'p50_ms': statistics.median(samples) * 1000,
            'p99_ms': percentile(samples, 0.99) * 1000, 'mean_ms': statistics.fmean(samples) * 1000}


def stop_process(process: subprocess.Popen, grace_s: float = 10) -> None:
    """Ends a helper process: SIGTERM, then SIGKILL if it is still there after grace_s.

    An rclpy process does not always exit on SIGTERM; a benchmark waiting for it forever hung
    the suite (the smoke run in make test was stopped by its 600 s limit).
    """
    process.terminate()
    try:
        process.wait(timeout=grace_s)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


def script_scale_and_scratch(description: str):
    """What a benchmark run as a script starts from: its --smoke flag read, a scratch folder.

    Returns:
        (the Scale, smoke or full; a new temporary folder).
    """
    import argparse
    import tempfile
    parser = argparse.ArgumentParser(description=description.strip().splitlines()[0])
    parser.add_argument('--smoke', action='store_true', help='tiny sizes, a few seconds')
    options = parser.parse_args()
    return (SCALES['smoke' if options.smoke else 'full'],
            pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-')))


class Deadline:
    """A wall-clock budget: how much is left, and whether it ran out."""

    def __init__(self, seconds: float):
        self.seconds = seconds
        self._end = time.monotonic() + seconds

    def left(self) -> float:
        return max(0.0, self._end - time.monotonic())

    def expired(self) -> bool:
        return self.left() <= 0.0


class CoreSnapshot:
    """A private copy of the core jar, its libraries and the in-process harness classes."""

    def __init__(self, scratch: pathlib.Path):
        self.root = scratch / 'core'
        if not (CORE_TARGET / 'armor-core.jar').is_file():
            raise RuntimeError('core/target/armor-core.jar is missing: run make setup')
        classes = CORE_TARGET / 'test-classes'
        compiled = [classes / (name.replace('.', '/') + '.class') for name in HARNESS_CLASSES]
        sources = [REPO / 'core' / 'src' / 'test' / 'java' / (name.replace('.', '/') + '.java')
                   for name in HARNESS_CLASSES]
        if any(not c.is_file() or c.stat().st_mtime < s.stat().st_mtime
               for c, s in zip(compiled, sources)):
            # make bench compiles them; this covers a suite started by hand or by the smoke test.
            # -B: no colour codes; stdout to stderr: benchmarks print their JSON on stdout.
            subprocess.run(['mvn', '-B', '-q', '-o', '-f', str(REPO / 'core' / 'pom.xml'),
                            'test-compile'], check=True, stdout=sys.stderr)
        self.root.mkdir(parents=True)
        shutil.copy2(CORE_TARGET / 'armor-core.jar', self.root)
        shutil.copytree(CORE_TARGET / 'lib', self.root / 'lib')
        for harness in compiled:
            package = harness.parent.relative_to(classes)
            shutil.copytree(harness.parent, self.root / 'test-classes' / package,
                            dirs_exist_ok=True)
        self.jar = self.root / 'armor-core.jar'

    @property
    def classpath(self) -> str:
        return f'{self.root / "test-classes"}:{self.jar}:{self.root / "lib"}/*'

    def library_versions(self) -> Dict[str, str]:
        """Versions of the OWL API and the reasoners, read from the jar names on the classpath."""
        wanted = {'owlapi-api': 'OWL API', 'org.semanticweb.hermit': 'HermiT',
                  'openllet-core': 'Openllet', 'jfact': 'JFact', 'elk-reasoner': 'ELK'}
        found = {}
        for jar in sorted((self.root / 'lib').glob('*.jar')):
            name, _, version = jar.stem.rpartition('-')
            if name in wanted:
                found[wanted[name]] = version
        return found


def peak_rss_mib(pid: int) -> Dict[str, float]:
    """Current (VmRSS) and peak (VmHWM) resident memory of a live process, in MiB."""
    fields = {}
    for line in pathlib.Path(f'/proc/{pid}/status').read_text().splitlines():
        key, _, value = line.partition(':')
        if key in ('VmRSS', 'VmHWM'):
            fields[key] = int(value.split()[0]) / 1024
    return {'rss_mib': fields['VmRSS'], 'peak_mib': fields['VmHWM']}


_namespaces = iter(range(1, 1 << 30))
# The test suite runs the benchmarks at smoke scale to prove they still run, not to measure: it
# sets this to JVM options (a JSON list) added to every benchmark node's jvm_options, its own or
# the node's default (tests/integration/conftest.py: C1 alone). Figures come from runs without.
EXTRA_JVM_OPTIONS_VARIABLE = 'ARMOR_BENCH_EXTRA_JVM_OPTIONS'


def _with_extra_jvm_options(parameters: Dict[str, str]) -> Dict[str, str]:
    extra = os.environ.get(EXTRA_JVM_OPTIONS_VARIABLE)
    if not extra:
        return parameters
    from armor_service.node_harness import default_jvm_options
    own = parameters.get('jvm_options')
    options = json.loads(own) if own else default_jvm_options()
    return {**parameters, 'jvm_options': json.dumps([*options, *json.loads(extra)])}


class BenchNode:
    """An ARMOR node for one benchmark, its transport, and the ids needed to measure it.

    Args:
        scratch: directory for the log, the journal and files the node may read.
        snapshot: the frozen core the node runs.
        parameters: extra node parameters, name -> value text.
        preload_robotics: load ontologies/robotics.owl as reference "robotics" at start.
    """

    def __init__(self, scratch: pathlib.Path, snapshot: CoreSnapshot,
                 parameters: Optional[Dict[str, str]] = None, preload_robotics: bool = False):
        from armor_client import ArmorTransport
        from armor_service.node_harness import ArmorNodeProcess
        self.namespace = f'/armor_bench_{os.getpid()}_{next(_namespaces)}'
        state = scratch / f'state{self.namespace.replace("/", "_")}'
        arguments = ['-r', f'__ns:={self.namespace}',
                     '-p', f'core_jar:={snapshot.jar}',
                     '-p', f'state_dir:={state}', '-p', 'restore_state:=false',
                     '-p', f'allowed_dirs:=["{scratch}", "{REPO / "ontologies"}"]']
        if preload_robotics:
            arguments += ['-p', f'preload_file:={REPO / "ontologies" / "robotics.owl"}',
                          '-p', 'preload_reference:=robotics']
        for name, value in _with_extra_jvm_options(parameters or {}).items():
            arguments += ['-p', f'{name}:={value}']
        self.process = ArmorNodeProcess(scratch / f'node{self.namespace.replace("/", "_")}.log',
                                        arguments, cwd=scratch)
        self.transport = ArmorTransport(namespace=self.namespace, service_wait_s=120)
        # The first call waits for discovery and the core; everything after is measurable.
        self.call('', 'GET ALL REFS', timeout_s=180)

    def call(self, reference: str, words: str, *args, timeout_s: Optional[float] = None):
        """call('ref', 'COMMAND PRIMARY SECONDARY', *args) -> ArmorDirectiveRes."""
        return self.transport.call(self.directive(reference, words, *args), timeout_s=timeout_s)

    @staticmethod
    def directive(reference: str, words: str, *args):
        from armor_client import directive
        command, primary, secondary = (words.split() + ['', '', ''])[:3]
        return directive('bench', reference, command, primary, secondary, args)

    def memory(self) -> Dict[str, Dict[str, float]]:
        """Resident memory of the node (Python) and its knowledge core (Java)."""
        return {'node': peak_rss_mib(self.process.process.pid),
                'core': peak_rss_mib(self.process.core_pid())}

    def stop(self) -> None:
        self.transport.close()
        self.process.stop()


@dataclasses.dataclass
class Scale:
    """How much the suite measures: `full` for the report, `smoke` to prove it still runs."""

    name: str
    latency_calls: int
    batch_lists: Dict[int, int]          # list size -> measured lists
    warmup_lists: int                    # per configuration and path, before measuring
    batch_budget_s: float                # per path and configuration
    abox_sizes: List[int]
    cycles: int                          # per reasoner and mode (2+: a room filled, then emptied)
    cycle_budget_s: Dict[int, float]     # per reasoner and mode, by ABox size
    owlready_budget_s: Dict[int, float]  # per owlready2 reasoner, by ABox size
    profile_s: float
    large_abox: int                      # benchmark 6: the cycle at this size ...
    large_budget_s: float                # ... per reasoner
    busy_abox: int                       # benchmark 6: reads while the reference reasons
    busy_idle_calls: int
    busy_writes: int
    busy_budget_s: float
    jvm_variants: int                    # benchmark 6: how many JVM option sets (first ones)


SCALES = {
    'full': Scale('full', latency_calls=2000, batch_lists={100: 30, 1000: 5}, warmup_lists=2,
                  batch_budget_s=45,
                  abox_sizes=[1000, 10000], cycles=20, cycle_budget_s={1000: 60, 10000: 120},
                  owlready_budget_s={1000: 90, 10000: 150}, profile_s=20,
                  large_abox=100000, large_budget_s=240, busy_abox=30000, busy_idle_calls=200,
                  busy_writes=4, busy_budget_s=240, jvm_variants=6),
    'smoke': Scale('smoke', latency_calls=20, batch_lists={10: 2, 100: 1}, warmup_lists=1,
                   batch_budget_s=5, abox_sizes=[20], cycles=2, cycle_budget_s={20: 15},
                   owlready_budget_s={20: 20}, profile_s=2, large_abox=200, large_budget_s=30,
                   busy_abox=100, busy_idle_calls=5, busy_writes=2, busy_budget_s=30,
                   jvm_variants=2),
}
