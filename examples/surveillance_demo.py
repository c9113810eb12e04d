#!/usr/bin/env python3
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The surveillance robot tutorial: a robot patrols a building, asking ARMOR where to go.

The building is ontologies/surveillance.owl: rooms R1-R4, corridors C1 and C2, the charging
station E, doors between them. The clock is simulated: each step the robot moves through one
door and 10 s pass. What the robot believes comes from the reasoner:

- which rooms are Urgent (not visited for longer than its threshold: a SWRL rule with
  built-ins over the visit times and the robot's clock),
- where it can go (canReach: a SWRL rule over the doors),
- whether it is a LowBattery robot (a defined class over its battery level),

and it decides with DL queries such as ``Urgent and (inverse (canReach) value robot)``:
low battery -> the charging station; else the reachable urgent room visited longest ago;
else the reachable corridor visited longest ago. Each move is one atomic batch (position,
clock, visit time, battery), sent while the demo holds the reference's mount.

With ``--plan`` the robot follows a plan instead: each step ARMOR generates a PDDL problem
from what the reasoner infers (QUERY PDDL PROBLEM under examples/pddl/surveillance-mapping.yaml:
visit every Urgent room, then recharge; only recharge while LowBattery), pyperplan solves it
for examples/pddl/surveillance-domain.pddl, and the robot makes the plan's first move. The
rules' choice is printed beside it.

Run it against a running service (``make run`` in another terminal, then ``make demo``):
    python examples/surveillance_demo.py [--steps 12] [--plan]
"""

import argparse
import dataclasses
import pathlib
import sys
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

from armor_client import Armor, ArmorError, Reasoner, Reference

ONTOLOGY = pathlib.Path(__file__).resolve().parents[1] / 'ontologies' / 'surveillance.owl'
PDDL = pathlib.Path(__file__).resolve().parent / 'pddl'
DOMAIN = PDDL / 'surveillance-domain.pddl'
MAPPING = PDDL / 'surveillance-mapping.yaml'
REFERENCE = 'surveillance'
ROBOT = 'robot'
STEP_S = 10
DRAIN_PER_MOVE = 10
FULL_BATTERY = 100


@dataclasses.dataclass(frozen=True)
class Step:
    """One step of the patrol: what the robot believed and what it decided.

    Attributes:
        time: the simulated clock, seconds.
        location: where the robot was.
        battery: its battery level.
        low_battery: whether the reasoner classified it LowBattery.
        urgent: the rooms the reasoner found Urgent.
        reachable: the locations it could reach (its own excluded).
        target: where it decided to go (its own location: stay and recharge).
        reason: why, in words.
        plan: in planning mode, the plan the move is the first step of.
        rules: in planning mode, what the rules would have chosen: (target, reason).
    """

    time: int
    location: str
    battery: int
    low_battery: bool
    urgent: List[str]
    reachable: List[str]
    target: str
    reason: str
    plan: Tuple[Tuple[str, ...], ...] = ()
    rules: Optional[Tuple[str, str]] = None

    def __str__(self) -> str:
        line = (f't={self.time:>3}s  in {self.location:<2}  battery {self.battery:>3}%  '
                f'urgent: {" ".join(self.urgent) or "-":<12} '
                f'reach: {" ".join(self.reachable):<12} -> {self.target} ({self.reason})')
        if self.rules is not None:
            line += f'  | rules: {self.rules[0]} ({self.rules[1]})'
        return line


class Planner:
    """The planning mode: a PDDL problem of the robot's state from ARMOR, a plan from pyperplan.

    Args:
        domain: the PDDL domain file.
        mapping: the mapping file (sent as text, so the node needs no access to it).
    """

    def __init__(self, domain: pathlib.Path = DOMAIN, mapping: pathlib.Path = MAPPING):
        # examples/pddl/planning.py: runs pyperplan and checks its plans.
        sys.path.insert(0, str(PDDL))
        import planning
        import yaml
        self.planning: Any = planning
        self.domain = domain
        self.mapping: Dict[str, Any] = yaml.safe_load(mapping.read_text())

    def plan(self, reference: Reference, robot: str,
             low_battery: bool) -> Tuple[Tuple[str, ...], ...]:
        """A plan from the robot's state, replayed against the domain before it is trusted.

        Args:
            reference: the surveillance reference.
            robot: the robot individual.
            low_battery: whether the reasoner finds it LowBattery (then it only recharges).

        Returns:
            The plan's actions, each (name, argument, ...).
        """
        mapping = dict(self.mapping, goal=[['recharged', robot]]) if low_battery else self.mapping
        problem = reference.pddl_problem(mapping)
        found = self.planning.solve(self.domain, problem)
        self.planning.validate(self.domain.read_text(), problem, found.steps)
        return tuple(found.steps)


class SurveillanceRobot:
    """The robot's loop: observe through the reasoner, decide, act in one atomic batch.

    Args:
        reference: the loaded surveillance ontology.
        robot: the robot individual.
        planner: when given, the robot follows its plans (and reports the rules' choice).
    """

    def __init__(self, reference: Reference, robot: str = ROBOT,
                 planner: Optional[Planner] = None):
        self.reference = reference
        self.robot = robot
        self.planner = planner

    def reachable(self, cls: str, here: str) -> List[str]:
        """The instances of cls the robot can reach, as the reasoner answers a DL query.

        Args:
            cls: a class (Urgent, Corridor, ChargingStation, Location).
            here: the robot's location, left out (the reach rule includes it).

        Returns:
            The reachable instances, sorted.
        """
        found = self.reference.dl_instances(f'{cls} and (inverse (canReach) value {self.robot})')
        return [location for location in found if location != here]

    def step(self) -> Step:
        """Observe, decide and act once.

        Returns:
            What the robot believed and decided.
        """
        ref = self.reference
        here = ref.object_values('isIn', self.robot)[0]
        now = ref.data_values('now', self.robot)[0]
        battery = ref.data_values('batteryLevel', self.robot)[0]
        low_battery = self.robot in ref.instances('LowBattery')
        visits = {row['place']: row['time'] for row in
                  ref.sparql('SELECT ?place ?time WHERE { ?place :visitedAt ?time }')}
        beliefs = Step(now, here, battery, low_battery, ref.instances('Urgent'),
                       self.reachable('Location', here), '', '')
        target, reason = self.decide(here, low_battery, visits, now)
        if self.planner is None:
            self.act(here, target, now, battery, visits)
            return dataclasses.replace(beliefs, target=target, reason=reason)
        plan = self.planner.plan(ref, self.robot, low_battery)
        # PDDL names are lower case; the ontology's are R1, C1, E.
        places = {place.lower(): place for place in visits}
        shown = ['recharge' if action[0] == 'recharge' else places[action[3]] for action in plan]
        planned = here if plan[0][0] == 'recharge' else places[plan[0][3]]
        self.act(here, planned, now, battery, visits)
        return dataclasses.replace(beliefs, target=planned, reason='plan: ' + ' '.join(shown),
                                   plan=plan, rules=(target, reason))

    def decide(self, here: str, low_battery: bool, visits: Dict[str, int],
               now: int) -> Tuple[str, str]:
        """Choose the next location by asking the reasoner what is reachable and urgent.

        Args:
            here: the robot's location.
            low_battery: whether the reasoner says it is a LowBattery robot.
            visits: the last visit time of every location.
            now: the clock.

        Returns:
            (target, reason).
        """
        def longest_ago(places: Sequence[str]) -> str:
            return min(places, key=lambda place: (visits[place], place))

        if low_battery:
            if here in self.reference.instances('ChargingStation'):
                return here, 'low battery: recharging'
            chargers = self.reachable('ChargingStation', here)
            if chargers:
                return chargers[0], 'low battery: to the charging station'
            return (longest_ago(self.reachable('Corridor', here)),
                    'low battery: towards the charging station')
        urgent = self.reachable('Urgent', here)
        if urgent:
            room = longest_ago(urgent)
            return room, f'urgent, unvisited for {now - visits[room]} s'
        corridors = self.reachable('Corridor', here)
        if corridors:
            return longest_ago(corridors), 'no urgent room in reach: corridor visited longest ago'
        return longest_ago(self.reachable('Location', here)), 'nothing urgent in reach'

    def act(self, here: str, target: str, now: int, battery: int,
            visits: Dict[str, int]) -> None:
        """Move (or recharge): one atomic list, so the ontology never shows half a move.

        Args:
            here: the robot's location.
            target: where it goes (here: it stays and recharges).
            now: the clock before the step.
            battery: the battery level before the step.
            visits: the last visit time of every location.
        """
        arrival = now + STEP_S
        new_battery = FULL_BATTERY if target == here else battery - DRAIN_PER_MOVE
        with self.reference.batch() as batch:
            if target != here:
                batch.replace_object_value('isIn', self.robot, target, here)
            batch.replace_data_value('now', self.robot, arrival, now, 'LONG')
            batch.replace_data_value('visitedAt', target, arrival, visits[target], 'LONG')
            batch.replace_data_value('batteryLevel', self.robot, new_battery, battery)


def load_fresh(armor: Armor, name: str = REFERENCE,
               ontology: pathlib.Path = ONTOLOGY) -> Reference:
    """Load the tutorial's ontology with Pellet, dropping a reference left by an earlier run.

    Args:
        armor: the session.
        name: the reference name.
        ontology: the ontology file.

    Returns:
        The reference, in its initial state.
    """
    if name in armor.references():
        armor.reference(name).drop()
    return armor.load_file(name, str(ontology), reasoner=Reasoner.PELLET)


def run(armor: Armor, steps: int, name: str = REFERENCE,
        report: Optional[Callable[[Step], None]] = None, plan: bool = False) -> List[Step]:
    """Run the patrol for some steps while holding the reference's mount.

    Args:
        armor: the session.
        steps: how many steps.
        name: the reference name to load the ontology as.
        report: called with each step as it happens.
        plan: follow plans of a PDDL planner instead of the rules.

    Returns:
        The steps.
    """
    reference = load_fresh(armor, name)
    robot = SurveillanceRobot(reference, planner=Planner() if plan else None)
    done: List[Step] = []
    with reference.mounted():
        for _ in range(steps):
            done.append(robot.step())
            if report:
                report(done[-1])
    return done


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the demo from the command line.

    Args:
        argv: the arguments (default: sys.argv[1:]).

    Returns:
        The exit status: 0, or 1 when ARMOR failed.
    """
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--steps', type=int, default=12, help='how many steps (default: 12)')
    parser.add_argument('--reference', default=REFERENCE,
                        help=f'reference name to load the ontology as (default: {REFERENCE})')
    parser.add_argument('--namespace', default='', help='namespace of the ARMOR node')
    parser.add_argument('--plan', action='store_true',
                        help='move as plans of a PDDL planner say (pyperplan over the problem '
                        'ARMOR generates), the rules\' choice printed beside')
    args = parser.parse_args(argv)
    print(f'Loading {ONTOLOGY.name} as "{args.reference}" (Pellet); the robot starts in E.')
    if args.plan:
        print(f'Planning: {MAPPING.name} for {DOMAIN.name}; each step follows the first action '
              'of a new plan.')
    try:
        with Armor('surveillance_demo', namespace=args.namespace) as armor:
            run(armor, args.steps, args.reference, report=print, plan=args.plan)
    except ArmorError as error:
        print(f'ARMOR failed: {error}', file=sys.stderr)
        return 1
    print(f'Done. Inspect what the robot left behind: armor shell {args.reference}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
