# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Many client processes on three references at once: nothing lost, nothing doubled, mounts exclusive.

    python tests/integration/load.py --clients 8 --operations 2000

Each client process owns its individuals and one counter per reference, so the final ontology
is known whatever the interleaving: every acknowledged ADD present, every counter holding
exactly the value its last acknowledged REPLACE wrote. Mount sessions and acknowledged
manipulations carry timestamps of the machine's monotonic clock, shared by all processes: no
other client's manipulation may be acknowledged entirely inside a mount session.
"""

import argparse
import json
import os
import pathlib
import random
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

from conftest import NS, ONTOLOGIES, start_node  # noqa: E402

REFERENCES = ['load0', 'load1', 'load2']
NAMESPACE = '/load'

MOUNTED = 102


def client(index: int, operations: int, out: pathlib.Path) -> None:
    """One client process: mixed directives, everything it was told recorded in `out`."""
    from armor_client import ArmorTransport, directive
    rng = random.Random(index)
    me = f'client{index}'
    armor = ArmorTransport(namespace=NAMESPACE, service_wait_s=120.0)
    added = {r: [] for r in REFERENCES}
    counters = {r: 0 for r in REFERENCES}
    acknowledged, sessions, latencies, errors = [], [], [], []

    def send(reference, command, primary='', secondary='', *args):
        started = time.monotonic()
        answer = armor.call(directive(me, reference, command, primary, secondary, args),
                            timeout_s=300)
        ended = time.monotonic()
        latencies.append(ended - started)
        manipulation = command in ('ADD', 'REPLACE', 'REASON')
        if answer.success and manipulation:
            acknowledged.append([reference, started, ended])
        if not answer.success and answer.exit_code not in (MOUNTED, 203):
            errors.append([command, primary, secondary, answer.exit_code, answer.error_description])
        return answer

    for reference in REFERENCES:
        while not send(reference, 'ADD', 'DATAPROP', 'IND', 'visitedAt', f'cnt{index}', 'LONG',
                       '0').success:
            time.sleep(0.01)
    for k in range(operations):
        reference = rng.choice(REFERENCES)
        roll = rng.random()
        if roll < 0.30:
            name = f'c{index}_{k}'
            if send(reference, 'ADD', 'IND', 'CLASS', name, 'Robot').success:
                added[reference].append(name)
        elif roll < 0.50:
            value = counters[reference]
            if send(reference, 'REPLACE', 'DATAPROP', 'IND', 'visitedAt', f'cnt{index}', 'LONG',
                    str(value + 1), str(value)).success:
                counters[reference] = value + 1
        elif roll < 0.85:
            send(reference, 'QUERY', 'IND', 'CLASS', 'Robot')
        elif roll < 0.90:
            send(reference, 'REASON')
        else:
            if not send(reference, 'MOUNT').success:
                continue
            mounted_at = time.monotonic()
            for j in range(3):
                name = f'm{index}_{k}_{j}'
                if send(reference, 'ADD', 'IND', 'CLASS', name, 'Robot').success:
                    added[reference].append(name)
            released_at = time.monotonic()
            send(reference, 'UNMOUNT')
            sessions.append([reference, mounted_at, released_at])
    armor.close()
    out.write_text(json.dumps({'client': me, 'added': added, 'counters': counters,
                               'acknowledged': acknowledged, 'sessions': sessions,
                               'latencies': latencies, 'errors': errors}))


def run(scratch: pathlib.Path, clients: int, operations: int) -> dict:
    """Start a node and the clients; audit the result. Returns the figures and the violations."""
    from armor_client import ArmorTransport, directive
    node = start_node(scratch, namespace=NAMESPACE)
    armor = ArmorTransport(namespace=NAMESPACE, service_wait_s=120.0)
    try:
        for reference in REFERENCES:
            assert armor.call(directive('coordinator', reference, 'LOAD', 'FILE', '', [
                str(ONTOLOGIES / 'robotics.owl'), '', 'false', 'HERMIT', 'true']),
                timeout_s=300).success
        started = time.monotonic()
        processes = [subprocess.Popen([sys.executable, __file__, '--as-client', str(i),
                                       '--operations', str(operations),
                                       '--out', str(scratch / f'client{i}.json')])
                     for i in range(clients)]
        deadlocked = False
        for process in processes:
            try:
                process.wait(timeout=max(600, operations))
            except subprocess.TimeoutExpired:
                deadlocked = True
                process.kill()
        elapsed = time.monotonic() - started
        results = [json.loads((scratch / f'client{i}.json').read_text())
                   for i in range(clients) if (scratch / f'client{i}.json').exists()]
        return audit(armor, results, elapsed, deadlocked, node)
    finally:
        armor.close()
        node.stop()


def audit(armor, results, elapsed, deadlocked, node) -> dict:
    from armor_client import directive

    def ask(reference, *words_and_args):
        command, primary, secondary, *args = words_and_args
        return armor.call(directive('auditor', reference, command, primary, secondary, args),
                          timeout_s=300).queried_objects

    lost = doubled = wrong_counters = exclusivity = 0
    for reference in REFERENCES:
        # A buffered reasoner still answers what it inferred before the last changes, next to
        # the asserted values (the contract's union); REASON makes both agree.
        assert armor.call(directive('auditor', reference, 'REASON', '', '', []),
                          timeout_s=300).success
        present = set(ask(reference, 'QUERY', 'IND', 'CLASS', 'Robot'))
        expected = {f'<{NS}robot1>'} | {f'<{NS}{name}>' for r in results
                                        for name in r['added'][reference]}
        lost += len(expected - present)
        doubled += len(present - expected)
        for r in results:
            values = ask(reference, 'QUERY', 'DATAPROP', 'IND', 'visitedAt',
                         r['client'].replace('client', 'cnt'))
            if values != [f'"{r["counters"][reference]}"^^xsd:long']:
                wrong_counters += 1
        for holder in results:
            for ref, mounted_at, released_at in holder['sessions']:
                if ref != reference:
                    continue
                for other in results:
                    if other is holder:
                        continue
                    exclusivity += sum(1 for r, s, e in other['acknowledged']
                                       if r == reference and s > mounted_at and e < released_at)
    latencies = sorted(x for r in results for x in r['latencies'])
    return {
        'clients_finished': len(results), 'deadlocked': deadlocked,
        'node_alive': node.process.poll() is None, 'directives': len(latencies),
        'seconds': elapsed, 'throughput': len(latencies) / elapsed,
        'p50_ms': 1000 * statistics.median(latencies),
        'p99_ms': 1000 * latencies[int(0.99 * (len(latencies) - 1))],
        'lost': lost, 'doubled': doubled, 'wrong_counters': wrong_counters,
        'exclusivity_violations': exclusivity,
        'mount_sessions': sum(len(r['sessions']) for r in results),
        'unexpected_errors': [e for r in results for e in r['errors']][:10],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--clients', type=int, default=8)
    parser.add_argument('--operations', type=int, default=2000)
    parser.add_argument('--as-client', type=int, default=None, help=argparse.SUPPRESS)
    parser.add_argument('--out', type=pathlib.Path, default=None, help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.as_client is not None:
        client(options.as_client, options.operations, options.out)
        return 0
    os.environ.setdefault('ROS_DOMAIN_ID', str(random.randint(1, 100)))
    report = run(pathlib.Path(tempfile.mkdtemp(prefix='armor-load-')), options.clients,
                 options.operations)
    print(json.dumps(report, indent=2))
    clean = (not report['deadlocked'] and report['node_alive'] and report['lost'] == 0
             and report['doubled'] == 0 and report['wrong_counters'] == 0
             and report['exclusivity_violations'] == 0 and not report['unexpected_errors'])
    return 0 if clean else 1


if __name__ == '__main__':
    sys.exit(main())
