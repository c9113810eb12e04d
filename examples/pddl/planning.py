# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Solve the problems ARMOR generates, and check the plans, for STRIPS domains with typing.

- ``solve(domain, problem)`` runs pyperplan (installed by tools/setup.sh) as a separate
  program and reads the plan it writes;
- ``validate(domain, problem, plan)`` replays a plan against the domain's semantics: every
  step names an action of the domain with objects of the right types, its preconditions hold
  in the state it is applied to, its effects give the next state, and the goal holds at the
  end. It also checks that the problem only uses the domain's predicates, with their arity
  and types. It knows STRIPS with typing (positive conjunctive preconditions and goals, add
  and delete effects), which is what the surveillance domain and pyperplan use.

    python examples/pddl/planning.py DOMAIN PROBLEM    # prints the plan, validated
"""

import dataclasses
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time
from typing import Dict, FrozenSet, List, Optional, Sequence, Set, Tuple, Union

Atom = Tuple[str, ...]
Step = Tuple[str, ...]
Text = Union[str, pathlib.Path]


class PlanningError(Exception):
    """The planner found no plan, or a plan or problem does not fit the domain."""


@dataclasses.dataclass
class Plan:
    """A plan and what finding it cost.

    Attributes:
        steps: the actions in order, each (name, argument, ...), lower case.
        search_s: the planner's own search time, as it reports it.
        wall_s: the wall time of the planner's process (start-up, parsing, grounding, search).
    """

    steps: List[Step]
    search_s: float
    wall_s: float

    def __len__(self) -> int:
        return len(self.steps)


def solve(domain: Text, problem_text: str, search: str = 'astar', heuristic: str = 'lmcut',
          timeout_s: float = 600.0) -> Plan:
    """Solve a problem with pyperplan.

    Args:
        domain: the domain file.
        problem_text: the problem (as QUERY PDDL PROBLEM answers it).
        search: pyperplan's search (astar with lmcut finds shortest plans; gbf is faster).
        heuristic: pyperplan's heuristic.
        timeout_s: the longest wait for the planner.

    Returns:
        The plan.

    Raises:
        PlanningError: the planner found none (its last lines say why).
    """
    with tempfile.TemporaryDirectory(prefix='armor-plan-') as work:
        problem = pathlib.Path(work) / 'problem.pddl'
        problem.write_text(problem_text)
        started = time.monotonic()
        run = subprocess.run(
            [sys.executable, '-m', 'pyperplan', '-l', 'info', '-s', search, '-H', heuristic,
             str(pathlib.Path(domain).resolve()), str(problem)],
            capture_output=True, text=True, timeout=timeout_s,
            # pyperplan breaks ties between equally short plans by set order, which Python's
            # per-process string hashing shuffles: a fixed seed gives one plan per problem.
            env={**os.environ, 'PYTHONHASHSEED': '0'})
        wall_s = time.monotonic() - started
        solution = problem.with_name(problem.name + '.soln')
        if not solution.exists():
            tail = '\n'.join((run.stdout + run.stderr).splitlines()[-5:])
            raise PlanningError(f'pyperplan found no plan (exit {run.returncode}):\n{tail}')
        steps = [tuple(line.strip().strip('()').lower().split())
                 for line in solution.read_text().splitlines() if line.strip()]
    found = re.search(r'Search time: ([0-9.]+)', run.stdout + run.stderr)
    return Plan(steps, float(found.group(1)) if found else wall_s, wall_s)


# ------------------------------------------------------------------ reading PDDL


def _tokens(text: str) -> List[str]:
    text = re.sub(r';[^\n]*', ' ', text.lower())
    return re.findall(r'[()]|[^\s()]+', text)


def _tree(text: str) -> list:
    """The first s-expression of the text as nested lists of words."""
    stack: List[list] = [[]]
    for token in _tokens(text):
        if token == '(':
            stack.append([])
        elif token == ')':
            if len(stack) < 2:
                raise PlanningError('unbalanced parentheses')
            done = stack.pop()
            stack[-1].append(done)
        else:
            stack[-1].append(token)
    if len(stack) != 1 or not stack[0]:
        raise PlanningError('unbalanced parentheses or no expression')
    return stack[0][0]


def _sections(tree: list) -> Dict[str, list]:
    return {item[0]: item[1:] for item in tree[2:] if isinstance(item, list) and item}


def _typed(words: Sequence[str]) -> List[Tuple[str, str]]:
    """(name, type) of a typed list such as ``a b - room c - door d`` (untyped: object)."""
    typed, pending = [], []
    items = list(words)
    i = 0
    while i < len(items):
        if items[i] == '-':
            typed += [(name, items[i + 1]) for name in pending]
            pending = []
            i += 2
        else:
            pending.append(items[i])
            i += 1
    return typed + [(name, 'object') for name in pending]


def _conjunction(tree: list, where: str) -> List[list]:
    """The atoms of (and ...) or of one atom; anything else is beyond STRIPS."""
    if not tree:
        return []
    if tree[0] == 'and':
        return [atom for part in tree[1:] for atom in _conjunction(part, where)]
    if tree[0] in ('or', 'imply', 'exists', 'forall', 'when', '=', '<', '>', '<=', '>='):
        raise PlanningError(f'{where}: ({tree[0]} ...) is beyond STRIPS')
    return [tree]


@dataclasses.dataclass
class Action:
    """One action of a domain: typed parameters, preconditions, add and delete effects."""

    name: str
    parameters: List[Tuple[str, str]]
    preconditions: List[list]
    adds: List[list]
    deletes: List[list]


@dataclasses.dataclass
class Domain:
    """A STRIPS domain with typing."""

    name: str
    parents: Dict[str, str]
    predicates: Dict[str, List[str]]
    actions: Dict[str, Action]

    @classmethod
    def parse(cls, text: str) -> 'Domain':
        """Read a domain's text."""
        tree = _tree(text)
        if tree[:1] != ['define'] or tree[1][:1] != ['domain']:
            raise PlanningError('not a PDDL domain')
        sections = _sections(tree)
        parents = dict(_typed(sections.get(':types', [])))
        predicates = {atom[0]: [kind for _, kind in _typed(atom[1:])]
                      for atom in sections.get(':predicates', [])}
        actions = {}
        for item in tree[2:]:
            if not (isinstance(item, list) and item[:1] == [':action']):
                continue
            fields = dict(zip(item[2::2], item[3::2]))
            effects = _effects(fields.get(':effect', []), item[1])
            actions[item[1]] = Action(item[1], _typed(fields.get(':parameters', [])),
                                      _conjunction(fields.get(':precondition', []), item[1]),
                                      *effects)
        return cls(tree[1][1], parents, predicates, actions)

    def is_a(self, kind: str, wanted: str) -> bool:
        """Whether objects of type `kind` are of type `wanted` (through the type hierarchy)."""
        seen = set()
        while kind not in seen:
            if kind == wanted or wanted == 'object':
                return True
            seen.add(kind)
            kind = self.parents.get(kind, 'object')
        return False


def _effects(tree: list, action: str) -> Tuple[List[list], List[list]]:
    adds, deletes = [], []
    parts = tree[1:] if tree[:1] == ['and'] else ([tree] if tree else [])
    for part in parts:
        if part[:1] == ['not']:
            deletes.append(part[1])
        elif part[:1] in (['when'], ['forall'], ['increase'], ['decrease'], ['assign']):
            raise PlanningError(f'{action}: ({part[0]} ...) is beyond STRIPS')
        else:
            adds.append(part)
    return adds, deletes


@dataclasses.dataclass
class Problem:
    """A problem: its objects with their types, its initial facts and its goal."""

    name: str
    domain: str
    objects: Dict[str, str]
    init: FrozenSet[Atom]
    goal: List[Atom]

    @classmethod
    def parse(cls, text: str) -> 'Problem':
        """Read a problem's text (numeric fluents of :init are left out)."""
        tree = _tree(text)
        if tree[:1] != ['define'] or tree[1][:1] != ['problem']:
            raise PlanningError('not a PDDL problem')
        sections = _sections(tree)
        objects = dict(_typed(sections.get(':objects', [])))
        init = frozenset(tuple(atom) for atom in sections.get(':init', []) if atom[:1] != ['='])
        goal = [tuple(atom) for atom in _conjunction(
            (sections.get(':goal') or [[]])[0], 'goal')]
        return cls(tree[1][1], sections[':domain'][0], objects, init, goal)


# ------------------------------------------------------------------ checking


def check_problem(domain: Domain, problem: Problem) -> None:
    """Every fact of the problem uses a predicate of the domain with objects of its types.

    Raises:
        PlanningError: naming the first fact that does not fit.
    """
    if problem.domain != domain.name:
        raise PlanningError(f'the problem is for domain {problem.domain}, not {domain.name}')
    for where, facts in (('init', sorted(problem.init)), ('goal', problem.goal)):
        for fact in facts:
            _check_atom(domain, problem, fact, f'{where} fact ({" ".join(fact)})')


def _check_atom(domain: Domain, problem: Problem, atom: Sequence[str], where: str) -> None:
    kinds = domain.predicates.get(atom[0])
    if kinds is None:
        raise PlanningError(f'{where}: the domain has no predicate {atom[0]}')
    if len(kinds) != len(atom) - 1:
        raise PlanningError(f'{where}: {atom[0]} takes {len(kinds)} argument(s)')
    for argument, kind in zip(atom[1:], kinds):
        if argument not in problem.objects:
            raise PlanningError(f'{where}: {argument} is no object of the problem')
        if not domain.is_a(problem.objects[argument], kind):
            raise PlanningError(f'{where}: {argument} is a {problem.objects[argument]}, not a '
                                f'{kind}')


def validate(domain_text: str, problem_text: str, steps: Sequence[Step]) -> Set[Atom]:
    """Replay a plan and check it reaches the goal.

    Args:
        domain_text: the domain.
        problem_text: the problem.
        steps: the plan's actions, each (name, argument, ...).

    Returns:
        The state the plan ends in.

    Raises:
        PlanningError: naming the first step that cannot be applied, or the goal facts that
            do not hold at the end.
    """
    domain, problem = Domain.parse(domain_text), Problem.parse(problem_text)
    check_problem(domain, problem)
    state: Set[Atom] = set(problem.init)
    for number, step in enumerate(steps, 1):
        where = f'step {number} ({" ".join(step)})'
        action = domain.actions.get(step[0])
        if action is None:
            raise PlanningError(f'{where}: the domain has no action {step[0]}')
        if len(step) - 1 != len(action.parameters):
            raise PlanningError(f'{where}: {action.name} takes {len(action.parameters)} '
                                'argument(s)')
        binding: Dict[str, str] = {}
        for (parameter, kind), argument in zip(action.parameters, step[1:]):
            if argument not in problem.objects:
                raise PlanningError(f'{where}: {argument} is no object of the problem')
            if not domain.is_a(problem.objects[argument], kind):
                raise PlanningError(f'{where}: {argument} is a {problem.objects[argument]}, '
                                    f'not a {kind}')
            binding[parameter] = argument

        def ground(atom: list) -> Atom:
            return tuple(binding.get(word, word) for word in atom)

        missing = [ground(atom) for atom in action.preconditions if ground(atom) not in state]
        if missing:
            raise PlanningError(f'{where}: precondition(s) do not hold: '
                                + ' '.join(f'({" ".join(atom)})' for atom in missing))
        state -= {ground(atom) for atom in action.deletes}
        state |= {ground(atom) for atom in action.adds}
    unmet = [goal for goal in problem.goal if goal not in state]
    if unmet:
        raise PlanningError('the goal does not hold after the plan: '
                            + ' '.join(f'({" ".join(atom)})' for atom in unmet))
    return state


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Solve DOMAIN PROBLEM, validate the plan and print it."""
    args = list(sys.argv[1:] if argv is None else argv)
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    domain, problem_text = pathlib.Path(args[0]), pathlib.Path(args[1]).read_text()
    plan = solve(domain, problem_text)
    validate(domain.read_text(), problem_text, plan.steps)
    for step in plan.steps:
        print(f'({" ".join(step)})')
    print(f'; {len(plan)} steps, valid; search {plan.search_s:.3f} s, planner {plan.wall_s:.2f} s')
    return 0


if __name__ == '__main__':
    sys.exit(main())
