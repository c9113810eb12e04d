# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""What one client's flood costs the others (issue 27 item 9), each flood bounded in time.

    python bench/client_floods.py [--seconds 40] [--baseline DIR] [--floods references ...]

Starts a node (robotics preloaded), then, one after the other:
- subscriptions: one client subscribes to the same query again and again (reading each
  answer topic, so none ends), up to --subscriptions or --seconds;
- references: one client CREATEs references in a loop, up to --seconds;
- changes: 200 changes of 40 KB each, then 4 threads ask GET REF CHANGES from revision 0 for
  --seconds.
For each: what the flooder got (how many made, refused with which code), the node's and the
core's resident memory before and after, and another client's latency (a REPLACE on robotics
for the subscriptions, a QUERY otherwise; p50/p90 of 40 calls) before and during or after.
`--baseline DIR` runs the same first against another checkout (DIR holds armor_service/,
armor_contract/, armor_client/ and install/armor_core/armor-core.jar, e.g. /work/main).
"""

import argparse
import os
import pathlib
import statistics
import sys
import tempfile
import threading
import time

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / 'bench'))
from harness import percentile, peak_rss_mib  # noqa: E402

ROBOTICS = REPO / 'ontologies' / 'robotics.owl'


def start(scratch: pathlib.Path, source: pathlib.Path, namespace: str):
    """A node of the given checkout (its Python packages and its installed core jar)."""
    from armor_service.node_harness import ArmorNodeProcess
    env = dict(os.environ)
    if source != REPO:
        packages = ':'.join(str(source / p) for p in ('armor_service', 'armor_contract',
                                                        'armor_client'))
        env['PYTHONPATH'] = f'{packages}:{env.get("PYTHONPATH", "")}'
        env['ARMOR_CORE_JAR'] = str(source / 'install' / 'armor_core' / 'armor-core.jar')
    return ArmorNodeProcess(scratch / f'node{namespace.replace("/", "_")}.log', [
        '-p', f'preload_file:={ROBOTICS}', '-p', 'preload_reference:=robotics',
        '-p', f'allowed_dirs:=["{scratch}", "{REPO / "ontologies"}"]',
        '-p', f'state_dir:={scratch / ("state" + namespace.replace("/", "_"))}',
        '-r', f'__ns:={namespace}'], cwd=scratch, env=env)


class Flood:
    def __init__(self, namespace: str, node):
        from armor_client import ArmorTransport
        self.transport = ArmorTransport(namespace=namespace, service_wait_s=180)
        self.node = node
        self.namespace = namespace
        assert self.call('', 'GET ALL REFS', timeout_s=240).success

    def call(self, reference, words, *args, client='bench', timeout_s=120):
        from armor_client import directive
        command, primary, secondary = (words.split() + ['', '', ''])[:3]
        return self.transport.call(directive(client, reference, command, primary, secondary,
                                             args), timeout_s=timeout_s)

    def memory(self) -> str:
        node = peak_rss_mib(self.node.process.pid)['rss_mib']
        core = peak_rss_mib(self.node.core_pid())['rss_mib']
        return f'node {node:.0f} MiB, core {core:.0f} MiB'

    def latency(self, change: bool = False, calls: int = 40) -> str:
        samples = []
        places = ('bedroom', 'kitchen')
        for i in range(calls):
            started = time.monotonic()
            if change:
                self.call('robotics', 'REPLACE OBJECTPROP IND', 'isIn', 'alice',
                          places[i % 2], places[(i + 1) % 2], client='neighbour')
            else:
                self.call('robotics', 'QUERY IND CLASS', 'OccupiedRoom', client='neighbour')
            samples.append(time.monotonic() - started)
        return (f'p50 {statistics.median(samples) * 1000:.0f} ms, '
                f'p90 {percentile(samples, 0.9) * 1000:.0f} ms')


def subscriptions(flood: Flood, limit: int, seconds: float) -> None:
    from armor_client import directive
    from armor_contract.events import ANSWER_QOS, SUBSCRIBE_SERVICE
    from armor_msgs.msg import ArmorAnswer
    from armor_msgs.srv import ArmorSubscribe
    node = flood.transport.node
    client = node.create_client(ArmorSubscribe, f'{flood.namespace}/{SUBSCRIBE_SERVICE}')
    client.wait_for_service(timeout_sec=60)
    print(f'  before: {flood.memory()}; neighbour REPLACE {flood.latency(change=True)}')
    made, codes, readers = 0, {}, []
    deadline = time.monotonic() + seconds
    while made + sum(codes.values()) < limit and time.monotonic() < deadline:
        done = threading.Event()
        future = client.call_async(ArmorSubscribe.Request(armor_request=directive(
            'flooder', 'robotics', 'QUERY', 'IND', 'CLASS', ['OccupiedRoom'])))
        future.add_done_callback(lambda _: done.set())
        done.wait(60)
        answer = future.result()
        if answer.success:
            made += 1
            readers.append(node.create_subscription(ArmorAnswer, answer.topic, lambda m: None,
                                                    ANSWER_QOS))
        else:
            codes[answer.exit_code] = codes.get(answer.exit_code, 0) + 1
    print(f'  flooder: {made} subscriptions made, refused {codes or "none"}')
    print(f'  after:  {flood.memory()}; neighbour REPLACE {flood.latency(change=True)}')
    for reader in readers:
        node.destroy_subscription(reader)


def references(flood: Flood, seconds: float) -> None:
    print(f'  before: {flood.memory()}; neighbour QUERY {flood.latency()}')
    made, codes = [], {}
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        name = f'flood_{len(made) + sum(codes.values())}'
        answer = flood.call(name, 'CREATE', '', 'false', 'PELLET', 'false', client='flooder')
        if answer.success:
            made.append(name)
        else:
            codes[answer.exit_code] = codes.get(answer.exit_code, 0) + 1
    print(f'  flooder: {len(made)} references made in {seconds:.0f} s, refused '
          f'{codes or "none"}')
    print(f'  after:  {flood.memory()}; neighbour QUERY {flood.latency()}')
    for name in made:
        flood.call(name, 'DROP', client='flooder')


def changes(flood: Flood, seconds: float) -> None:
    flood.call('history', 'LOAD FILE', str(ROBOTICS), '', 'false', 'PELLET', 'false')
    for i in range(200):
        flood.call('history', 'ADD DATAPROP IND', 'note', 'robot1', 'STRING',
                   f'{i}' + 'x' * 40_000)
    print(f'  before: {flood.memory()}; neighbour QUERY {flood.latency()}')
    answers, answered_bytes = [0], [0]
    stop = time.monotonic() + seconds

    def ask():
        while time.monotonic() < stop:
            answer = flood.call('', 'GET REF CHANGES', 'history', '0', client='flooder')
            answers[0] += 1
            answered_bytes[0] += sum(len(text) for text in answer.queried_objects)
    threads = [threading.Thread(target=ask) for _ in range(4)]
    for thread in threads:
        thread.start()
    during = flood.latency()
    for thread in threads:
        thread.join()
    per_answer = answered_bytes[0] / max(1, answers[0]) / (1 << 20)
    print(f'  flooder: {answers[0]} answers in {seconds:.0f} s, {per_answer:.2f} MiB each')
    print(f'  during: neighbour QUERY {during}; after: {flood.memory()}')


def run(source: pathlib.Path, label: str, args) -> None:
    print(f'== {label} ({source})')
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-floods-'))
    namespace = f'/floods_{os.getpid()}_{label}'
    node = start(scratch, source, namespace)
    try:
        flood = Flood(namespace, node)
        if 'subscriptions' in args.floods:
            print('subscriptions of one client')
            subscriptions(flood, args.subscriptions, args.seconds)
        if 'references' in args.floods:
            print('references of one client (CREATE in a loop)')
            references(flood, args.seconds)
        if 'changes' in args.floods:
            print('GET REF CHANGES from revision 0, 4 threads')
            changes(flood, args.seconds)
        flood.transport.close()
    finally:
        node.stop()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--seconds', type=float, default=40.0)
    parser.add_argument('--subscriptions', type=int, default=300)
    parser.add_argument('--baseline', type=pathlib.Path)
    parser.add_argument('--floods', nargs='+', default=['subscriptions', 'references', 'changes'],
                        choices=['subscriptions', 'references', 'changes'])
    args = parser.parse_args()
    os.environ.setdefault('ROS_DOMAIN_ID', str(150 + os.getpid() % 80))
    if args.baseline:
        run(args.baseline, 'baseline', args)
    run(REPO, 'this', args)


if __name__ == '__main__':
    main()
