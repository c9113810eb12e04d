# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Benchmark of the live web view (issue 13): how fast a change reaches an open page, what a
page holds after a long run of changes, and what open pages cost the robot's ROS clients.

    python bench/web_view.py [--changes 100] [--soak-minutes 10] [--pages 5]
                             [--phase-seconds 30] [--individuals N] [--parts latency,cost,soak]
                             [--json FILE]

Starts an ARMOR node (robotics.owl preloaded as "robotics", PELLET, the web view on a free
port) and drives Debian's chromium with Playwright, side by side in one run. With
--individuals N every part runs on a reference of N individuals instead (robotics' TBox and
individuals, N/5 rooms and 4N/5 robots in them, PELLET): the heavy case, where each of the
pages' refreshes reads hundreds of individuals under the reference's lock.

1. Change -> page latency, measured in the browser: a page shows the individuals table with
   bedroom; a ROS client moves alice into bedroom and out again, `--changes` times. A
   MutationObserver in the page stamps (performance.timeOrigin + now, the same wall clock as the
   client's) the moment bedroom's row shows it is, or no longer is, an OccupiedRoom (an
   inference). Latency = stamp - the client's send time (and - its acknowledgement).
2. Soak: two pages (graph and individuals) stay open for `--soak-minutes` while a client moves
   alice every 100 ms. Every minute the changes pause for one probe change whose latency is
   measured as in 1 (a page that fell behind shows it late); JS heap (after a forced GC), DOM
   nodes and event listeners of each page, and the node's resident memory, are sampled.
3. Cost of open pages: a ROS client's round trips (QUERY CLASS IND alice true, her most
   specific types, and REPLACE OBJECTPROP IND moving her) with no page open and with `--pages`
   pages open, each switching tab every pass (every tab's fetches) and reloading every fifth
   pass, and all refreshing what they show after each of the client's moves; four phases of
   `--phase-seconds` alternate off/on/off/on so that the machine's noise falls on both.
   Ratio = p50 with pages / p50 without. The pages' browser runs on the same 2 cores.
"""

import argparse
import json
import pathlib
import statistics
import sys
import tempfile
import threading
import time
from typing import Dict, List

from answers import checked
from harness import REPO, BenchNode, CoreSnapshot, latency_summary, peak_rss_mib

sys.path.insert(0, str(REPO / 'tests' / 'integration'))
import web_browser  # noqa: E402  (the tests' browser set-up)
from web_browser import free_port, launch  # noqa: E402

# The reference every part reads and changes: robotics, or the large one of --individuals.
REFERENCE = 'robotics'

ROOMS = ('bedroom', 'corridor1')
TABS = ('graph', 'classes', 'individuals', 'recent')
# Stamps the moment the bedroom row shows the wanted state (see the module docstring).
OBSERVER = """
() => {
  window.__bench = {want: null, seenAt: null};
  const check = () => {
    const cell = document.querySelector('tr[data-name="bedroom"] td.types');
    if (!cell || window.__bench.want === null || window.__bench.seenAt !== null) return;
    if (cell.textContent.includes('OccupiedRoom') === window.__bench.want) {
      window.__bench.seenAt = performance.timeOrigin + performance.now();
    }
  };
  new MutationObserver(check).observe(document.querySelector('#individuals-table tbody'),
    {childList: true, subtree: true, characterData: true});
}
"""


def percentiles_ms(samples: List[float]) -> Dict[str, float]:
    ordered = sorted(samples)
    pick = lambda q: ordered[min(len(ordered) - 1, int(q * len(ordered)))]  # noqa: E731
    return {'n': len(samples), 'p50_ms': statistics.median(samples), 'p90_ms': pick(0.9),
            'p99_ms': pick(0.99), 'max_ms': ordered[-1]}


class Mover:
    """Moves alice between bedroom and the corridor over ROS; knows where she is."""

    def __init__(self, node: BenchNode):
        self.node = node
        self.inside = False
        self.lock = threading.Lock()

    def move(self) -> float:
        """One move; answers the wall-clock ms at which it was sent."""
        with self.lock:
            new, old = (ROOMS[1], ROOMS[0]) if self.inside else (ROOMS[0], ROOMS[1])
            sent = time.time() * 1000
            answer = self.node.call(REFERENCE, 'REPLACE OBJECTPROP IND', 'isIn', 'alice', new,
                                    old)
            if not answer.success:
                raise RuntimeError(f'move failed: {answer.error_description}')
            self.inside = not self.inside
            return sent


def open_individuals(context, url: str):
    page = context.new_page()
    page.goto(url + f'#/{REFERENCE}/individuals')
    # bedroom is on the first page of robotics; a large reference is searched for it.
    page.fill('#individual-search', 'bedroom')
    page.wait_for_selector('tr[data-name="bedroom"] td.types')
    page.wait_for_function(
        '() => document.querySelectorAll("#individuals-table tbody tr").length === 1')
    page.evaluate(OBSERVER)
    return page


def probe(page, mover: Mover) -> Dict[str, float]:
    """One move and when the page showed it: ms after it was sent and after it was answered."""
    page.evaluate('(want) => { window.__bench.want = want; window.__bench.seenAt = null; }',
                  not mover.inside)
    sent = mover.move()
    answered = time.time() * 1000
    page.wait_for_function('() => window.__bench.seenAt !== null', timeout=30_000, polling=20)
    seen = page.evaluate('window.__bench.seenAt')
    return {'from_send_ms': seen - sent, 'from_ack_ms': seen - answered}


def measure_latency(browser, url: str, mover: Mover, changes: int) -> Dict[str, Dict]:
    context = browser.new_context()
    page = open_individuals(context, url)
    samples = []
    for _ in range(changes):
        samples.append(probe(page, mover))
        time.sleep(0.2)
    context.close()
    return {'from_send': percentiles_ms([s['from_send_ms'] for s in samples]),
            'from_ack': percentiles_ms([s['from_ack_ms'] for s in samples])}


def page_metrics(cdp) -> Dict[str, float]:
    cdp.send('HeapProfiler.collectGarbage')
    metrics = {m['name']: m['value'] for m in cdp.send('Performance.getMetrics')['metrics']}
    return {'js_heap_mib': metrics['JSHeapUsedSize'] / (1 << 20), 'dom_nodes': metrics['Nodes'],
            'listeners': metrics['JSEventListeners']}


def soak(browser, url: str, node: BenchNode, mover: Mover, minutes: float) -> Dict:
    context = browser.new_context(viewport={'width': 1400, 'height': 900})
    graph = context.new_page()
    graph.goto(url + f'#/{REFERENCE}/graph')
    graph.wait_for_selector('#graph-note:has-text("links")')
    table = open_individuals(context, url)
    sessions = {'graph': context.new_cdp_session(graph),
                'individuals': context.new_cdp_session(table)}
    for cdp in sessions.values():
        cdp.send('Performance.enable')
    moving = threading.Event()
    stop = threading.Event()
    moves = [0]

    def keep_moving():
        while not stop.is_set():
            if moving.is_set():
                mover.move()
                moves[0] += 1
            time.sleep(0.1)

    mover_thread = threading.Thread(target=keep_moving, daemon=True)
    mover_thread.start()
    moving.set()
    samples = []
    start = time.monotonic()
    end = start + minutes * 60
    while True:
        time.sleep(max(0.0, min(60.0, end - time.monotonic())))
        moving.clear()
        time.sleep(0.3)  # the move in flight lands
        sample = {'minute': round((time.monotonic() - start) / 60, 1), 'moves': moves[0],
                  'probe': probe(table, mover),
                  'pages': {name: page_metrics(cdp) for name, cdp in sessions.items()},
                  'node_rss_mib': peak_rss_mib(node.process.process.pid)['rss_mib']}
        samples.append(sample)
        print(f'  soak {sample["minute"]:5.1f} min: {sample["moves"]} moves, probe '
              f'{sample["probe"]["from_ack_ms"]:.0f} ms, heap '
              + ', '.join(f'{n} {m["js_heap_mib"]:.2f} MiB/{m["dom_nodes"]:.0f} nodes'
                          for n, m in sample['pages'].items())
              + f', node {sample["node_rss_mib"]:.1f} MiB', flush=True)
        if time.monotonic() >= end:
            break
        moving.set()
    stop.set()
    mover_thread.join()
    context.close()
    return {'minutes': minutes, 'moves': moves[0], 'samples': samples}


def round_trips(node: BenchNode, mover: Mover, stop: threading.Event) -> Dict[str, List[float]]:
    times: Dict[str, List[float]] = {'QUERY': [], 'REPLACE': []}
    while not stop.is_set():
        begun = time.perf_counter()
        # Alice's most specific types: a reasoner's answer, a few names long.
        answer = node.call(REFERENCE, 'QUERY CLASS IND', 'alice', 'true')
        times['QUERY'].append(time.perf_counter() - begun)
        checked(answer, "alice's most specific types", ['Person'])
        begun = time.perf_counter()
        mover.move()
        times['REPLACE'].append(time.perf_counter() - begun)
    return times


def cpu_seconds(pid: int) -> float:
    fields = pathlib.Path(f'/proc/{pid}/stat').read_text().rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / 100.0


def cost_of_pages(browser, url: str, node: BenchNode, mover: Mover, pages: int,
                  phase_s: float) -> Dict:
    phases: Dict[str, Dict[str, List[float]]] = {
        'without': {'QUERY': [], 'REPLACE': []}, 'with': {'QUERY': [], 'REPLACE': []}}
    node_cpu = {'without': 0.0, 'with': 0.0}
    passes = [0]
    for phase in ('without', 'with', 'without', 'with'):
        context = None
        open_pages = []
        if phase == 'with':
            context = browser.new_context(viewport={'width': 1400, 'height': 900})
            for _ in range(pages):
                page = context.new_page()
                page.goto(url + f'#/{REFERENCE}/graph')
                open_pages.append(page)
            # A large reference's first graph can take long on a loaded machine.
            open_pages[-1].wait_for_selector('#graph-note:has-text("links")', timeout=180_000)
        result: Dict[str, Dict[str, List[float]]] = {}
        stop = threading.Event()
        failed: List[Exception] = []

        def client():
            try:
                result.update(times=round_trips(node, mover, stop))
            except Exception as error:  # a wrong answer: the phase's figures mean nothing
                failed.append(error)
        worker = threading.Thread(target=client)
        cpu_before = cpu_seconds(node.process.process.pid)
        worker.start()
        turn = 0
        end = time.monotonic() + phase_s
        while time.monotonic() < end:
            if not open_pages:
                time.sleep(0.2)
                continue
            # Every page shows another tab (its fetches); every fifth pass, reloads.
            for page in open_pages:
                if turn % 5 == 4:
                    page.reload(timeout=180_000)
                else:
                    page.click(f'.tabs button[data-tab="{TABS[turn % len(TABS)]}"]')
            open_pages[-1].wait_for_timeout(200)
            turn += 1
            passes[0] += 1
        stop.set()
        worker.join()
        if failed:
            raise failed[0]
        node_cpu[phase] += cpu_seconds(node.process.process.pid) - cpu_before
        for command, samples in result['times'].items():
            phases[phase][command].extend(samples)
        if context is not None:
            context.close()
    summary = {}
    for command in ('QUERY', 'REPLACE'):
        without = latency_summary(phases['without'][command])
        with_pages = latency_summary(phases['with'][command])
        summary[command] = {'without': without, 'with': with_pages,
                            'p50_ratio': with_pages['p50_ms'] / without['p50_ms']}
    summary['page_passes'] = passes[0]
    summary['node_cpu_s'] = node_cpu
    return summary


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--changes', type=int, default=100)
    parser.add_argument('--soak-minutes', type=float, default=10.0)
    parser.add_argument('--pages', type=int, default=5)
    parser.add_argument('--phase-seconds', type=float, default=30.0,
                        help='length of each of the 4 phases of the cost measurement')
    parser.add_argument('--individuals', type=int, default=0,
                        help='run on a reference of this many individuals (0: robotics)')
    parser.add_argument('--parts', default='latency,cost,soak')
    parser.add_argument('--browser-nice', type=int, default=0,
                        help='run the browser at this niceness (19: it gets only the CPU the '
                             'robot leaves; the cost left is the node\'s and the core\'s)')
    parser.add_argument('--json', type=pathlib.Path)
    options = parser.parse_args()
    parts = set(options.parts.split(','))
    global REFERENCE
    from playwright.sync_api import sync_playwright
    with tempfile.TemporaryDirectory(prefix='armor-bench-web-') as scratch_dir:
        scratch = pathlib.Path(scratch_dir)
        port = free_port()
        node = BenchNode(scratch, CoreSnapshot(scratch), {'web_port': str(port)},
                         preload_robotics=True)
        url = f'http://127.0.0.1:{port}/'
        if options.individuals:
            from ontology_factory import write_abox
            rooms = max(1, options.individuals // 5)
            abox = write_abox(scratch / 'large.owl', rooms, options.individuals - rooms)
            answer = node.call('large', 'LOAD FILE', str(abox), '', 'false', 'PELLET', 'false',
                               timeout_s=600)
            if not answer.success:
                raise RuntimeError(f'loading {abox} failed: {answer.error_description}')
            REFERENCE = 'large'
        mover = Mover(node)
        results: Dict = {}
        try:
            with sync_playwright() as playwright:
                executable = web_browser.CHROMIUM
                if options.browser_nice:
                    executable = str(scratch / 'nice-chromium')
                    pathlib.Path(executable).write_text(
                        f'#!/bin/sh\nexec nice -n {options.browser_nice} '
                        f'{web_browser.CHROMIUM} "$@"\n')
                    pathlib.Path(executable).chmod(0o755)
                browser = launch(playwright, '--enable-precise-memory-info', executable=executable)
                results['browser_nice'] = options.browser_nice
                results['reference'] = REFERENCE
                if 'latency' in parts:
                    print(f'1. change -> page latency over {options.changes} changes', flush=True)
                    results['latency'] = measure_latency(browser, url, mover, options.changes)
                if 'cost' in parts:
                    print(f'3. ROS round trips without and with {options.pages} open pages',
                          flush=True)
                    results['cost'] = cost_of_pages(browser, url, node, mover, options.pages,
                                                    options.phase_seconds)
                if 'soak' in parts:
                    print(f'2. soak: {options.soak_minutes} min of a move every 100 ms',
                          flush=True)
                    results['soak'] = soak(browser, url, node, mover, options.soak_minutes)
                browser.close()
        finally:
            node.stop()
    report(results)
    if options.json:
        options.json.write_text(json.dumps(results, indent=2))
    return 0


def report(results: Dict) -> None:
    print(f'\n(reference: {results["reference"]}, browser niceness {results["browser_nice"]})')
    if 'latency' in results:
        report_latency(results['latency'])
    if 'cost' in results:
        report_cost(results['cost'])
    if 'soak' in results:
        report_soak(results['soak'])


def report_latency(latency: Dict) -> None:
    print('== change -> page (in the browser), bedroom becoming / ceasing to be an OccupiedRoom')
    for origin in ('from_send', 'from_ack'):
        figures = latency[origin]
        print(f'  {origin:9}: p50 {figures["p50_ms"]:.0f} ms, p90 {figures["p90_ms"]:.0f} ms, '
              f'p99 {figures["p99_ms"]:.0f} ms, max {figures["max_ms"]:.0f} ms '
              f'({figures["n"]} changes)')


def report_cost(cost: Dict) -> None:
    print('== ROS round trip p50 without / with open pages')
    for command in ('QUERY', 'REPLACE'):
        entry = cost[command]
        print(f'  {command:7}: {entry["without"]["p50_ms"]:.2f} ms / {entry["with"]["p50_ms"]:.2f}'
              f' ms = x{entry["p50_ratio"]:.3f} (p99 {entry["without"]["p99_ms"]:.1f} / '
              f'{entry["with"]["p99_ms"]:.1f} ms; {entry["with"]["calls"]} calls each)')
    print(f'  node CPU: {cost["node_cpu_s"]["without"]:.1f} s without, '
          f'{cost["node_cpu_s"]["with"]:.1f} s with pages ({cost["page_passes"]} page passes)')


def report_soak(soak_run: Dict) -> None:
    first, last = soak_run['samples'][0], soak_run['samples'][-1]
    print(f'== soak: {soak_run["minutes"]} min, {soak_run["moves"]} moves')
    for name in first['pages']:
        before, after = first['pages'][name], last['pages'][name]
        print(f"  {name:11}: JS heap {before['js_heap_mib']:.2f} -> "
              f"{after['js_heap_mib']:.2f} MiB,"
              f' DOM nodes {before["dom_nodes"]:.0f} -> {after["dom_nodes"]:.0f}, listeners '
              f'{before["listeners"]:.0f} -> {after["listeners"]:.0f}')
    probes = [s['probe']['from_ack_ms'] for s in soak_run['samples']]
    print(f'  probe latency after each minute: first {probes[0]:.0f} ms, last '
          f'{probes[-1]:.0f} ms, max {max(probes):.0f} ms')
    print(f'  node resident memory: {first["node_rss_mib"]:.1f} -> {last["node_rss_mib"]:.1f} MiB')


if __name__ == '__main__':
    sys.exit(main())
