# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Benchmark 1, transport overhead: round trips through the service against a bare echo floor.

    python bench/query_latency.py [--calls 2000] [--commands QUERY,ADD]

Starts an ARMOR node (robotics.owl preloaded as "robotics", default settings: HermiT, reasoner
synchronised after every change, journal forced to disk) and two bare rclpy echo services
answering the same ArmorDirective message: one on rclpy.spin (the floor), one on the executor
the node uses. Calls from this process alternate between them, so every path sees the same
noise, and the ratios service/floor are the figures that matter on a shared machine.

QUERY is QUERY IND CLASS OccupiedRoom (an inferred answer). ADD is ADD IND CLASS of a new
individual each call, on the preloaded reference and on a second reference whose reasoner is
buffered (it only sees changes at REASON), which isolates the reasoner's share of an ADD.
Every answer is checked (bench/answers.py): the query's rooms, and after the ADDs (untimed)
that each reference's robots are exactly the ones added.
Run as a script it measures and prints; the suite (bench/suite.py) calls measure().
"""

import argparse
import json
import pathlib
import subprocess
import sys
import tempfile
import threading
import time

from answers import checked, ROBOTICS_OCCUPIED_ROOMS
from harness import REPO, BenchNode, CoreSnapshot, Deadline, latency_summary, stop_process

COMMANDS = ('QUERY', 'ADD')


class EchoFloor:
    """A bare echo service in its own process, and a client for it on the transport's node."""

    def __init__(self, node: BenchNode, executor: str):
        from armor_msgs.srv import ArmorDirective
        from echo_service import ECHO_SERVICE
        namespace = f'{node.namespace}_echo_{executor}'
        self.process = subprocess.Popen(
            [sys.executable, str(REPO / 'bench' / 'echo_service.py'), '--namespace', namespace,
             '--executor', executor])
        self.client = node.transport.node.create_client(ArmorDirective,
                                                        f'{namespace}/{ECHO_SERVICE}')
        if not self.client.wait_for_service(timeout_sec=60):
            raise RuntimeError(f'echo service ({executor}) did not come up')
        self.request = ArmorDirective.Request(
            armor_request=BenchNode.directive('robotics', 'QUERY IND CLASS', 'OccupiedRoom'))

    def call(self):
        """One round trip, waiting exactly as ArmorTransport does (executor thread, an Event)."""
        done = threading.Event()
        future = self.client.call_async(self.request)
        future.add_done_callback(lambda _: done.set())
        if not done.wait(30):
            raise RuntimeError('echo service did not answer within 30 s')
        return checked(future.result().armor_response, 'echo', ROBOTICS_OCCUPIED_ROOMS)

    def stop(self):
        stop_process(self.process)


class CoreAlone:
    """A core reached over its socket from a process with no ROS in it: the core's share.

    Same jar, same settings as the node's core (journal forced to disk), robotics.owl loaded
    as the node preloads it; what the service costs above this is the node's and ROS's part.
    It runs in a process of its own (core_alone), as a process with rclpy threads spinning
    makes every hand-off between threads dearer.
    """

    def __init__(self, scratch: pathlib.Path, jar: str):
        from armor_service.core_process import CoreProcess
        from armor_service.parameters import core_parameters
        settings = {p.name: p.default() if callable(p.default) else p.default
                    for p in core_parameters()}
        settings.update(allowed_dirs=[str(REPO / 'ontologies')],
                        state_dir=str(scratch / 'core-alone-state'), restore_state=False)
        self.core = CoreProcess(jar, settings)
        self.core.start()
        loaded = self.call('robotics', 'LOAD FILE', str(REPO / 'ontologies' / 'robotics.owl'),
                           '', 'false', '', 'false')  # as the node's preload
        if not loaded.success:
            raise RuntimeError(f'LOAD failed: {loaded.exit_code} {loaded.error_description}')

    def call(self, reference: str, words: str, *args):
        from armor_service import wire
        command, primary, secondary = (words.split() + ['', ''])[:3]
        directive = {'client_name': 'bench', 'reference_name': reference, 'command': command,
                     'primary_command_spec': primary, 'secondary_command_spec': secondary,
                     'args': list(args)}
        reply = self.core.request({'op': 'directive', 'directive': directive}, 120)
        return wire.response_from_json(reply['response'])

    def stop(self):
        self.core.stop()


# Each command's i-th directive (words, then arguments), the same on every path.
DIRECTIVES = {
    'QUERY': lambda i: ('QUERY IND CLASS', 'OccupiedRoom'),
    'ADD': lambda i: ('ADD IND CLASS', f'probe{i}', 'Robot'),
}
# What each command's answer holds: the occupied rooms; nothing.
ANSWERS = {'QUERY': ROBOTICS_OCCUPIED_ROOMS, 'ADD': ()}


def check_robots(call, reference: str, probes: int, what: str) -> None:
    """After `probes` ADDs of probe0.. on reference: its robots are robotics.owl's and those.

    call(reference, words, *args) answers a directive; a buffered reasoner is brought up to
    date first. Not timed: it checks that the measured ADDs did what they were sent for.
    """
    checked(call(reference, 'REASON'), f'{what}: REASON')
    checked(call(reference, 'QUERY IND CLASS', 'Robot'), f'{what}: robots after the ADDs',
            ['robot1', *(f'probe{i}' for i in range(probes))])


def core_alone(command: str, calls: int, scratch: pathlib.Path, jar: str) -> dict:
    """The same command's round trips to a core alone, measured in a new process."""
    finished = subprocess.run(
        [sys.executable, __file__, '--core-alone', command, '--calls', str(calls),
         '--scratch', str(scratch), '--jar', jar], capture_output=True, text=True, timeout=600)
    if finished.returncode != 0:
        raise RuntimeError(f'core alone ({command}) failed: {finished.stderr[-2000:]}')
    return json.loads(finished.stdout)


def _core_alone_worker(command: str, calls: int, scratch: pathlib.Path, jar: str) -> dict:
    core = CoreAlone(scratch, jar)
    try:
        samples = []
        warmup = min(50, calls)
        for i in range(-warmup, calls):
            directive = DIRECTIVES[command](i + warmup)
            seconds, answer = _timed(lambda: core.call('robotics', *directive))
            checked(answer, f'core alone, {command}', ANSWERS[command])
            if i >= 0:
                samples.append(seconds)
        if command == 'ADD':
            check_robots(core.call, 'robotics', warmup + calls, 'core alone')
        return latency_summary(samples)
    finally:
        core.stop()


def _timed(call):
    start = time.perf_counter()
    answer = call()
    return time.perf_counter() - start, answer


def measure(calls: int, scratch: pathlib.Path, snapshot: CoreSnapshot, commands=COMMANDS,
            budget_s: float = 300) -> dict:
    """Per command: latency summaries of the service paths and of both echo services.

    Each command stops at `calls` measured rounds or after `budget_s`, whichever comes first
    (an ADD gets slower as the ontology grows); the summaries say how many calls they cover.
    """
    node = BenchNode(scratch, snapshot, preload_robotics=True)
    floors = {}
    try:
        floors = {'floor': EchoFloor(node, 'single'), 'multi_echo': EchoFloor(node, 'multi')}
        loaded = node.call('robotics_buffered', 'LOAD FILE',
                           str(REPO / 'ontologies' / 'robotics.owl'), '', 'false', 'HERMIT',
                           'true', timeout_s=120)
        if not loaded.success:
            raise RuntimeError(f'LOAD failed: {loaded.exit_code} {loaded.error_description}')
        paths = {
            'QUERY': {'service': lambda i: node.call('robotics', *DIRECTIVES['QUERY'](i))},
            'ADD': {'service': lambda i: node.call('robotics', *DIRECTIVES['ADD'](i)),
                    'service_buffered_reasoner': lambda i: node.call(
                        'robotics_buffered', *DIRECTIVES['ADD'](i))},
        }
        results = {}
        for command in commands:
            samples = {name: [] for name in [*paths[command], *floors]}
            warmup = min(50, calls)
            deadline = Deadline(budget_s)
            sent = 0
            for i in range(-warmup, calls):
                if deadline.expired():
                    break
                sent += 1
                for name, call in paths[command].items():
                    seconds, answer = _timed(lambda: call(i + warmup))
                    checked(answer, f'{name}, {command}', ANSWERS[command])
                    if i >= 0:
                        samples[name].append(seconds)
                for name, floor in floors.items():
                    seconds, _ = _timed(floor.call)
                    if i >= 0:
                        samples[name].append(seconds)
            if command == 'ADD':
                for reference in ('robotics', 'robotics_buffered'):
                    check_robots(lambda *d: node.call(*d, timeout_s=120), reference, sent,
                                 f'service, {reference}')
            results[command] = {name: latency_summary(values) for name, values in samples.items()}
            results[command]['core_alone'] = core_alone(command, len(samples['service']),
                                                        scratch / f'alone-{command}',
                                                        snapshot.jar)
        return results
    finally:
        for floor in floors.values():
            floor.stop()
        node.stop()


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--calls', type=int, default=2000)
    parser.add_argument('--budget-s', type=float, default=300, help='per command')
    parser.add_argument('--commands', default='QUERY',
                        help='comma-separated subset of ' + ','.join(COMMANDS))
    parser.add_argument('--core-alone', metavar='COMMAND', help=argparse.SUPPRESS)
    parser.add_argument('--scratch', type=pathlib.Path, help=argparse.SUPPRESS)
    parser.add_argument('--jar', help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.core_alone:
        print(json.dumps(_core_alone_worker(options.core_alone, options.calls, options.scratch,
                                            options.jar)))
        return
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-'))
    results = measure(options.calls, scratch, CoreSnapshot(scratch),
                      commands=options.commands.split(','), budget_s=options.budget_s)
    print(json.dumps(results, indent=2))
    for command, paths in results.items():
        floor = paths['floor']['p50_ms']
        for name, figures in paths.items():
            print(f'{command:5} {name:26} p50 {figures["p50_ms"]:8.3f} ms  '
                  f'p99 {figures["p99_ms"]:8.3f} ms  p50/floor {figures["p50_ms"] / floor:5.2f}')


if __name__ == '__main__':
    main()
