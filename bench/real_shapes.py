# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Benchmark 9 (issue 28), the ontologies robots really use: a cycle per shape and size, through
the service, every answer checked, the modular reasoners beside the whole-ontology Openllet.

    python bench/real_shapes.py [--smoke] [--shapes c] [--sizes 1000] [--reasoners PELLET]
                                [--baseline-jar JAR]

--baseline-jar runs another build of the core (an armor-core.jar with its lib/ beside it, e.g.
main's core/target) beside this one, each size on both, so a change is measured side by side.

Shapes (each written here as an OWL functional-syntax file):
- (a) robotics: bench/abox.py's map and moves (benchmark 3's cycle);
- (b) part-of map: places in a transitive part-of tree (building, floors, zones, rooms),
  rooms adjacent in a row (symmetric), agents located at rooms, BusyPlace = Place and
  inverse(locatedAt) some Agent; cycle: REPLACE locatedAt, REASON, QUERY IND CLASS BusyPlace;
- (c) the surveillance course's topological map with its SWRL rules (doors give connectedTo,
  isIn + connectedTo give canReach, now - visitedAt > threshold gives URGENT), a corridor spine
  with a door per room, every individual different; the students' loop: REPLACE isIn, REPLACE
  now, REPLACE visitedAt, REASON, QUERY IND CLASS URGENT, QUERY OBJECTPROP IND canReach; at
  100, 1,000 and 10,000 locations (the whole-ontology Openllet up to 1,000);
- (d) (b) with a functional locatedAt and a hasValue class (AtDock = Agent and locatedAt value dock).
The generator knows every right answer, so each answer is checked (ones that must disappear too:
moves empty a place, time makes rooms urgent and visits make them not).
"""

import pathlib
import statistics
import time
from typing import Dict, List, Optional, Set

from abox import RoboticsABox
from harness import BenchNode, CoreSnapshot, Deadline

NS = 'http://www.example.org/shapes#'
WHOLE = 'openllet.owlapi.OpenlletReasonerFactory'
REASONERS = {'PELLET': 'PELLET', 'HERMIT': 'HERMIT', 'Openllet, whole ontology': WHOLE}
SIZES = {'full': [1000, 10000], 'smoke': [60]}
# (c) also at 100 locations; the whole-ontology Openllet is not run on it past 1,000 (at 1,000 its LOAD
# alone took 138 s and no cycle finished within the budget: a 10,000 run would only measure the budget).
COURSE_SIZES = {'full': [100, 1000, 10000], 'smoke': [30]}
WHOLE_COURSE_UP_TO = 1000
CYCLES = {'full': 15, 'smoke': 2}
BUDGET_S = {'full': 240, 'smoke': 60}


def _header() -> List[str]:
    return [f'Prefix(:=<{NS}>)', 'Prefix(xsd:=<http://www.w3.org/2001/XMLSchema#>)',
            'Prefix(owl:=<http://www.w3.org/2002/07/owl#>)',
            'Prefix(swrlb:=<http://www.w3.org/2003/11/swrlb#>)',
            'Prefix(var:=<urn:swrl:var#>)', f'Ontology(<{NS[:-1]}>']


class PartOfMap:
    """(b), and (d) with `functional`: about `individuals` places and agents."""

    def __init__(self, individuals: int, functional: bool):
        self.functional = functional
        rooms = max(8, individuals * 3 // 5)
        floors = max(1, rooms // 200)
        zones = max(2, rooms // 20)
        self.floors = [f'floor{i}' for i in range(floors)]
        self.zones = [f'zone{i}' for i in range(zones)]
        self.rooms = ['dock'] + [f'room{i}' for i in range(1, rooms)]
        self.agents = [f'robot{i}' for i in range(individuals - rooms - zones - floors - 1)]
        occupied = self.rooms[:len(self.rooms) // 2]
        self.at: Dict[str, str] = {a: occupied[i % len(occupied)] for i, a in enumerate(self.agents)}
        self._empty = self.rooms[len(occupied):]
        self._movable = [a for a in self.agents if self.at[a] != 'dock']

    def write(self, path: pathlib.Path) -> pathlib.Path:
        lines = _header() + [
            'SubClassOf(:Room :Place) SubClassOf(:Zone :Place) SubClassOf(:Floor :Place)',
            'SubClassOf(:Building :Place) SubClassOf(:Robot :Agent) DisjointClasses(:Place :Agent)',
            'TransitiveObjectProperty(:partOf) ObjectPropertyDomain(:partOf :Place)',
            'ObjectPropertyRange(:partOf :Place) SymmetricObjectProperty(:adjacentTo)',
            'ObjectPropertyDomain(:locatedAt :Agent) ObjectPropertyRange(:locatedAt :Place)',
            'EquivalentClasses(:BusyPlace ObjectIntersectionOf(:Place '
            'ObjectSomeValuesFrom(ObjectInverseOf(:locatedAt) :Agent)))']
        if self.functional:
            lines += ['FunctionalObjectProperty(:locatedAt)',
                      'EquivalentClasses(:AtDock ObjectIntersectionOf(:Agent '
                      'ObjectHasValue(:locatedAt :dock)))']
        lines.append('ClassAssertion(:Building :building)')
        for floor in self.floors:
            lines.append(f'ClassAssertion(:Floor :{floor}) ObjectPropertyAssertion(:partOf :{floor} '
                         ':building)')
        for i, zone in enumerate(self.zones):
            lines.append(f'ClassAssertion(:Zone :{zone}) ObjectPropertyAssertion(:partOf :{zone} '
                         f':{self.floors[i % len(self.floors)]})')
        for i, room in enumerate(self.rooms):
            lines.append(f'ClassAssertion(:Room :{room}) ObjectPropertyAssertion(:partOf :{room} '
                         f':{self.zones[i % len(self.zones)]})')
            if i:
                lines.append(f'ObjectPropertyAssertion(:adjacentTo :{room} :{self.rooms[i - 1]})')
        for agent in self.agents:
            lines.append(f'ClassAssertion(:Robot :{agent}) '
                         f'ObjectPropertyAssertion(:locatedAt :{agent} :{self.at[agent]})')
        path.write_text('\n'.join(lines) + '\n)\n')
        return path

    def _count(self) -> Dict[str, int]:
        count: Dict[str, int] = {}
        for place in self.at.values():
            count[place] = count.get(place, 0) + 1
        return count

    @property
    def moves_left(self) -> int:
        # An agent moves only out of a place it shares (the place stays busy), never out of the dock.
        sharing = sum(c - 1 for place, c in self._count().items() if place != 'dock' and c > 1)
        return min(len(self._empty), sharing)

    def cycle(self) -> List[tuple]:
        """One move of an agent that shares its place into an empty one: the directives."""
        count = self._count()
        agent = next(a for a in reversed(self._movable) if count[self.at[a]] >= 2)
        self._movable.remove(agent)
        old, new = self.at[agent], self._empty.pop(0)
        self.at[agent] = new
        return [('REPLACE OBJECTPROP IND', 'locatedAt', agent, new, old)]

    def questions(self) -> List[tuple]:
        return [(('QUERY IND CLASS', 'BusyPlace'), sorted(set(self.at.values())))]


class CourseMap:
    """(c): `locations` locations (a corridor spine, rooms with a door each), one robot, rules."""

    THRESHOLD = 100

    def __init__(self, locations: int):
        corridors = max(2, locations // 10)
        self.corridors = [f'corridor{i}' for i in range(corridors)]
        self.rooms = [f'room{i}' for i in range(locations - corridors)]
        self.doors: Dict[str, List[str]] = {}  # door -> the two locations it joins
        for i in range(1, corridors):
            self.doors[f'cdoor{i}'] = [self.corridors[i - 1], self.corridors[i]]
        for i, room in enumerate(self.rooms):
            self.doors[f'door{i}'] = [room, self.corridors[i % corridors]]
        self.robot_at = self.corridors[0]
        self.now = 1000
        # Visits spread over the past: some rooms urgent from the start.
        self.visited = {room: self.now - (i * 37) % 300 for i, room in enumerate(self.rooms)}
        self._step = 0

    def write(self, path: pathlib.Path) -> pathlib.Path:
        lines = _header() + [
            'SubClassOf(:Room :Location) SubClassOf(:Corridor :Location)',
            'DisjointClasses(:Room :Corridor :Door :Robot)',
            'ObjectPropertyDomain(:hasDoor :Location) ObjectPropertyRange(:hasDoor :Door)',
            'FunctionalDataProperty(:now) FunctionalDataProperty(:visitedAt)',
            'SubClassOf(:URGENT :Room)',
            'DLSafeRule(Body(ClassAtom(:Location Variable(var:a)) ClassAtom(:Location Variable(var:b))'
            ' ObjectPropertyAtom(:hasDoor Variable(var:a) Variable(var:d))'
            ' ObjectPropertyAtom(:hasDoor Variable(var:b) Variable(var:d))'
            ' DifferentIndividualsAtom(Variable(var:a) Variable(var:b)))'
            ' Head(ObjectPropertyAtom(:connectedTo Variable(var:a) Variable(var:b))))',
            'DLSafeRule(Body(ClassAtom(:Robot Variable(var:r)) ObjectPropertyAtom(:isIn Variable(var:r)'
            ' Variable(var:a)) ObjectPropertyAtom(:connectedTo Variable(var:a) Variable(var:b)))'
            ' Head(ObjectPropertyAtom(:canReach Variable(var:r) Variable(var:b))))',
            'DLSafeRule(Body(ClassAtom(:Robot Variable(var:r)) DataPropertyAtom(:now Variable(var:r)'
            ' Variable(var:t)) DataPropertyAtom(:urgencyThreshold Variable(var:r) Variable(var:k))'
            ' ClassAtom(:Room Variable(var:l)) DataPropertyAtom(:visitedAt Variable(var:l) Variable(var:v))'
            ' BuiltInAtom(swrlb:subtract Variable(var:age) Variable(var:t) Variable(var:v))'
            ' BuiltInAtom(swrlb:greaterThan Variable(var:age) Variable(var:k)))'
            ' Head(ClassAtom(:URGENT Variable(var:l))))',
            'ClassAssertion(:Robot :robot)', f'ObjectPropertyAssertion(:isIn :robot :{self.robot_at})',
            f'DataPropertyAssertion(:now :robot "{self.now}"^^xsd:integer)',
            f'DataPropertyAssertion(:urgencyThreshold :robot "{self.THRESHOLD}"^^xsd:integer)']
        for corridor in self.corridors:
            lines.append(f'ClassAssertion(:Corridor :{corridor})')
        for room in self.rooms:
            lines.append(f'ClassAssertion(:Room :{room}) '
                         f'DataPropertyAssertion(:visitedAt :{room} "{self.visited[room]}"^^xsd:integer)')
        for door, (a, b) in self.doors.items():
            lines.append(f'ClassAssertion(:Door :{door}) ObjectPropertyAssertion(:hasDoor :{a} :{door})'
                         f' ObjectPropertyAssertion(:hasDoor :{b} :{door})')
        everyone = ['robot'] + self.corridors + self.rooms + list(self.doors)
        lines.append('DifferentIndividuals(' + ' '.join(f':{i}' for i in everyone) + ')')
        path.write_text('\n'.join(lines) + '\n)\n')
        return path

    moves_left = 10 ** 9

    def _neighbours(self, location: str) -> Set[str]:
        return {other for pair in self.doors.values() if location in pair
                for other in pair if other != location}

    def cycle(self) -> List[tuple]:
        """The robot walks to a neighbour (a room it visits, or a corridor), 40 s pass."""
        self._step += 1
        old_place, old_now = self.robot_at, self.now
        rooms = sorted(n for n in self._neighbours(old_place) if n.startswith('room'))
        place = rooms[self._step % len(rooms)] if rooms and self._step % 2 else sorted(
            n for n in self._neighbours(old_place) if n.startswith('corridor'))[0]
        self.robot_at, self.now = place, self.now + 40
        directives = [('REPLACE OBJECTPROP IND', 'isIn', 'robot', place, old_place),
                      ('REPLACE DATAPROP IND', 'now', 'robot', 'INTEGER', str(self.now), str(old_now))]
        if place in self.visited:
            directives.append(('REPLACE DATAPROP IND', 'visitedAt', place, 'INTEGER', str(self.now),
                               str(self.visited[place])))
            self.visited[place] = self.now
        return directives

    def questions(self) -> List[tuple]:
        urgent = sorted(r for r, v in self.visited.items() if self.now - v > self.THRESHOLD)
        return [(('QUERY IND CLASS', 'URGENT'), urgent),
                (('QUERY OBJECTPROP IND', 'canReach', 'robot'), sorted(self._neighbours(self.robot_at)))]


class Robotics:
    """(a): benchmark 3's map and moves, in the same interface."""

    def __init__(self, individuals: int):
        self.abox = RoboticsABox(individuals)

    def write(self, path: pathlib.Path) -> pathlib.Path:
        return self.abox.write(path)

    @property
    def moves_left(self) -> int:
        return self.abox.moves_left

    def cycle(self) -> List[tuple]:
        move = self.abox.next_move()
        return [('REPLACE OBJECTPROP IND', 'isIn', move.agent, move.new_room, move.old_room)]

    def questions(self) -> List[tuple]:
        return [(('QUERY IND CLASS', 'OccupiedRoom'), self.abox.occupied_rooms())]


SHAPES = {
    '(a) robotics': lambda n: Robotics(n),
    '(b) part-of map': lambda n: PartOfMap(n, functional=False),
    '(c) course map with SWRL rules': lambda n: CourseMap(n),
    '(d) part-of map, functional, hasValue': lambda n: PartOfMap(n, functional=True),
}


def _short(answer) -> List[str]:
    return sorted(iri.rstrip('>').rsplit('#', 1)[-1] for iri in answer.queried_objects)


def _run(node: BenchNode, path: pathlib.Path, shape, reasoner: str, cycles: int,
         budget_s: float, reference: str) -> dict:
    deadline = Deadline(budget_s)
    result = {'load_s': None, 'first_s': None, 'cycles': [], 'wrong': 0, 'note': '',
              'reasoning': '', 'steps': {}}

    def call(*words, what: str):
        if deadline.expired():
            raise TimeoutError(f'{what}: out of the {budget_s:.0f} s budget')
        start = time.perf_counter()
        answer = node.call(reference, *words, timeout_s=max(deadline.left(), 1.0))
        if not answer.success:
            raise RuntimeError(f'{what}: {words[0]} failed: {answer.exit_code} {answer.error_description}')
        return time.perf_counter() - start, answer

    try:
        result['load_s'], loaded = call('LOAD FILE', str(path), '', 'false', reasoner, 'false',
                                        what='LOAD')
        result['reasoning'] = loaded.error_description
        result['first_s'], _ = call('REASON', what='first REASON')
        for _ in range(cycles):
            if shape.moves_left <= 0:
                break
            spent = 0.0
            for directive in shape.cycle() + [('REASON',)]:
                seconds, _ = call(*directive, what='a cycle')
                spent += seconds
                result['steps'].setdefault(' '.join(directive[:2]), []).append(seconds)
            for question, expected in shape.questions():
                seconds, answer = call(*question, what='a question')
                spent += seconds
                result['steps'].setdefault(' '.join(question[:2]), []).append(seconds)
                result['wrong'] += _short(answer) != expected
            result['cycles'].append(spent)
        result['memory'] = node.memory()
        node.call(reference, 'DROP', timeout_s=120)
    except (TimeoutError, RuntimeError) as error:
        result['note'] = str(error)
        result['memory'] = node.memory()
    except Exception as error:  # a call that never answered within the budget
        result['note'] = f'no answer within the budget: {type(error).__name__}'
        result['memory'] = node.memory()
    return result


def measure(scratch: pathlib.Path, snapshot: CoreSnapshot, scale: str, shapes: str = 'abcd',
            reasoners: Optional[List[str]] = None, baseline=None,
            sizes: Optional[List[int]] = None) -> Dict[str, dict]:
    """results[shape][size][reasoner] = one run's figures.

    At full scale each run has a node of its own (its memory figure is that run's); the smoke
    scale shares one node, to stay short in make test. `shapes` are the letters to run,
    `reasoners` the names of REASONERS to run (all by default), `baseline` another core snapshot
    run beside each (its rows are named "... (baseline)"), `sizes` the sizes to run of those the
    scale has (all by default).
    """
    cores = [('', snapshot)] + ([(' (baseline)', baseline)] if baseline is not None else [])
    chosen = {name: reasoner for name, reasoner in REASONERS.items() if not reasoners or name in reasoners}
    results: Dict[str, dict] = {}
    # A LOAD may take the run's budget (the default reasoner limit, 30 s, stops the first reasoning at 10,000).
    limit = {'reasoner_timeout_ms': str(BUDGET_S[scale] * 1000)}
    shared = BenchNode(scratch, snapshot, parameters=limit) if scale == 'smoke' else None
    try:
        for label, make in SHAPES.items():
            if label[1] not in shapes:
                continue
            results[label] = {}
            course = label.startswith('(c)')
            for size in (COURSE_SIZES if course else SIZES)[scale]:
                if sizes and size not in sizes:
                    continue
                path = make(size).write(scratch / f'shape_{label[1]}_{size}.ofn')
                results[label][size] = {}
                runs = [(name + suffix, reasoner, core) for name, reasoner in chosen.items()
                        for suffix, core in cores]
                for index, (name, reasoner, core) in enumerate(runs):
                    if course and reasoner == WHOLE and size > WHOLE_COURSE_UP_TO:
                        results[label][size][name] = {
                            'load_s': None, 'first_s': None, 'cycles': [], 'wrong': 0, 'reasoning': '',
                            'note': f'not run: past {WHOLE_COURSE_UP_TO:,} locations the whole-ontology'
                                    ' Openllet does not finish a cycle within the budget'}
                        continue
                    node = (shared if core is snapshot else None) or BenchNode(scratch, core, parameters=limit)
                    try:
                        results[label][size][name] = _run(
                            node, path, make(size), reasoner, CYCLES[scale], BUDGET_S[scale],
                            f'shape_{label[1]}_{size}_{index}')
                    finally:
                        if node is not shared:
                            node.stop()
    finally:
        if shared is not None:
            shared.stop()
    return results


def _p50(run: dict) -> Optional[float]:
    return statistics.median(run['cycles']) * 1000 if run['cycles'] else None


def render(results: Dict[str, dict]) -> str:
    """The section's Markdown: a row per shape, size and reasoner, the whole ontology's beside."""
    lines = ['| shape | size | reasoner | LOAD | first REASON | cycles | cycle p50 | whole-ontology '
             'p50 | ratio | answers right | core peak | note |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|']
    for label, sizes in results.items():
        for size, runs in sizes.items():
            whole = _p50(runs.get('Openllet, whole ontology', {'cycles': []}))
            for name, run in runs.items():
                p50 = _p50(run)
                ratio = f'{whole / p50:.1f}x' if p50 and whole else '-'
                memory = run.get('memory', {}).get('core', {}).get('peak_mib')
                baseline = _p50(runs.get(name + ' (baseline)', {'cycles': []}))
                if baseline and p50:
                    run = dict(run, note=f'baseline p50 {baseline:.1f} ms: {baseline / p50:.1f}x '
                                         + (run['note'] or run['reasoning']))
                lines.append('| ' + ' | '.join([
                    label, f'{size:,}', name,
                    f'{run["load_s"]:.1f} s' if run['load_s'] is not None else '-',
                    f'{run["first_s"]:.1f} s' if run['first_s'] is not None else '-',
                    str(len(run['cycles'])), f'{p50:.1f} ms' if p50 else '-',
                    f'{whole:.1f} ms' if whole else '-', ratio,
                    ('yes' if not run['wrong'] else f'**{run["wrong"]} wrong**')
                    if run['cycles'] else '-',
                    f'{memory:.0f} MiB' if memory else '-',
                    (run['note'] or run['reasoning'])[:160].replace('|', '/')]) + ' |')
    return ('\n'.join(lines) + '\n\nTargets (issue 28, set for a quiet machine; the best of Openllet and '
            'HermiT in modules, measured under the load average stated above):\n'
            + targets(results) + '\n\nWhere a cycle goes (p50 of each directive over ROS 2, ms):\n'
            + where_cycles_go(results))


# Issue 28's targets at a size: cycle p50 (ms) by shape letter; LOAD + first REASON; the core's memory.
CYCLE_TARGETS_MS = {('a', 10000): 20, ('b', 10000): 20, ('d', 10000): 20, ('c', 1000): 50, ('c', 10000): 200}
LOAD_TARGET_S = (10000, 10.0)
MEMORY_TARGET_MIB = (10000, 1024)


def targets(results: Dict[str, dict]) -> str:
    """A line per target: the best modular reasoner's figure against it, met or missed."""
    lines = []
    for label, sizes in results.items():
        for size, runs in sizes.items():
            modular = {name: run for name, run in runs.items()
                       if name in ('PELLET', 'HERMIT') and run.get('cycles')}
            if not modular:
                continue
            target = CYCLE_TARGETS_MS.get((label[1], size))
            if target is not None:
                name, best = min(((n, _p50(r)) for n, r in modular.items()), key=lambda x: x[1])
                lines.append(f'- {label}, {size:,}: cycle p50 {best:.1f} ms ({name}), target <= {target} ms: '
                             + ('met' if best <= target else '**missed**'))
            if size == LOAD_TARGET_S[0]:
                name, seconds = min(((n, r['load_s'] + r['first_s']) for n, r in modular.items()),
                                    key=lambda x: x[1])
                met = seconds <= LOAD_TARGET_S[1]
                lines.append(f'- {label}, {size:,}: LOAD + first REASON {seconds:.1f} s ({name}), target '
                             f'<= {LOAD_TARGET_S[1]:.0f} s: ' + ('met' if met else '**missed**'))
                peaks = [r.get('memory', {}).get('core', {}).get('peak_mib') for r in modular.values()]
                peaks = [p for p in peaks if p]
                if peaks:
                    met = max(peaks) <= MEMORY_TARGET_MIB[1]
                    lines.append(f'- {label}, {size:,}: core peak {max(peaks):.0f} MiB, target <= '
                                 f'{MEMORY_TARGET_MIB[1]} MiB: ' + ('met' if met else '**missed**'))
    return '\n'.join(lines)


def where_cycles_go(results: Dict[str, dict]) -> str:
    """Per run: the p50 of each directive of the cycle over ROS 2."""
    lines = []
    for label, sizes in results.items():
        for size, runs in sizes.items():
            for name, run in runs.items():
                steps = ', '.join(f'{words} {statistics.median(times) * 1000:.1f}'
                                  for words, times in run.get('steps', {}).items())
                if steps:
                    lines.append(f'- {label}, {size:,}, {name}: {steps}')
    return '\n'.join(lines)


class _Baseline:
    """Another build of the core, run as it is (BenchNode needs only its jar)."""

    def __init__(self, jar: str):
        self.jar = pathlib.Path(jar).resolve()
        if not self.jar.is_file() or not (self.jar.parent / 'lib').is_dir():
            raise SystemExit(f'--baseline-jar: {self.jar} with a lib/ folder beside it is missing')


def main():
    import argparse
    import tempfile
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--smoke', action='store_true', help='tiny sizes, a few seconds')
    parser.add_argument('--shapes', default='abcd', help='the shapes to run, by letter (default abcd)')
    parser.add_argument('--sizes', nargs='*', type=int, help='the sizes to run (default all)')
    parser.add_argument('--reasoners', nargs='*', choices=list(REASONERS), help='the reasoners to run')
    parser.add_argument('--baseline-jar', help='another core build to run beside this one')
    options = parser.parse_args()
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-'))
    baseline = _Baseline(options.baseline_jar) if options.baseline_jar else None
    results = measure(scratch, CoreSnapshot(scratch), 'smoke' if options.smoke else 'full',
                      options.shapes, options.reasoners, baseline, options.sizes)
    print(render(results))
    print('\nTargets:\n' + targets(results))
    print('\nWhere a cycle goes (p50 per directive, ms):\n' + where_cycles_go(results))


if __name__ == '__main__':
    main()
