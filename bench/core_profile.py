# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Where the knowledge core spends its time: a JDK Flight Recorder profile of a running node.

    python bench/core_profile.py [--smoke]

A node is started with a flight recording in its core (the node parameter jvm_options), the
workload runs, `jcmd JFR.dump` saves the recording (the core is halted, not shut down, when the
node stops, so the JVM would not write it itself), and `jfr print` lists its execution
samples. Each sample is put in the first component, in COMPONENTS order, that has a frame
anywhere on its stack: the share of samples per component is where the time goes.
"""

import collections
import json
import pathlib
import re
import subprocess
import time

from answers import checked, WrongAnswer
from batch_throughput import directive_list
from harness import REPO, BenchNode, CoreSnapshot, Deadline, script_scale_and_scratch

COMPONENTS = (  # (component, frame prefixes); the first match on a sample's stack wins
    ('naming: EntityResolver (plain name -> IRI)',
     ('io.github.armor.core.reference.EntityResolver',)),
    ('reasoner', ('org.semanticweb.HermiT', 'openllet', 'uk.ac.manchester.cs.jfact',
                  'org.semanticweb.elk')),
    ('journal (durability)', ('io.github.armor.core.durability',)),
    ('OWL API ontology changes',
     ('uk.ac.manchester.cs.owl.owlapi.OWLOntologyManagerImpl.applyChanges',
      'uk.ac.manchester.cs.owl.owlapi.OWLImmutableOntologyImpl',
      'uk.ac.manchester.cs.owl.owlapi.Internals')),
    # Every worker stack has CoreServer at its bottom: only (de)serialising and socket I/O count.
    ('wire: socket and JSON', ('com.google.gson', 'io.github.armor.core.server.WireCodec',
                               'io.github.armor.core.server.CoreServer.readFrame',
                               'io.github.armor.core.server.CoreServer.writeFrame')),
    ('other ARMOR core code', ('io.github.armor.core.ArmorCore', 'io.github.armor.core.pipeline',
                               'io.github.armor.core.command', 'io.github.armor.core.answers',
                               'io.github.armor.core.log', 'io.github.armor.core.reference')),
)
_FRAME = re.compile(r'^\s{4}(\S+)\(')


def jfr_options(recording: pathlib.Path) -> str:
    """jvm_options value (a ROS string list) with a recording at 10 ms sampling, deep stacks."""
    return ('["-Xmx4g", "-XX:+ExitOnOutOfMemoryError", '
            f'"-XX:StartFlightRecording=name=armor,settings=profile,filename={recording}", '
            '"-XX:FlightRecorderOptions=stackdepth=512"]')


def dump(core_pid: int, recording: pathlib.Path) -> None:
    subprocess.run(['jcmd', str(core_pid), 'JFR.dump', 'name=armor', f'filename={recording}'],
                   check=True, capture_output=True, timeout=120)


def samples(recording: pathlib.Path) -> list:
    """Stacks (top frame first, as 'package.Class.method') of the recording's execution samples."""
    text = subprocess.run(['jfr', 'print', '--stack-depth', '512', '--events',
                           'jdk.ExecutionSample', str(recording)],
                          check=True, capture_output=True, text=True).stdout
    stacks = []
    for event in text.split('jdk.ExecutionSample {')[1:]:
        stacks.append([m.group(1) for m in map(_FRAME.match, event.splitlines()) if m])
    return stacks


def summarise(stacks: list, top: int = 8, components: tuple = COMPONENTS) -> dict:
    """Share of samples per component, the hottest top frames, and the hottest ARMOR frames."""
    counts = collections.Counter()
    leaves = collections.Counter()
    armor_frames = collections.Counter()
    for stack in stacks:
        if not stack:
            continue
        leaves[stack[0]] += 1
        component = next((name for name, prefixes in components
                          if any(frame.startswith(prefixes) for frame in stack)),
                         'outside the directive path (server loop, JIT, class loading)')
        counts[component] += 1
        for frame in set(stack):
            if frame.startswith('io.github.armor.core'):
                armor_frames[frame] += 1
    total = max(1, sum(counts.values()))
    return {'samples': sum(counts.values()),
            'components': [(name, count / total) for name, count in counts.most_common()],
            'top_frames': [(name, count / total) for name, count in leaves.most_common(top)],
            'armor_frames': [(name, count / total)
                             for name, count in armor_frames.most_common(top)]}


def profile_batch(scratch: pathlib.Path, snapshot: CoreSnapshot, seconds: float,
                  list_size: int = 1000) -> dict:
    """The core while it answers lists of ADDs through the service (a buffered reasoner)."""
    recording = scratch / 'batch.jfr'
    node = BenchNode(scratch, snapshot, parameters={'jvm_options': jfr_options(recording)})
    try:
        checked(node.call('profiled', 'LOAD FILE', str(REPO / 'ontologies' / 'robotics.owl'),
                          '', 'false', 'HERMIT', 'true', timeout_s=120), 'LOAD')
        deadline = Deadline(seconds)
        lists = 0
        while lists == 0 or not deadline.expired():
            answer = node.transport.call_list(directive_list('profiled', lists, list_size),
                                              timeout_s=600)
            if not answer.success:
                raise WrongAnswer(f'list {lists} failed: {answer.armor_responses[:1]}')
            lists += 1
        dump(node.process.core_pid(), recording)
    finally:
        node.stop()
    return {'workload': f'{lists} lists of {list_size} ADD directives through '
                        'armor_interface_serialized_srv (buffered HermiT)',
            **summarise(samples(recording))}


def profile_single_adds(scratch: pathlib.Path, snapshot: CoreSnapshot, seconds: float) -> dict:
    """The core while it answers single ADDs of new individuals on the preloaded reference."""
    recording = scratch / 'add.jfr'
    node = BenchNode(scratch, snapshot, parameters={'jvm_options': jfr_options(recording)},
                     preload_robotics=True)
    try:
        deadline = Deadline(seconds)
        calls = 0
        while calls == 0 or not deadline.expired():
            checked(node.call('robotics', 'ADD IND CLASS', f'probe{calls}', 'Robot',
                              timeout_s=600), 'ADD')
            calls += 1
        dump(node.process.core_pid(), recording)
    finally:
        node.stop()
    return {'workload': f'{calls} single ADD IND CLASS directives (a new individual each) on '
                        'the preloaded reference with the defaults (HermiT, non-buffered)',
            **summarise(samples(recording))}


def profile_cycle(scratch: pathlib.Path, snapshot: CoreSnapshot, abox_path: pathlib.Path,
                  individuals: int, reasoner: str, buffered: bool, with_reason: bool,
                  seconds: float) -> dict:
    """The core while it runs the reasoning cycle of benchmark 3 on one reasoner and mode."""
    from abox import RoboticsABox
    recording = scratch / 'cycle.jfr'
    node = BenchNode(scratch, snapshot, parameters={'jvm_options': jfr_options(recording)})
    workload = RoboticsABox(individuals)
    try:
        checked(node.call('profiled', 'LOAD FILE', str(abox_path), '', 'false', reasoner,
                          str(buffered).lower(), timeout_s=600), 'LOAD')
        deadline = Deadline(seconds)
        cycles = 0
        while cycles == 0 or (not deadline.expired() and workload.moves_left):
            move = workload.next_move()
            checked(node.call('profiled', 'REPLACE OBJECTPROP IND', 'isIn', move.agent,
                              move.new_room, move.old_room, timeout_s=600), 'REPLACE')
            if with_reason:
                checked(node.call('profiled', 'REASON', timeout_s=600), 'REASON')
            checked(node.call('profiled', 'QUERY IND CLASS', 'OccupiedRoom', timeout_s=600),
                    f'cycle {cycles} of the profile', workload.occupied_rooms())
            cycles += 1
        dump(node.process.core_pid(), recording)
    finally:
        node.stop()
    mode = ('buffered' if buffered else 'non-buffered') + ('' if with_reason else ', no REASON')
    return {'workload': f'{cycles} reasoning cycles at {individuals} individuals, {reasoner} '
                        f'({mode}), including the load',
            **summarise(samples(recording))}


def main():
    scale, scratch = script_scale_and_scratch(__doc__)
    started = time.monotonic()
    print(json.dumps(profile_batch(scratch, CoreSnapshot(scratch), scale.profile_s), indent=2))
    print(f'{time.monotonic() - started:.0f} s')


if __name__ == '__main__':
    main()
