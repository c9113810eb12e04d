# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The planner bridge at scale: a PDDL problem of about 1,000 objects from ARMOR, then planned.

    python bench/pddl_bridge.py [--objects 1000] [--runs 5] [--reasoner HERMIT] [--json]

Writes an office building (halls of 24 rooms in a row, a dock, a rover; places connected by
the doors they share, a property chain only the reasoner evaluates; a few alarms, whose rooms
the reasoner classifies as AlarmedRoom, a defined class), loads it into an ARMOR node of its
own and measures, side by side in one run:

- generation: QUERY PDDL PROBLEM over ROS 2, the first call (which realises the ontology)
  and the median of the next runs;
- the same facts gathered by a client without the bridge: QUERY IND CLASS for each class and
  QUERY OBJECTPROP IND for each object and property, one round trip each (what feeding a
  planner by hand costs); the ratio of the two;
- the planner: pyperplan (greedy best-first with h_FF) on the generated problem, its wall time
  (start-up, parsing, grounding, search) and its own search time, the plan's length, and the
  plan replayed against the domain (examples/pddl/planning.py).
"""

import argparse
import json
import pathlib
import statistics
import sys
import tempfile
import time
from typing import Dict, List

from harness import REPO, BenchNode, CoreSnapshot

sys.path.insert(0, str(REPO / 'examples' / 'pddl'))
import planning  # noqa: E402  (examples/pddl is no package)

DOMAIN = REPO / 'examples' / 'pddl' / 'surveillance-domain.pddl'
ROOMS_PER_HALL = 24
MAPPING = {
    'domain': 'surveillance', 'problem': 'office-patrol',
    'types': {'Robot': 'robot', 'Place': 'location'},
    'unary_predicates': {'Dock': 'charging-station'},
    'binary_predicates': {'isIn': 'at', 'connectedTo': 'connected'},
    'goal': [{'forall': 'AlarmedRoom', 'require': ['visited', '?room']}, ['recharged', 'rover']],
}
TBOX = '''@prefix : <http://www.example.org/office#> .
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
<http://www.example.org/office> a owl:Ontology .
:Place a owl:Class . :Door a owl:Class . :Robot a owl:Class . :Alarm a owl:Class .
:Room a owl:Class ; rdfs:subClassOf :Place .
:Hall a owl:Class ; rdfs:subClassOf :Place .
:Dock a owl:Class ; rdfs:subClassOf :Place .
:AlarmedRoom a owl:Class ; owl:equivalentClass [ a owl:Class ; owl:intersectionOf ( :Room
    [ a owl:Restriction ; owl:onProperty :raises ; owl:someValuesFrom :Alarm ] ) ] .
:isIn a owl:ObjectProperty .
:hasDoor a owl:ObjectProperty .
:isDoorOf a owl:ObjectProperty ; owl:inverseOf :hasDoor .
:connectedTo a owl:ObjectProperty ; owl:propertyChainAxiom ( :hasDoor :isDoorOf ) .
:raises a owl:ObjectProperty .
:detectedIn a owl:ObjectProperty ; owl:inverseOf :raises .
'''


def building(path: pathlib.Path, objects: int) -> Dict[str, int]:
    """Write a building of about `objects` PDDL objects (places and the rover) as Turtle."""
    halls = max(1, round((objects - 2) / (ROOMS_PER_HALL + 1)))
    lines = [TBOX, ':dock a :Dock ; :hasDoor :dock-door .', ':rover a :Robot ; :isIn :dock .']
    for h in range(halls):
        doors = [f':hall-door{h}'] + ([f':hall-door{h - 1}'] if h else [':dock-door'])
        for r in range(ROOMS_PER_HALL):
            lines.append(f':room{h}-{r} a :Room ; :hasDoor :room-door{h}-{r} .')
            doors.append(f':room-door{h}-{r}')
        lines.append(f':hall{h} a :Hall ; :hasDoor {" , ".join(doors)} .')
    # Alarms in three rooms spread over the building: the goal's rooms.
    alarmed = [(h, 3) for h in sorted({halls // 6, halls // 2, halls - 1})]
    for number, (h, r) in enumerate(alarmed):
        lines.append(f':smoke{number} a :Alarm ; :detectedIn :room{h}-{r} .')
    path.write_text('\n'.join(lines) + '\n')
    return {'halls': halls, 'rooms': halls * ROOMS_PER_HALL, 'alarmed rooms': len(alarmed),
            'objects': halls * (ROOMS_PER_HALL + 1) + 2}


def by_hand(node: BenchNode, reference: str) -> Dict[str, float]:
    """The facts of the problem gathered with the built-in queries, one round trip each."""
    started = time.monotonic()
    calls = 0
    objects = set()
    for cls in ('Robot', 'Place', 'Dock', 'AlarmedRoom'):
        answer = node.call(reference, 'QUERY IND CLASS', cls, timeout_s=600)
        calls += 1
        if cls in ('Robot', 'Place'):
            objects.update(answer.queried_objects)
    facts = 0
    for individual in sorted(objects):
        for prop in ('isIn', 'connectedTo'):
            facts += len(node.call(reference, 'QUERY OBJECTPROP IND', prop, individual,
                                   timeout_s=600).queried_objects)
            calls += 1
    return {'seconds': time.monotonic() - started, 'calls': calls, 'facts': facts}


def measure(scratch: pathlib.Path, snapshot: CoreSnapshot, objects: int, runs: int,
            reasoner: str) -> dict:
    """Generate, gather by hand and plan on a building of about `objects` objects."""
    ontology = scratch / f'office-{objects}.ttl'
    shape = building(ontology, objects)
    node = BenchNode(scratch, snapshot)
    try:
        started = time.monotonic()
        loaded = node.call('office', 'LOAD FILE', str(ontology), '', 'false', reasoner, 'false',
                           timeout_s=600)
        if not loaded.success:
            raise RuntimeError(f'LOAD failed: {loaded.exit_code} {loaded.error_description}')
        load_s = time.monotonic() - started
        mapping = json.dumps(MAPPING)
        times: List[float] = []
        problem = ''
        for _ in range(runs + 1):
            started = time.monotonic()
            answer = node.call('office', 'QUERY PDDL PROBLEM', mapping, timeout_s=600)
            times.append(time.monotonic() - started)
            if not answer.success:
                raise RuntimeError(f'QUERY PDDL PROBLEM failed: {answer.exit_code} '
                                   f'{answer.error_description}')
            if problem and answer.queried_objects[0] != problem:
                raise RuntimeError('the same state gave two different problems')
            problem = answer.queried_objects[0]
        hand = by_hand(node, 'office')
    finally:
        node.stop()
    parsed = planning.Problem.parse(problem)
    plan = planning.solve(DOMAIN, problem, search='gbf', heuristic='hff')
    planning.validate(DOMAIN.read_text(), problem, plan.steps)
    generation_s = statistics.median(times[1:])
    return {
        'building': shape, 'reasoner': reasoner, 'load_s': load_s,
        'problem': {'objects': len(parsed.objects), 'init facts': len(parsed.init),
                    'goal facts': len(parsed.goal), 'bytes': len(problem.encode())},
        'generation': {'first_s': times[0], 'median_s': generation_s, 'runs': runs},
        'by_hand': hand, 'by_hand_over_bridge': hand['seconds'] / generation_s,
        'planner': {'search': 'gbf', 'heuristic': 'hff', 'wall_s': plan.wall_s,
                    'search_s': plan.search_s, 'plan_length': len(plan), 'valid': True},
    }


def show(result: dict) -> str:
    problem, generation, hand, plan = (result['problem'], result['generation'],
                                       result['by_hand'], result['planner'])
    return '\n'.join([
        f'building: {result["building"]}; reasoner {result["reasoner"]}, '
        f'LOAD {result["load_s"]:.2f} s',
        f'problem: {problem["objects"]} objects, {problem["init facts"]} init facts, '
        f'{problem["goal facts"]} goal facts, {problem["bytes"]:,} bytes',
        f'QUERY PDDL PROBLEM: first {generation["first_s"]:.3f} s, then median '
        f'{generation["median_s"]:.3f} s over {generation["runs"]} runs (byte-identical)',
        f'the same facts by hand: {hand["calls"]} queries, {hand["facts"]} facts, '
        f'{hand["seconds"]:.2f} s = {result["by_hand_over_bridge"]:.1f}x the bridge',
        f'pyperplan ({plan["search"]}, {plan["heuristic"]}): {plan["wall_s"]:.2f} s wall, '
        f'search {plan["search_s"]:.2f} s, plan of {plan["plan_length"]} steps, valid'])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--objects', type=int, default=1000, help='objects of the problem')
    parser.add_argument('--runs', type=int, default=5, help='generations measured after the first')
    parser.add_argument('--reasoner', default='HERMIT', help='reasoner of the building')
    parser.add_argument('--json', action='store_true', help='print the figures as JSON')
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix='armor-bench-pddl-') as scratch:
        snapshot = CoreSnapshot(pathlib.Path(scratch))
        result = measure(pathlib.Path(scratch), snapshot, args.objects, args.runs, args.reasoner)
    print(json.dumps(result, indent=2) if args.json else show(result))
    return 0


if __name__ == '__main__':
    sys.exit(main())
