# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""What oversized and runaway requests cost the service (issue 20 items 5 and 7).

    python bench/request_limits.py [--floods 20] [--baseline DIR]

Starts a node, then measures:
- the node's and the core's resident memory before and after a flood of 50 MB requests
  (ADD IND CLASS with a 50 MB individual name, then QUERY SPARQL with a 50 MB query text),
  and how long each was in answering;
- how long a SPARQL cross join (five unconstrained triple patterns) takes to be answered,
  counting rows (SELECT *) and counting only (COUNT), with the node's default limits.

`--baseline DIR` runs the same measurements first against another checkout (DIR holds its
armor_service/ and a built core/target/armor-core.jar, e.g. the branch point extracted with
`git archive`), so both columns come from one run on the same machine.
"""

import argparse
import os
import pathlib
import subprocess
import sys
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / 'tests' / 'integration'))
MiB = 1 << 20
CROSS_JOIN_ROWS = 'SELECT * WHERE { ?a ?b ?c . ?d ?e ?f . ?g ?h ?i . ?j ?k ?l . ?m ?n ?o }'
CROSS_JOIN_COUNT = ('SELECT (COUNT(*) AS ?n) WHERE { ?a ?b ?c . ?d ?e ?f . ?g ?h ?i . ?j ?k ?l . '
                    '?m ?n2 ?o }')
ANSWER_WAIT_S = 150.0


def rss_mib(pid: int) -> float:
    for line in pathlib.Path(f'/proc/{pid}/status').read_text().splitlines():
        if line.startswith('VmRSS:'):
            return int(line.split()[1]) / 1024
    return float('nan')


def start(scratch: pathlib.Path, source: pathlib.Path, namespace: str):
    """A node of the given checkout (its armor_service package and its core jar)."""
    env = dict(os.environ)
    env['PYTHONPATH'] = f'{source}/armor_service:{env.get("PYTHONPATH", "")}'
    jar = source / 'core' / 'target' / 'armor-core.jar'
    if source == REPO:
        jar = pathlib.Path(env['ARMOR_CORE_JAR'])
    log = open(scratch / 'node.log', 'w')
    process = subprocess.Popen(
        [sys.executable, '-m', 'armor_client.cli', 'serve', '--ros-args',
         '-p', f'preload_file:={REPO / "ontologies" / "robotics.owl"}',
         '-p', 'preload_reference:=robotics', '-p', f'allowed_dirs:=["{scratch}", "{REPO / "ontologies"}"]',
         '-p', f'state_dir:={scratch / "state"}', '-p', f'core_jar:={jar}',
         '-r', f'__ns:={namespace}'], stdout=log, stderr=subprocess.STDOUT, env=env)
    return process


def core_pid(node_pid: int) -> int:
    for stat in pathlib.Path('/proc').glob('[0-9]*/stat'):
        try:
            name, rest = stat.read_text().split('(', 1)[1].rsplit(')', 1)
        except (OSError, ValueError):
            continue
        if name == 'java' and int(rest.split()[1]) == node_pid:
            return int(stat.parent.name)
    raise RuntimeError('no core process')


def timed(armor, request, timeout_s=ANSWER_WAIT_S):
    from armor_client.errors import ArmorCallTimeout
    started = time.monotonic()
    try:
        response = armor.call(request, timeout_s=timeout_s)
    except ArmorCallTimeout:
        return None, time.monotonic() - started
    return response, time.monotonic() - started


def measure(source: pathlib.Path, floods: int, label: str) -> dict:
    from armor_client import ArmorTransport, directive
    namespace = f'/limits_{label}_{os.getpid()}'
    with tempfile.TemporaryDirectory(prefix='armor-limits-') as scratch_dir:
        scratch = pathlib.Path(scratch_dir)
        node = start(scratch, source, namespace)
        armor = ArmorTransport(namespace=namespace, service_wait_s=120.0)
        try:
            try:
                armor.call(directive('bench', '', 'GET', 'ALL', 'REFS'), timeout_s=180)
            except Exception:
                print((scratch / 'node.log').read_text()[-3000:], file=sys.stderr)
                raise
            time.sleep(2)
            figures = {'node MiB before': rss_mib(node.pid),
                       'core MiB before': rss_mib(core_pid(node.pid))}
            answers = []
            big = 'x' * (50 * MiB)
            for i in range(floods):
                name_flood = directive('bench', 'robotics', 'ADD', 'IND', 'CLASS',
                                       [big[:-len(str(i))] + str(i), 'Robot'])
                response, seconds = timed(armor, name_flood)
                answers.append((response.exit_code if response else 'none', seconds))
            query_flood = directive('bench', 'robotics', 'QUERY', 'SPARQL', '',
                                    ['SELECT * WHERE { ?s ?p ?o } #' + big])
            response, seconds = timed(armor, query_flood)
            answers.append((response.exit_code if response else 'none', seconds))
            del big, name_flood, query_flood
            time.sleep(5)
            figures['node MiB after flood'] = rss_mib(node.pid)
            figures['core MiB after flood'] = rss_mib(core_pid(node.pid))
            figures['flood exit codes'] = sorted({code for code, _ in answers}, key=str)
            figures['flood answer s (max)'] = max(s for _, s in answers)
            figures['state dir MiB'] = sum(p.stat().st_size for p in (scratch / 'state').rglob('*')
                                           if p.is_file()) / MiB
            for label_, query in (('cross join rows', CROSS_JOIN_ROWS),
                                  ('cross join COUNT', CROSS_JOIN_COUNT)):
                response, seconds = timed(armor, directive('bench', 'robotics', 'QUERY', 'SPARQL',
                                                           '', [query]))
                figures[f'{label_}: answered after s'] = (
                    f'{seconds:.1f}' if response else f'> {ANSWER_WAIT_S:.0f} (no answer)')
                figures[f'{label_}: answer'] = (
                    f'{response.exit_code} timeout={response.timeout} '
                    f'rows={len(response.queried_objects)}' if response else '-')
            return figures
        finally:
            armor.close()
            node.terminate()
            try:
                node.wait(timeout=30)
            except subprocess.TimeoutExpired:
                node.kill()
                node.wait()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--floods', type=int, default=20, help='50 MB requests in the flood')
    parser.add_argument('--baseline', type=pathlib.Path, help='an earlier checkout to compare')
    options = parser.parse_args()
    columns = {}
    if options.baseline:
        columns['baseline'] = measure(options.baseline.resolve(), options.floods, 'baseline')
    columns['this checkout'] = measure(REPO, options.floods, 'current')
    keys = list(next(iter(columns.values())).keys())
    print(f'| figure | {" | ".join(columns)} |')
    print('|---|' + '---|' * len(columns))
    for key in keys:
        cells = []
        for figures in columns.values():
            value = figures.get(key)
            cells.append(f'{value:,.0f}' if isinstance(value, float) and 'MiB' in key
                         else f'{value:.1f}' if isinstance(value, float) else str(value))
        print(f'| {key} | {" | ".join(cells)} |')


if __name__ == '__main__':
    main()
