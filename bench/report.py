# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Turns the suite's results into bench/REPORT.md: a summary, then one table per benchmark."""

import math
import statistics
from typing import Dict, List, Optional, Tuple

from harness import percentile
from reasoning_cycle import MODES, ROBOT_MODE, WHOLE_ONTOLOGY, summarise

TRANSPORT_TARGET = 1.5   # service p50 / echo floor p50, at most
BATCH_TARGET = 0.5       # service rate / in-process rate, at least


def _ms(value: Optional[float]) -> str:
    return '-' if value is None else f'{value:.2f} ms' if value < 100 else f'{value:.0f} ms'


def _seconds(value: Optional[float]) -> str:
    return '-' if value is None else f'{value:.2f} s'


def _table(header: List[str], rows: List[List[str]]) -> str:
    lines = ['| ' + ' | '.join(header) + ' |', '|' + '---|' * len(header)]
    lines += ['| ' + ' | '.join(str(cell) for cell in row) + ' |' for row in rows]
    return '\n'.join(lines)


def _met(ok: bool) -> str:
    return 'yes' if ok else '**no**'


def recommend(reasoning: dict) -> Tuple[Optional[Tuple[str, str]], str]:
    """The reasoner and mode with the fastest correct cycle over every ABox size.

    Candidates finished every size with every answer right; they are ranked by the geometric
    mean of their cycle p50 over the sizes, so one size's noise does not decide alone.
    Returns ((reasoner, mode), why) or (None, why) when nothing qualifies.
    """
    sizes = sorted(reasoning)
    candidates = []
    for reasoner, modes in reasoning[sizes[-1]]['service'].items():
        if reasoner in WHOLE_ONTOLOGY:  # the reference of before, not a setting to choose
            continue
        for mode in modes:
            runs = [reasoning[size]['service'][reasoner][mode] for size in sizes]
            figures = [summarise(run) for run in runs]
            if all(run['finished'] and f['cycles'] and f['correct'] for run, f in zip(runs,
                                                                                    figures)):
                mean = math.prod(f['cycle_p50_ms'] for f in figures) ** (1 / len(figures))
                candidates.append((mean, reasoner, mode, [f['cycle_p50_ms'] for f in figures]))
    if not candidates:
        return None, 'no reasoner finished the cycle with right answers at every size'
    candidates.sort()

    def describe(candidate):
        return (f'{candidate[1]} ({candidate[2]}) ' + ' / '.join(
            f'{p50:.0f}' for p50 in candidate[3]) + ' ms')

    sizes_text = ' / '.join(f'{size:,}' for size in sizes)
    why = (f'fastest correct cycle over {sizes_text} individuals (cycle p50, ranked by their '
           f'geometric mean): {describe(candidates[0])}'
           + (f'; next: {describe(candidates[1])}' if len(candidates) > 1 else ''))
    return candidates[0][1:3], why


def _best_owlready(sides: dict) -> Optional[Tuple[float, str, bool]]:
    """owlready2's fastest cycle (p50 ms, reasoner, every answer right), right ones first.

    owlready2 keeps an inferred type after the fact behind it is gone, so it answers wrongly
    once a room empties; its time is still what a Python robot would pay, and says so.
    """
    runs = [(not summarise(r)['correct'], summarise(r)['cycle_p50_ms'], name)
            for name, r in sides['owlready2'].items() if summarise(r)['cycles']]
    if not runs:
        return None
    wrong, p50_ms, name = min(runs)
    return p50_ms, name, not wrong


def _memory(modes: dict) -> Dict[str, float]:
    """Peak resident memory over a reasoner's runs: node, core, and both."""
    node = max(r['memory']['node']['peak_mib'] for r in modes.values() if 'memory' in r)
    core = max(r['memory']['core']['peak_mib'] for r in modes.values() if 'memory' in r)
    return {'node': node, 'core': core, 'total': node + core}


def _round_trip_shares(transport: dict) -> list:
    """Where a round trip goes, from benchmark 1's paths of the same run (when it has them)."""
    if 'core_alone' not in transport.get('QUERY', {}):
        return []
    parts = []
    for command, target in (('QUERY', ISSUE15_QUERY_TARGET), ('ADD', ISSUE15_ADD_TARGET)):
        paths = transport[command]
        floor, executor = paths['floor']['p50_ms'], paths['multi_echo']['p50_ms']
        core, service = paths['core_alone']['p50_ms'], paths['service']['p50_ms']
        room = target * floor - executor
        verdict = ('more than the core alone takes' if room >= core
                   else 'less than the core alone takes')
        parts.append(f'{command}: {_ms(service)} = the echo on the node\'s executor '
                     f'{_ms(executor)} ({executor / floor:.2f}x the floor) + the core alone '
                     f'{_ms(core)} (its socket from a process without ROS) + '
                     f'{_ms(max(service - executor - core, 0))} for the hand-off between the '
                     f'node\'s threads and the core; the target leaves {_ms(max(room, 0))} above '
                     f'the executor, {verdict}')
    return ['Where the round trips go (p50, benchmark 1 of this run): ' + '; '.join(parts)
            + '. The core runs as a process of its own so that the node survives a reasoner '
            'that hangs or runs out of memory; the hand-off is its price. The core\'s part of an '
            'ADD is in the single-ADD profile of section 5.', '']


def _slowest_part(transport: dict, batch: list, profiles: dict) -> str:
    """The benchmark furthest from its target, and where the core's time goes in it."""
    gaps = []  # (how many times worse than the target, what, profile of that workload)
    for command, profile in (('QUERY', None), ('ADD', 'Single ADDs')):
        ratio = transport[command]['service']['p50_ms'] / transport[command]['floor']['p50_ms']
        gaps.append((ratio / TRANSPORT_TARGET, f'{command} through the service at p50 takes '
                     f'{ratio:.1f}x the echo floor (target {TRANSPORT_TARGET}x)', profile))
    for row in batch:
        ratio = row['service']['per_s'] / row['armor_core']['per_s']
        gaps.append((BATCH_TARGET / ratio, f'lists of {row["configuration"]} run at {ratio:.0%} '
                     f'of the in-process rate (target {BATCH_TARGET:.0%})', 'Batch'))
    _, what, profile = max(gaps)
    text = what + '.'
    if profile == 'Single ADDs':
        text += (f' The same ADD on a reference with a buffered reasoner takes '
                 f'{transport["ADD"]["service_buffered_reasoner"]["p50_ms"]:.1f} ms against '
                 f'{transport["ADD"]["service"]["p50_ms"]:.1f} ms.')
    if profile:
        component, share = profiles[profile]['components'][0]
        text += (f' In the core\'s profile of that workload, "{component}" holds {share:.0%} of '
                 f'the samples (profile "{profile}").')
    else:
        text += (' The core answers it in a fraction of that (profile "Reasoning cycle": the '
                 'query is cheap); the rest is the node\'s Python hand-offs between the ROS '
                 'executor, the core socket and its reader thread.')
    return text


ISSUE15_CYCLE_TARGET_MS = {1000: 20, 10000: 50}
ISSUE15_LARGE_TARGET = (1000, 60)  # cycle p50 ms, load s
ISSUE15_ADD_TARGET = 2.0           # ADD p50 / echo floor p50, at most
ISSUE15_QUERY_TARGET = 1.3         # QUERY p50 / echo floor p50, at most
ISSUE15_BUSY_TARGET = 2.0          # busy QUERY p50 / idle QUERY p50, at most
ISSUE15_MEMORY_TARGET_MIB = 512


def _best_modular(runs: Dict[str, dict]) -> Optional[Tuple[str, dict]]:
    """The modular reasoner with the fastest all-right cycle, and its figures."""
    best = None
    for reasoner, run in runs.items():
        figures = summarise(run)
        if reasoner in WHOLE_ONTOLOGY or not run['finished'] or not figures['cycles'] \
                or not figures['correct']:
            continue
        if best is None or figures['cycle_p50_ms'] < best[1]['cycle_p50_ms']:
            best = (reasoner, {**figures, 'load_s': run['load_s']})
    return best


def _whole(run: Optional[dict]) -> str:
    if not run:
        return '-'
    figures = summarise(run)
    text = f'{_ms(figures["cycle_p50_ms"])}' if figures['cycles'] else 'no cycle'
    text += f', load {_seconds(run["load_s"])}' if run.get('load_s') is not None else ''
    return text + ('' if run['finished'] else f' ({run["note"]})')


DIRECTION_NAMES = {
    'rebuild:PELLET': 'Openllet on the whole ontology, rebuilt after a removal (before issue 15)',
    'rebuild:HERMIT': 'HermiT on the whole ontology, rebuilt after a removal',
    'openllet-incremental': 'Openllet incremental consistency and deletion, flushed',
    'flush:HERMIT': 'HermiT on the whole ontology, flushed (its incremental ABox update)',
    'flush:ELK': 'ELK, flushed (incremental; OWL 2 EL only)',
    'modular:PELLET': 'modular reasoner over Openllet (this issue)',
    'modular:HERMIT': 'modular reasoner over HermiT (this issue)',
    'Konclude': 'Konclude (external process), realising the file',
}


def _directions(directions: Dict[str, dict], individuals: int) -> List[str]:
    """The directions of issue 15 measured in-process on the same cycle, with what was kept."""
    right = {name: d for name, d in directions.items() if d.get('cycles') and d.get('wrong') == 0}
    modular = [d['cycle_p50_ms'] for name, d in right.items() if name.startswith('modular:')]
    best = min(modular) if modular else None
    rows = []
    for name, figures in directions.items():
        if not figures.get('cycles'):
            verdict = 'not kept: ' + figures.get('note', 'no result')
        elif figures.get('wrong'):
            verdict = f'not kept: {figures["wrong"]} wrong answers of {figures["cycles"]}'
        elif name.startswith('modular:'):
            verdict = ('kept: the service\'s reasoner for references brought up to date after '
                       'every change')
        elif best:
            verdict = (f'not kept: {figures["cycle_p50_ms"] / best:.0f}x the modular cycle'
                       + ('; answers from scratch each time' if name == 'Konclude' else ''))
        else:
            verdict = '-'
        rows.append([DIRECTION_NAMES.get(name, name), _ms(figures.get('first_ms')),
                     _ms(figures.get('cycle_p50_ms')), _ms(figures.get('cycle_max_ms')),
                     {0: 'yes'}.get(figures.get('wrong'),
                                    '**no**' if figures.get('cycles') else '-'),
                     verdict])
    return [f'### The directions of the issue, in-process ({individuals:,} individuals)', '',
            'The same cycle (an agent moves, then the instances of OccupiedRoom) in one JVM with '
            'no service around it (`ReasoningDirectionsBench`), one JVM per direction; "first" is '
            'loading the reasoner up to the first answer. Every answer is checked.', '',
            _table(['direction', 'first', 'cycle p50', 'cycle max', 'answers right', 'verdict'],
                   rows), '']


def _robot_speed(results: dict) -> List[str]:
    """Section 7: the table of issue 15, each figure beside its reference from the same run."""
    transport, reasoning = results['transport'], results['reasoning']
    speed = results['robot_speed']
    whole_label = next(iter(WHOLE_ONTOLOGY))
    rows = []
    for individuals, target in ISSUE15_CYCLE_TARGET_MS.items():
        if individuals not in reasoning:
            continue
        service = reasoning[individuals]['service']
        best = _best_modular({r: m[ROBOT_MODE] for r, m in service.items() if ROBOT_MODE in m})
        whole = service.get(whole_label, {}).get(ROBOT_MODE)
        rows.append([f'cycle p50, {individuals:,} individuals, complete answers',
                     f'{_ms(best[1]["cycle_p50_ms"])} ({best[0]})' if best else 'no correct run',
                     f'{whole_label}: {_whole(whole)}', f'<= {target} ms',
                     _met(bool(best) and best[1]['cycle_p50_ms'] <= target)])
    large = speed['large']
    best = _best_modular(large)
    cycle_target, load_target = ISSUE15_LARGE_TARGET
    rows.append([f'cycle p50, {speed["large_individuals"]:,} individuals',
                 f'{_ms(best[1]["cycle_p50_ms"])}, load {_seconds(best[1]["load_s"])} ({best[0]})'
                 if best else 'no correct run',
                 f'{whole_label}: {_whole(large.get(whole_label))}',
                 f'<= {cycle_target / 1000:.0f} s, load <= {load_target} s',
                 _met(bool(best) and best[1]['cycle_p50_ms'] <= cycle_target
                      and best[1]['load_s'] <= load_target)])
    for command, label, target in (('ADD', 'ADD round trip, default reference settings',
                                    ISSUE15_ADD_TARGET),
                                   ('QUERY', 'QUERY round trip', ISSUE15_QUERY_TARGET)):
        service, floor = transport[command]['service'], transport[command]['floor']
        ratio = service['p50_ms'] / floor['p50_ms']
        rows.append([label, f'{_ms(service["p50_ms"])} = {ratio:.2f}x echo',
                     f'echo floor {_ms(floor["p50_ms"])}', f'<= {target}x echo',
                     _met(ratio <= target)])
    busy = speed['busy']
    modular, whole = busy.get('PELLET', {}), busy.get(whole_label, {})
    if modular.get('busy_p50_ms'):
        ratio = modular['busy_p50_ms'] / modular['idle_p50_ms']
        rows.append(['QUERY on reference A while A reasons for seconds',
                     f'{_ms(modular["busy_p50_ms"])} = {ratio:.2f}x idle '
                     f'({_ms(modular["idle_p50_ms"])}); {modular["marked"]} of '
                     f'{modular["busy_reads"]} marked with a revision',
                     f'{whole_label}: ' + (f'{_ms(whole["busy_p50_ms"])} (waits for the reasoner)'
                                           if whole.get('busy_p50_ms') else 'no read overlapped'),
                     f'<= {ISSUE15_BUSY_TARGET}x idle, marked',
                     _met(ratio <= ISSUE15_BUSY_TARGET and modular['marked'] > 0
                          and modular['right'])])
    ten = max((n for n in reasoning if n <= 10000), default=None)
    if ten:
        service = reasoning[ten]['service']
        core = service.get('PELLET', {}).get(ROBOT_MODE, {}).get('memory', {}).get('core', {})
        before = service.get(whole_label, {}).get(ROBOT_MODE, {}).get('memory', {}).get('core', {})
        if core:
            rows.append([f'core memory, {ten:,} individuals (PELLET, the robot\'s mode)',
                         f'{core["peak_mib"]:,.0f} MiB',
                         f'{whole_label}: {before["peak_mib"]:,.0f} MiB' if before else '-',
                         f'<= {ISSUE15_MEMORY_TARGET_MIB} MiB',
                         _met(core['peak_mib'] <= ISSUE15_MEMORY_TARGET_MIB)])
    out = ['## 7. Reasoning at robot speed (issue 15)', '',
           'A reference with a complete reasoner (HermiT, Openllet, JFact) brought up to date '
           'after every change keeps every individual\'s types and, after an ABox change, reasons '
           'only on the modules the change reaches: the parts of the ABox tied together by '
           'properties the schema can propagate along (here an agent and its room; `connectedTo` '
           'ties nothing). Modules alike share one reasoning. Answers equal a fresh reasoner on '
           'the whole ontology (randomised equivalence test in `make test`). The reference rows '
           'run the same workload through the reasoner named by its factory class '
           f'(`{WHOLE_ONTOLOGY[whole_label]}`), which the service uses as it did before: on the '
           'whole ontology, rebuilt after every removal.', '',
           _table(['figure', 'this run', 'reference (same run)', 'target', 'met'], rows), '']
    out += _round_trip_shares(transport)
    out += [f'### The cycle at {speed["large_individuals"]:,} individuals', '',
            'Benchmark 3\'s cycle (non-buffered, no REASON), one node per reasoner.', '']
    rows = []
    for who, run in large.items():
        figures = summarise(run)
        rows.append([who, _seconds(run['load_s']), _seconds(run['first_s']), figures['cycles'],
                     _ms(figures['cycle_p50_ms']), _ms(figures['cycle_max_ms']),
                     {True: 'yes', False: '**no**', None: '-'}[figures['correct']],
                     f'{run["memory"]["core"]["peak_mib"]:,.0f} MiB' if 'memory' in run else '-',
                     run['note'] or 'finished'])
    out += [_table(['reasoner', 'load', 'first', 'cycles', 'cycle p50', 'cycle max',
                    'answers right', 'core peak', 'status'], rows), '']
    out += [f'### Reads while the reference reasons ({speed["busy_individuals"]:,} '
            'individuals)', '',
            'A second client asks QUERY IND CLASS OccupiedRoom, first on the idle reference, then '
            'over and over while the first client changes the schema (ADD / REMOVE CLASS CLASS '
            'Vehicle Agent), after which every module is reasoned on again (the whole ontology, '
            'for the reference). "busy" reads started while such a change was under way. A read '
            'answered from the last reasoned state says so in `error_description` with the '
            'revision it reflects.', '']
    rows = []
    for who, figures in busy.items():
        rows.append([who, _ms(figures.get('idle_p50_ms')), figures.get('busy_reads', 0),
                     _ms(figures.get('busy_p50_ms')), _ms(figures.get('busy_max_ms')),
                     figures.get('marked', 0), _seconds(figures.get('write_p50_s')),
                     {True: 'yes', False: '**no**', None: '-'}[figures.get('right')],
                     figures.get('note') or 'finished'])
    out += [_table(['reference', 'idle p50', 'busy reads', 'busy p50', 'busy max',
                    'marked with a revision', 'schema change p50', 'answers right', 'status'],
                   rows), '']
    if 'directions' in speed:
        out += _directions(speed['directions'], max(n for n in reasoning))
    out += [f'### JVM options and memory ({max(n for n in reasoning):,} individuals)', '',
            'The core\'s peak resident memory (VmHWM) with the ABox loaded and the robot\'s cycle '
            'run (PELLET, non-buffered, no REASON), one node per option set (each with '
            '`-XX:+ExitOnOutOfMemoryError`). Compact object headers need JDK 24 or later; the '
            'project\'s Java is 17, so that row runs the same core on the JDK 25 installed '
            'here.', '']
    rows = []
    for label, figures in speed['memory'].items():
        peak = figures.get('core_peak_mib')
        rows.append([f'`{label}`', f'{peak:,.0f} MiB' if peak else '-',
                     _seconds(figures.get('load_s')), _ms(figures.get('cycle_p50_ms')),
                     _ms(figures.get('cycle_max_ms')),
                     {True: 'yes', False: '**no**', None: '-'}[figures.get('correct')],
                     figures.get('note') or 'finished'])
    out += [_table(['JVM options', 'core peak', 'load', 'cycle p50', 'cycle max', 'answers right',
                    'status'], rows), '']
    return out


def render(results: dict) -> str:
    """The whole report as Markdown."""
    machine, versions = results['machine'], results['versions']
    transport, batch, reasoning = results['transport'], results['batch'], results['reasoning']
    profiles = results['profiles']
    choice, why = recommend(reasoning)
    out = [f'# ARMOR for ROS 2: benchmark report',
           '',
           f'Produced by `make bench` (scale `{results["scale"]}`) on {results["date"]}, '
           f'commit `{results["commit"]}`, in {results["duration_s"] / 60:.1f} minutes. '
           'Every figure and its reference come from the same run on the same machine; on this '
           'shared, noisy machine the ratios are the figures to compare.',
           '',
           '## Summary', '']

    rows = []
    for command, label in (('QUERY', 'QUERY IND CLASS'), ('ADD', 'ADD IND CLASS')):
        service, floor = transport[command]['service'], transport[command]['floor']
        ratio = service['p50_ms'] / floor['p50_ms']
        rows.append([f'1. transport, {label}, p50', _ms(service['p50_ms']),
                     f'echo floor {_ms(floor["p50_ms"])}', f'{ratio:.2f}x',
                     f'<= {TRANSPORT_TARGET}x', _met(ratio <= TRANSPORT_TARGET)])
    for row in batch:
        ratio = row['service']['per_s'] / row['armor_core']['per_s']
        rows.append([f'2. batch, {row["configuration"]}', f'{row["service"]["per_s"]:,.0f} /s',
                     f'in-process ArmorCore {row["armor_core"]["per_s"]:,.0f} /s',
                     f'{ratio:.0%}', f'>= {BATCH_TARGET:.0%}', _met(ratio >= BATCH_TARGET)])
    for individuals, sides in reasoning.items():
        best = _best_owlready(sides)
        if choice:
            figures = summarise(sides['service'][choice[0]][choice[1]])
            cycle = figures['cycle_p50_ms']
            reference = (f'owlready2 {best[1]} {_ms(best[0])}'
                         + ('' if best[2] else ' (answers wrong once a room empties)') if best
                         else 'owlready2: no cycle in its budget')
            speedup = f'{best[0] / cycle:.1f}x faster' if best and cycle else '-'
            rows.append([f'3. reasoning cycle, {individuals:,} individuals, {choice[0]} '
                         f'({choice[1]})', _ms(cycle), reference, speedup, 'faster than owlready2',
                         _met(bool(best and cycle and cycle < best[0])) if best else '-'])
    largest = max(reasoning)
    if choice:
        memory = _memory(reasoning[largest]['service'][choice[0]])
        rows.append([f'4. peak memory, {largest:,} individuals, {choice[0]}',
                     f'{memory["total"]:,.0f} MiB', f'node {memory["node"]:,.0f} + core '
                     f'{memory["core"]:,.0f} MiB', '-', '-', '-'])
    if 'lubm' in results:
        rows += _lubm_summary(results['lubm'])
    out += [_table(['benchmark', 'service', 'reference', 'ratio', 'target', 'met'], rows), '']
    out += [f'**Default for the robot\'s cycle:** '
            + (f'{choice[0]}, {choice[1]} ({why}).' if choice else why),
            '',
            f'**Slowest part of the service:** {_slowest_part(transport, batch, profiles)} '
            'See [Profile](#5-profile).', '']

    out += ['## Machine and versions', '',
            _table(['what', 'value'], [[k, v] for k, v in {**machine, **versions}.items()]), '']

    out += ['## 1. Transport overhead', '',
            f'Round trips from one process to the node in another, up to {transport["calls"]:,} '
            'calls per path (column "calls"; fewer only when a 300 s budget per command ran '
            'out), alternating between the paths so that each sees the same noise. The '
            'floor is a bare rclpy service (rclpy.spin) answering the same ArmorDirective '
            'message; "echo on the node\'s executor" is the same echo on a MultiThreadedExecutor '
            'with 16 threads and a reentrant group, as the node spins. ADD adds a new individual '
            'every call to the preloaded reference (HermiT, non-buffered: the reasoner is brought '
            'up to date after each change; journal forced to disk) and to a reference with a '
            'buffered reasoner. "The core alone" sends the same directives, as many, to a core '
            'of the same jar and settings over its socket from a process without ROS (after the '
            'interleaved paths): the core\'s share of the round trip.', '']
    names = {'service': 'ARMOR service', 'service_buffered_reasoner':
             'ARMOR service, buffered reasoner', 'floor': 'bare rclpy echo (floor)',
             'multi_echo': "echo on the node's executor",
             'core_alone': 'the core alone (its socket, from this process; no ROS)'}
    rows = []
    for command in ('QUERY', 'ADD'):
        paths = transport[command]
        for name, figures in paths.items():
            rows.append([command, names[name], f'{figures["calls"]:,}', _ms(figures['p50_ms']),
                         _ms(figures['p99_ms']),
                         f'{figures["p50_ms"] / paths["floor"]["p50_ms"]:.2f}x',
                         f'{figures["p99_ms"] / paths["floor"]["p99_ms"]:.2f}x'])
    out += [_table(['command', 'path', 'calls', 'p50', 'p99', 'p50 / floor', 'p99 / floor'],
                   rows), '']

    out += ['## 2. Batch throughput', '',
            'Lists of "ADD IND CLASS agent Robot" / "ADD OBJECTPROP IND isIn agent room" pairs on '
            'robotics.owl (HermiT), through `armor_interface_serialized_srv` and, in a separate '
            'JVM, through `ArmorCore.executeList` and through the bare OWL API (one change per '
            'directive, the reasoner kept up to date as a reference does). Same lists, same '
            'warm-up, each path from a fresh load.', '']
    rows = []
    for row in batch:
        rows.append([row['configuration'], row['service']['lists'],
                     f'{row["service"]["per_s"]:,.0f}', f'{row["armor_core"]["per_s"]:,.0f}',
                     f'{row["owlapi"]["per_s"]:,.0f}',
                     f'{row["service"]["per_s"] / row["armor_core"]["per_s"]:.0%}',
                     f'{row["service"]["per_s"] / row["owlapi"]["per_s"]:.1%}',
                     _ms(row['service']['list_ms_p50'])])
    out += [_table(['configuration', 'lists', 'service /s', 'ArmorCore in-process /s',
                    'bare OWL API /s', 'service / ArmorCore', 'service / OWL API',
                    'service list p50'], rows), '']

    out += ['## 3. Reasoning under updates', '',
            'ABox of N individuals on ontologies/robotics.owl (a fifth rooms in a corridor chain, '
            'the rest robots and people, two or more per room in half the rooms). One cycle: an '
            'agent moves (REPLACE OBJECTPROP IND isIn), REASON, QUERY IND CLASS OccupiedRoom (a '
            'defined class: Room and contains some Agent, contains being the inverse of isIn). '
            'Moves alternate: one fills an empty room, the next walks that agent on and empties '
            'it again, which must leave the answer. Every answer is checked against the known '
            'right one. '
            '"first" is the first REASON (or the first query, without REASON): the whole ABox '
            'is realised there. owlready2 does the same cycle with its bundled reasoners '
            '(`sync_reasoner_hermit` / `sync_reasoner_pellet`, property values not inferred), '
            'which start a new JVM per call. Modes: ' + '; '.join(
                f'*{mode}*: buffered reasoner {str(buffered).lower()}, '
                f'{"REASON in the cycle" if reason else "no REASON, the query asks the reasoner"}'
                for mode, (buffered, reason) in MODES.items()) + '.', '']
    for individuals, sides in reasoning.items():
        best = _best_owlready(sides)
        rows = []
        runs = [(f'ARMOR {reasoner}', mode, result)
                for reasoner, modes in sides['service'].items() for mode, result in modes.items()]
        runs += [(f'owlready2 {reasoner}', 'sync_reasoner', result)
                 for reasoner, result in sides['owlready2'].items()]
        for who, mode, result in runs:
            figures = summarise(result)
            speedup = (f'{best[0] / figures["cycle_p50_ms"]:.1f}x'
                       if best and figures['cycle_p50_ms'] else '-')
            rows.append([who, mode, _seconds(result['load_s']), _seconds(result['first_s']),
                         figures['cycles'], _ms(figures['cycle_p50_ms']),
                         _ms(figures['cycle_max_ms']), _ms(figures['reason_p50_ms']),
                         {True: 'yes', False: '**no**', None: '-'}[figures['correct']],
                         speedup, result['note'] or 'finished'])
        out += [f'### {individuals:,} individuals', '',
                _table(['who', 'mode', 'load', 'first', 'cycles', 'cycle p50', 'cycle max',
                        'REASON p50', 'answers right', 'best owlready2 / this', 'status'],
                       rows), '']

    out += ['## 4. Memory', '',
            'Peak resident memory (VmHWM) of the node (Python) and of its knowledge core (Java, '
            'the node\'s default `jvm_options`) over the runs of benchmark 3, with the ABox '
            'loaded and reasoned in every mode, one node per reasoner.', '']
    rows = []
    for individuals, sides in reasoning.items():
        for reasoner, modes in sides['service'].items():
            memory = _memory(modes)
            rows.append([f'{individuals:,}', reasoner, f'{memory["node"]:,.0f} MiB',
                         f'{memory["core"]:,.0f} MiB', f'{memory["total"]:,.0f} MiB'])
    out += [_table(['individuals', 'reasoner', 'node peak', 'core peak', 'total'], rows), '']

    out += ['## 5. Profile', '',
            'JDK Flight Recorder in the core of a benchmark node (`jvm_options`, 10 ms sampling, '
            'stacks up to 512 frames), dumped with `jcmd JFR.dump` and read with `jfr print`. '
            'Each execution sample counts for the first component found on its stack, in the '
            'order of the table.', '']
    for title, profile in profiles.items():
        out += [f'### {title}: {profile["workload"]}', '',
                f'{profile["samples"]:,} samples.', '',
                _table(['component', 'share of samples'],
                       [[name, f'{share:.1%}'] for name, share in profile['components']]), '',
                _table(['hottest top frame', 'share'],
                       [[f'`{name}`', f'{share:.1%}'] for name, share in profile['top_frames']]),
                '',
                _table(['ARMOR frame on the stack', 'share'],
                       [[f'`{name}`', f'{share:.1%}'] for name, share in profile['armor_frames']]),
                '']
    if 'lubm' in results:
        out += _lubm_section(results['lubm'])
    if 'robot_speed' in results:
        out += _robot_speed(results)
    return '\n'.join(out)


def _p50(values: List[float]) -> Optional[float]:
    return statistics.median(values) if values else None


def _lubm_summary(lubm: dict) -> List[List[str]]:
    """The four rows of benchmark 6 in the summary: each figure, its references, its target."""
    targets, met = lubm['targets_ms'], lubm['met']
    service, core = lubm['service']['mean_ms'], lubm['in_process']['armor_core']['mean_ms']
    bare = lubm['in_process']['bare_jena']['mean_ms']
    first = _p50(lubm['service_change']['first_query_ms'])
    many = lubm['service_many']['mean_ms']
    many_core = lubm.get('in_process_many', {}).get('armor_core', {}).get('mean_ms')
    many_bare = lubm.get('in_process_many', {}).get('bare_jena', {}).get('mean_ms')
    return [
        [f'6. LUBM 14-query mean over ROS 2, {lubm["data"]["one"]}, PELLET', _ms(service),
         f'in the core {_ms(core)}, bare Jena {_ms(bare)}', f'{service / bare:.1f}x bare Jena',
         f'<= {targets["service"]:g} ms', _met(met['service'])],
        ['6. LUBM 14-query mean in the core (in-process ArmorCore)', _ms(core),
         f'bare Jena {_ms(bare)}', f'{core / bare:.2f}x', f'<= {targets["in_process"]:g} ms',
         _met(met['in_process'])],
        ['6. first query after a one-fact change, p50, over ROS 2', _ms(first),
         f'ADD {_ms(_p50(lubm["service_change"]["add_ms"]))}; graph built afresh '
         f'{_ms(lubm["in_process"]["graph"]["full_build_ms"])}', '-',
         f'<= {targets["first_after_change"]:g} ms', _met(met['first_after_change'])],
        [f'6. LUBM 14-query mean over ROS 2, {lubm["data"]["many"]}', _ms(many),
         f'in the core {_ms(many_core)}, bare Jena {_ms(many_bare)}',
         f'{many / many_bare:.1f}x bare Jena' if many_bare else '-',
         f'<= {targets["departments"]:g} ms', _met(met['departments'])],
    ]


def _rows_right(run: Optional[dict]) -> str:
    if not run:
        return 'not run at this scale'
    right = sum(a == b for a, b in zip(run['rows'], run['expected_rows']))
    return f'{right}/{len(run["rows"])}' + ('' if run['rows_ok'] else ' **(differs)**')


def _lubm_section(lubm: dict) -> List[str]:
    one, many = lubm['data']['one'], lubm['data']['many']
    out = ['## 6. SPARQL on LUBM', '',
           'The 14 LUBM queries (bench/data/lubm/queries.json) through `QUERY SPARQL`: over ROS 2 '
           'from another process (bench/lubm.py), in a separate JVM through `ArmorCore.execute` '
           '(no socket, no ROS), and with plain Jena ARQ over a plain in-memory copy of the '
           'same graph, its results read but not rendered (the floor; `LubmBench.java`). Each '
           'figure is the mean over rounds of the 14 queries after warm-up rounds, the mean of '
           'the 14 per-query means; every answer\'s row count is checked against the expected '
           'one on every round. Openllet (PELLET) with a non-buffered reasoner, after REASON. '
           f'One department: {one}. More departments: {many}; bench/lubm_generator.py writes '
           'them. A second reasoner (HermiT) answers the same queries once.', '']
    over_ros = {key: f'{len(lubm[key]["per_query_ms"])}/{len(lubm[key]["per_query_ms"])}'
                for key in ('service', 'service_many')}  # a wrong row count stops the run
    out += ['### Answers', '',
            'Queries whose row count is the expected one.', '',
            _table(['data', 'PELLET over ROS 2', 'PELLET in the core', 'HERMIT in the core'],
                   [[one, over_ros['service'], _rows_right(lubm['in_process']),
                     _rows_right(lubm['second_reasoner'])],
                    [many, over_ros['service_many'], _rows_right(lubm.get('in_process_many')),
                     _rows_right(lubm.get('second_reasoner_many'))]]), '']
    for title, service_key, core_key in ((one, 'service', 'in_process'),
                                         (many, 'service_many', 'in_process_many')):
        service, core = lubm[service_key], lubm.get(core_key)
        queries = range(1, len(service['per_query_ms']) + 1)
        rows = []
        for index in queries:
            rows.append([index, core['rows'][index - 1] if core else '-',
                         _ms(service['per_query_ms'][index - 1]),
                         _ms(core['armor_core']['per_query_ms'][index - 1]) if core else '-',
                         _ms(core['bare_jena']['per_query_ms'][index - 1]) if core else '-'])
        rows.append(['**mean**', '', f'**{_ms(service["mean_ms"])}**',
                     f'**{_ms(core["armor_core"]["mean_ms"])}**' if core else '-',
                     f'**{_ms(core["bare_jena"]["mean_ms"])}**' if core else '-'])
        rounds = f'Measured rounds: {service["rounds"]} over ROS 2' + (
            f', {core["armor_core"]["rounds"]} in the core and on bare Jena' if core else '') + (
            f'. The round trip of `ASK {{}}` (nothing to find, one value back), asked after '
            f'each query over ROS 2: {_ms(service["ask_floor_ms"])} on average')
        out += [f'### 14 queries, {title}', '', f'{rounds}.', '',
                _table(['query', 'rows', 'over ROS 2', 'in the core', 'bare Jena'], rows), '']
    change, core_change = lubm['service_change'], lubm['in_process']['change']
    graph = lubm['in_process']['graph']
    out += ['### The first query after a one-fact change', '',
            f'ADD IND CLASS of a new graduate student, then query {core_change["query"]} (all '
            'students: the new one is a Student by inference, so the answer must grow by one, '
            'and does: checked every time), then the same query again; '
            f'{change["changes"]} times over ROS 2, {core_change["changes"]} in the core. The '
            'graph\'s share was measured on a reference beside the core: the reasoner brought up '
            'to date (what ADD does), Openllet\'s realisation, the derivation of the new graph '
            'from the last one, against a fresh build.', '',
            _table(['step', 'p50', 'p90'], [
                ['ADD, over ROS 2', _ms(_p50(change['add_ms'])),
                 _ms(_p90(change['add_ms']))],
                ['first query after it, over ROS 2', _ms(_p50(change['first_query_ms'])),
                 _ms(_p90(change['first_query_ms']))],
                ['the query again, over ROS 2', _ms(_p50(change['next_query_ms'])),
                 _ms(_p90(change['next_query_ms']))],
                ['ADD, in the core', _ms(_p50(core_change['add_ms'])),
                 _ms(_p90(core_change['add_ms']))],
                ['first query after it, in the core', _ms(_p50(core_change['first_query_ms'])),
                 _ms(_p90(core_change['first_query_ms']))],
                ['graph: reasoner brought up to date', _ms(_p50(graph['change_ms'])),
                 _ms(_p90(graph['change_ms']))],
                ['graph: realisation (Openllet)', _ms(_p50(graph['realise_ms'])),
                 _ms(_p90(graph['realise_ms']))],
                ['graph: derived from the last one', _ms(_p50(graph['derive_ms'])),
                 _ms(_p90(graph['derive_ms']))],
                [f'graph: built afresh ({graph["triples"]:,} triples), for comparison',
                 _ms(graph['full_build_ms']),
                 '-']]), '']
    loads = []
    for title, key, core_key in ((one, 'service_load', 'in_process'),
                                 (many, 'service_many_load', 'in_process_many')):
        figures, core = lubm[key], lubm.get(core_key)
        loads.append([title, f'{core["graph"]["triples"]:,}' if core else '-',
                      _seconds(figures['load_ms'] / 1000), _seconds(figures['reason_ms'] / 1000),
                      _seconds(figures['first_query_ms'] / 1000),
                      _seconds(core['graph']['full_build_ms'] / 1000) if core else '-'])
    out += ['### Loading', '',
            'Over ROS 2: LOAD FILE (PELLET, non-buffered), REASON, and the first query, which '
            'builds the graph; in the core, the graph built afresh.', '',
            _table(['data', 'triples in the graph', 'LOAD', 'REASON', 'first query',
                    'graph built afresh (core)'], loads), '']
    for title, profile in lubm.get('profiles', {}).items():
        out += [f'### Profile where a target is missed: {title}', '',
                f'{profile["workload"]}; {profile["samples"]:,} samples of the core (JDK Flight '
                'Recorder, `jcmd JFR.start`/`JFR.stop` around the workload).', '',
                _table(['component', 'share of samples'],
                       [[name, f'{share:.1%}'] for name, share in profile['components']]), '',
                _table(['hottest top frame', 'share'],
                       [[f'`{name}`', f'{share:.1%}'] for name, share in profile['top_frames']]),
                '']
    return out


def _p90(values: List[float]) -> Optional[float]:
    return percentile(values, 0.9) if values else None
