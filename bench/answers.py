# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The answers behind the benchmarks' figures: a figure of a call that answered wrongly is void.

Benchmarks whose every call must be right check each answer with `checked` as it comes (a
wrong one raises WrongAnswer and stops the run). Benchmarks that also measure alternatives
(owlready2, other ways of reasoning) record whether each answer was right instead, since a
wrong answer there is a finding; `wrong_in` reads a suite run's results and lists every
ARMOR figure among them whose answers were not all right, so the suite fails on it.
"""

from typing import Iterable, List, Optional

# What ontologies/robotics.owl answers to QUERY IND CLASS OccupiedRoom: robot1 is in the
# kitchen; alice is in corridor1, a Corridor, which is not a Room.
ROBOTICS_OCCUPIED_ROOMS = ('kitchen',)
# ELK reasons in OWL 2 EL, without inverse properties: it cannot find OccupiedRoom's members
# (ontologies/robotics.owl), so its cycle answers are incomplete by design, never stale.
INCOMPLETE_REASONERS = ('ELK',)


class WrongAnswer(RuntimeError):
    """ARMOR answered a benchmark's call wrongly: the figures around it measure nothing."""


def short_names(answer) -> List[str]:
    """The entities of an answer by short name (after '#'), sorted."""
    return sorted(iri.rstrip('>').rsplit('#', 1)[-1] for iri in answer.queried_objects)


def checked(answer, what: str, names: Optional[Iterable[str]] = None):
    """The answer, when it succeeded and (names given) holds exactly those entities.

    Raises:
        WrongAnswer: it failed, or its entities are not `names`.
    """
    if not answer.success:
        raise WrongAnswer(f'{what}: exit code {answer.exit_code}, {answer.error_description}')
    if names is not None and short_names(answer) != sorted(names):
        got, wanted = set(short_names(answer)), set(names)
        raise WrongAnswer(f'{what}: {len(answer.queried_objects)} entities, missing '
                          f'{sorted(wanted - got)[:10]}, not expected {sorted(got - wanted)[:10]}')
    return answer


def _cycles_wrong(label: str, run: dict, incomplete: bool) -> List[str]:
    """A reasoning-cycle run (bench/reasoning_cycle.py _run_mode) whose answers were not right."""
    cycles = run.get('cycles', [])
    if incomplete:
        bad = sum(1 for c in cycles if not c.get('sound', c['correct']))
        return [f'{label}: {bad} of {len(cycles)} answers name rooms nobody is in'] if bad else []
    bad = sum(1 for c in cycles if not c['correct'])
    return [f'{label}: {bad} of {len(cycles)} answers wrong'] if bad else []


def wrong_in(results: dict) -> List[str]:
    """Every ARMOR figure of a suite run (bench/suite.py) whose checked answers were not right."""
    wrong: List[str] = []
    for individuals, sides in results.get('reasoning', {}).items():
        for reasoner, modes in sides['service'].items():
            for mode, run in modes.items():
                wrong += _cycles_wrong(f'3. cycle, {individuals} individuals, {reasoner}, {mode}',
                                       run, reasoner in INCOMPLETE_REASONERS)
    speed = results.get('robot_speed', {})
    for label, run in speed.get('large', {}).items():
        wrong += _cycles_wrong(f'6. cycle at {speed["large_individuals"]} individuals, {label}',
                               run, False)
    for label, reads in speed.get('busy', {}).items():
        if reads.get('right') is False:
            wrong.append(f'6. reads while busy, {label}: a read answered wrongly')
    for label, run in speed.get('memory', {}).items():
        if run.get('correct') is False:
            wrong.append(f'6. memory, {label}: a cycle answered wrongly')
    for direction, run in speed.get('directions', {}).items():
        if direction.startswith('modular:') and run.get('wrong'):
            wrong.append(f'6. direction {direction}: {run["wrong"]} wrong answers')
    clients = results.get('default_clients', {})
    for run in ('sequential', 'flood'):
        audit = clients.get(run, {}).get('recovery', {})
        for key in ('missing', 'unexpected', 'listed_twice', 'applied_twice'):
            if audit.get(key):
                wrong.append(f'8. default clients, {run}: {audit[key]} {key.replace("_", " ")} '
                             'after the recovery')
    for row in results.get('explanations', {}).get('rows', []):
        label = f'12. explanations, {row["map"]}, {row["individuals"] or "TBox"}, {row["kind"]}'
        if 'error' in row:
            # No figure at all is no right answer either: the row's harness failed.
            wrong.append(f'{label}: no answer: {row["error"]}')
        wrong += [f'{label}: {problem}' for problem in row.get('wrong', [])]
    for individuals, by_reasoner in results.get('soma', {}).items():
        for reasoner, entry in by_reasoner.items():
            if entry['modular'].get('wrong'):
                wrong.append(f'11. SOMA, {individuals} individuals, {reasoner}: '
                             f'{entry["modular"]["wrong"]} wrong answers')
    return wrong
