# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Benchmark 11 (issue 36), KnowRob's upper ontology: SOMA-HOME (on DUL) under a kitchen ABox.

    python bench/soma.py [--smoke] [--sizes 100,1000] [--reasoners HERMIT] [--no-whole]

A KnowRob user's ontology (tests/integration/soma_kitchen.py): containers, tableware and agents
over SOMA-HOME's whole import closure, tableware inside containers through SOMA:isInsideOf
(transitive, only its inverse used by the defined class ContainerWithCup), at 100 / 1,000 /
10,000 individuals. Per reasoner and size, on a node of its own:
- LOAD (the schema's classification runs in the background over an upper ontology: LOAD's
  answer says so, and the time it took is read from the overview once done);
- the first answer: QUERY IND CLASS ContainerWithCup;
- the cycle, as ARMOR clients run it: a cup moves to an empty container (REPLACE OBJECTPROP IND
  isInsideOf), REASON, QUERY IND CLASS ContainerWithCup; every answer is checked against the
  generator's, which follows containment transitively;
- at the smallest size, the same moves on the reasoner on the whole ontology (the reasoner named
  by its factory class, which ARMOR uses as it is), each answer compared with the modular one.
"""

import argparse
import json
import os
import pathlib
import statistics
import sys
import time
from typing import Dict, List, Optional

from harness import REPO, BenchNode, CoreSnapshot, Deadline

sys.path.insert(0, str(REPO / 'tests' / 'integration'))
from soma_kitchen import DEFINED_CLASS, SOMA, KitchenABox  # noqa: E402
from web_browser import free_port  # noqa: E402

REASONERS = ('HERMIT', 'PELLET')
WHOLE = {'HERMIT': 'org.semanticweb.HermiT.ReasonerFactory',
         'PELLET': 'openllet.owlapi.OpenlletReasonerFactory'}
SIZES = {'full': [100, 1000, 10000], 'smoke': [40]}
CYCLES = {'full': 20, 'smoke': 2}
WHOLE_CYCLES = {'full': 3, 'smoke': 1}
# Per reasoner and size: LOAD, first answer and cycles share it.
BUDGET_S = {'full': {100: 900, 1000: 900, 10000: 1800}, 'smoke': {40: 600}}
# The whole-ontology reasoner (ARMOR before issue 36) runs on the same moves within this: on
# SOMA it can take longer than any robot waits, and then its row says where it stopped.
WHOLE_BUDGET_S = {'full': 600, 'smoke': 300}
INSIDE = f'<{SOMA}isInsideOf>'


class OutOfBudget(Exception):
    """A step did not answer within what was left of the budget."""


def _names(answer) -> List[str]:
    return sorted(iri.rstrip('>').rsplit('#', 1)[-1] for iri in answer.queried_objects)


def _core_cpu_s(node: BenchNode) -> float:
    """CPU seconds the node's knowledge core has used (every thread, the background
    classification's too): on a machine shared with other work, the figure wall time hides."""
    if not hasattr(node, 'core_pid'):
        node.core_pid = node.process.core_pid()
    stat = pathlib.Path(f'/proc/{node.core_pid}/stat').read_text()
    fields = stat.rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')


class _Session:
    """One reference on one node, its directives timed against one budget."""

    def __init__(self, node: BenchNode, reference: str, budget_s: float):
        self.node = node
        self.reference = reference
        self.deadline = Deadline(budget_s)

    def call(self, words: str, *args):
        if self.deadline.expired():
            raise OutOfBudget(f'{words}: the {self.deadline.seconds:.0f} s budget ran out')
        from armor_client.errors import ArmorServiceCallError
        start = time.perf_counter()
        try:
            answer = self.node.call(self.reference, words, *args,
                                    timeout_s=max(self.deadline.left(), 1.0))
        except ArmorServiceCallError as error:
            raise OutOfBudget(f'{words}: no answer within the {self.deadline.seconds:.0f} s '
                              'budget') from error
        if not answer.success:
            raise RuntimeError(f'{words} failed: {answer.exit_code} {answer.error_description}')
        return time.perf_counter() - start, answer


def _classification(port: int, reference: str, wait_s: float) -> dict:
    """The web view's word on the classification, once it is done (or when wait_s ran out)."""
    import urllib.request
    end = time.monotonic() + wait_s
    while True:
        with urllib.request.urlopen(f'http://127.0.0.1:{port}/api/references/{reference}',
                                    timeout=60) as reply:
            summary = json.loads(reply.read())
        text = summary.get('classification', '')
        if 'background' not in text or time.monotonic() > end:
            return {'text': text, 'ms': summary.get('classification_ms'),
                    'reasoning': summary.get('reasoning', '')}
        time.sleep(2)


def run_modular(node: BenchNode, port: int, path: pathlib.Path, individuals: int, reasoner: str,
                cycles: int, budget_s: float) -> dict:
    """LOAD, first answer and the cycle of one reasoner on one size; moves as played."""
    kitchen = KitchenABox(individuals)
    session = _Session(node, 'kitchen', budget_s)
    result = {'load_s': None, 'first_s': None, 'cycles': [], 'wrong': 0, 'moves': [],
              'answers': [], 'note': '', 'statement': ''}
    try:
        cpu = _core_cpu_s(node)
        result['load_s'], loaded = session.call('LOAD FILE', str(path), '', 'false', reasoner,
                                                'false')
        result['load_cpu_s'] = _core_cpu_s(node) - cpu
        result['statement'] = loaded.error_description
        result['first_s'], first = session.call('QUERY IND CLASS', DEFINED_CLASS)
        result['wrong'] += _names(first) != kitchen.containers_with_cup()
        for _ in range(min(cycles, kitchen.moves_left)):
            move = kitchen.next_move()
            cpu = _core_cpu_s(node)
            change, _ = session.call('REPLACE OBJECTPROP IND', INSIDE, move.item, move.new,
                                     move.old)
            reason, _ = session.call('REASON')
            query, answer = session.call('QUERY IND CLASS', DEFINED_CLASS)
            result['cycles'].append({'change': change, 'reason': reason, 'query': query})
            result.setdefault('cycle_cpu_s', []).append(_core_cpu_s(node) - cpu)
            result['moves'].append([move.item, move.new, move.old])
            result['answers'].append(_names(answer))
            result['wrong'] += _names(answer) != kitchen.containers_with_cup()
        result['classification'] = _classification(port, 'kitchen', session.deadline.left())
        result['memory'] = node.memory()
        result['load_average'] = os.getloadavg()[0]
    except (OutOfBudget, RuntimeError) as error:
        result['note'] = str(error)
    return result


def run_whole(node: BenchNode, path: pathlib.Path, factory: str, moves: List[list],
              answers: List[List[str]], budget_s: float) -> dict:
    """The modular run's moves on the reasoner on the whole ontology: how many answers agree."""
    session = _Session(node, 'whole', budget_s)
    result = {'load_s': None, 'cycles': [], 'agree': 0, 'checked': 0, 'note': ''}
    try:
        result['load_s'], _ = session.call('LOAD FILE', str(path), '', 'false', factory, 'false')
        for move, modular in zip(moves, answers):
            change, _ = session.call('REPLACE OBJECTPROP IND', INSIDE, *move)
            reason, _ = session.call('REASON')
            query, answer = session.call('QUERY IND CLASS', DEFINED_CLASS)
            result['cycles'].append({'change': change, 'reason': reason, 'query': query})
            result['checked'] += 1
            result['agree'] += _names(answer) == modular
    except (OutOfBudget, RuntimeError) as error:
        result['note'] = str(error)
    return result


def measure(scratch: pathlib.Path, snapshot: CoreSnapshot, scale: str,
            sizes: Optional[List[int]] = None, reasoners=REASONERS,
            whole: bool = True) -> Dict[int, dict]:
    """results[size][reasoner] = {'modular': ..., 'whole': ... (smallest size only)}."""
    sizes = sizes or SIZES[scale]
    folder = scratch / 'soma'
    results: Dict[int, dict] = {}
    for individuals in sizes:
        path = KitchenABox(individuals).write(folder, f'kitchen{individuals}')
        budget = BUDGET_S[scale].get(individuals, max(BUDGET_S[scale].values()))
        results[individuals] = {}
        for reasoner in reasoners:
            port = free_port()
            # The reasoner time limit is the budget: on SOMA a busy machine's first reasoning can
            # pass the default 30 s, and the figure is then what this measures, not a 211.
            node = BenchNode(scratch, snapshot, parameters={
                'web_port': str(port), 'reasoner_timeout_ms': str(budget * 1000)})
            try:
                modular = run_modular(node, port, path, individuals, reasoner, CYCLES[scale],
                                      budget)
            finally:
                node.stop()
            entry = {'modular': modular}
            # The whole-ontology reasoner's LOAD is measured even when the modular run made no
            # move (its figure is the "before"); its answers are compared on the moves made.
            if whole and individuals == min(sizes):
                node = BenchNode(scratch, snapshot, parameters={
                    'reasoner_timeout_ms': str(WHOLE_BUDGET_S[scale] * 1000)})
                try:
                    entry['whole'] = run_whole(node, path, WHOLE[reasoner],
                                               modular['moves'][:WHOLE_CYCLES[scale]],
                                               modular['answers'], WHOLE_BUDGET_S[scale])
                finally:
                    node.stop()
            results[individuals][reasoner] = entry
    return results


def _p50_ms(cycles: List[dict], part: str = '') -> Optional[float]:
    if not cycles:
        return None
    return statistics.median(sum(c.values()) if not part else c[part] for c in cycles) * 1000


def _median_ms(seconds: Optional[List[float]]) -> Optional[float]:
    return statistics.median(seconds) * 1000 if seconds else None


def _ms(value: Optional[float]) -> str:
    return '-' if value is None else (f'{value:,.0f} ms' if value >= 10 else f'{value:.1f} ms')


def _s(value: Optional[float]) -> str:
    return '-' if value is None else f'{value:,.1f} s'


def render(results: Dict[int, dict]) -> str:
    """The section's Markdown: one row per size and reasoner, the whole-ontology check beside."""
    lines = ['| individuals | reasoner | LOAD | classification (background) | first answer '
             '| cycles | cycle p50 | change / REASON / query p50 | cycle max '
             '| core CPU: LOAD, cycle p50 | answers right '
             '| whole-ontology reasoner on the same moves | note |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for individuals, by_reasoner in results.items():
        for reasoner, entry in by_reasoner.items():
            run = entry['modular']
            cycles = run['cycles']
            whole = entry.get('whole')
            if whole is None:
                check = '-'
            elif whole['checked']:
                check = (f'{whole["agree"]} of {whole["checked"]} answers equal; its cycle p50 '
                         f'{_ms(_p50_ms(whole["cycles"]))}, LOAD {_s(whole["load_s"])}')
            else:
                check = f'no answer: {whole["note"][:90]}'
            classified = run.get('classification', {})
            lines.append('| ' + ' | '.join([
                f'{individuals:,}', reasoner, _s(run['load_s']),
                (f'{classified["ms"] / 1000:,.0f} s' if classified.get('ms')
                 else classified.get('text', '-')[:60] or '-'),
                _s(run['first_s']), str(len(cycles)), _ms(_p50_ms(cycles)),
                ' / '.join(_ms(_p50_ms(cycles, part)) for part in ('change', 'reason', 'query')),
                _ms(max(sum(c.values()) for c in cycles) * 1000 if cycles else None),
                f'{_s(run.get("load_cpu_s"))}, '
                f'{_ms(_median_ms(run.get("cycle_cpu_s")))}',
                ('yes' if not run['wrong'] else f'**{run["wrong"]} wrong**') if cycles else '-',
                check, (f'load average {run["load_average"]:.0f}; ' if run.get('load_average')
                        else '') + run['note'][:140].replace('|', '/')]) + ' |')
    return '\n'.join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--smoke', action='store_true')
    parser.add_argument('--sizes', default='')
    parser.add_argument('--reasoners', default=','.join(REASONERS))
    parser.add_argument('--json', type=pathlib.Path)
    parser.add_argument('--no-whole', action='store_true',
                        help='leave out the whole-ontology reasoner (the "before" figures)')
    options = parser.parse_args()
    import tempfile
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-soma-'))
    scale = 'smoke' if options.smoke else 'full'
    sizes = [int(s) for s in options.sizes.split(',') if s] or None
    results = measure(scratch, CoreSnapshot(scratch), scale, sizes,
                      tuple(r for r in options.reasoners.split(',') if r), not options.no_whole)
    if options.json:
        options.json.write_text(json.dumps(results, indent=2, default=str))
    print(render(results))


if __name__ == '__main__':
    main()
