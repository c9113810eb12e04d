# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A kitchen ABox of any size on KnowRob's upper ontology (SOMA-HOME on DUL), and its workload.

The shape a KnowRob user moving to ARMOR writes: a small ontology of their own that imports
SOMA-HOME (by its IRI, resolved offline through a catalog beside the file), with containers
(cupboards, drawers, refrigerators, dishwashers), tableware (cups, bowls, plates, glasses,
forks, spoons) inside them through SOMA:isInsideOf (transitive, the inverse of
SOMA:containsObject), drawers inside cupboards, agents (robots and people) inside kitchens,
and one defined class over containment:

    kitchen:ContainerWithCup = SOMA:DesignedContainer and (SOMA:containsObject some SOMA:Cup)

Only the inverse (isInsideOf) is asserted, and a cupboard holds a cup only through one of its
drawers, so answers need the inverse and the transitivity. `KitchenABox` knows the right answer
at every step: each move takes a cup out of a container that holds another cup and puts it into
an empty container, so the answer grows by one container per move.

The SOMA files are not in the repository: `soma_data()` finds them beside the checkout
(`shared/data/soma` in a parent folder: /work/shared for /work/main and /work/wt/NAME) or where
ARMOR_SOMA_DATA says. Tests and benchmarks copy them (926 KB, with their catalog) into their
scratch folder beside the kitchen file, so the node reads nothing outside its allowed folders.
"""

import dataclasses
import os
import pathlib
import shutil
from typing import Dict, List

KITCHEN = 'http://www.example.org/kitchen#'
KITCHEN_IRI = 'http://www.example.org/kitchen'
SOMA = 'http://www.ease-crc.org/ont/SOMA.owl#'
DUL = 'http://www.ontologydesignpatterns.org/ont/dul/DUL.owl#'
SOMA_HOME_IRI = 'http://www.ease-crc.org/ont/SOMA-HOME.owl'
DEFINED_CLASS = 'ContainerWithCup'

CONTAINER_KINDS = ('Refrigerator', 'Dishwasher', 'Drawer')
TABLEWARE_KINDS = ('Cup', 'Bowl', 'Plate', 'Glass', 'Fork', 'Spoon')


def soma_data() -> pathlib.Path:
    """The folder of SOMA-HOME.owl, its import closure and catalog (see the module docstring)."""
    configured = os.environ.get('ARMOR_SOMA_DATA')
    candidates = [pathlib.Path(configured)] if configured else [
        parent / 'shared' / 'data' / 'soma'
        for parent in pathlib.Path(__file__).resolve().parents]
    for folder in candidates:
        if (folder / 'SOMA-HOME.owl').is_file() and (folder / 'catalog-v001.xml').is_file():
            return folder
    raise FileNotFoundError('SOMA-HOME.owl and its catalog were not found in '
                            + ', '.join(str(c) for c in candidates)
                            + ' (set ARMOR_SOMA_DATA to the folder that holds them)')


@dataclasses.dataclass
class Move:
    """One changed fact: `item` isInsideOf `new` instead of `old`."""

    item: str
    new: str
    old: str


class KitchenABox:
    """`individuals` named individuals: a kitchen per 100, a twentieth agents, a fifth
    containers (every third a cupboard with two drawers, the rest refrigerators, dishwashers or
    drawers), the rest tableware, one kind after another (a sixth cups).

    Tableware goes into the first half of the containers that can hold it (not cupboards: their
    drawers do), two or more per container; the second half stays empty for the moves.
    """

    def __init__(self, individuals: int):
        if individuals < 40:
            raise ValueError('a kitchen ABox needs at least 40 individuals')
        self.individuals = individuals
        self.kitchens = [f'kitchen{i}' for i in range(max(1, individuals // 100))]
        agent_count = individuals // 20
        self.agents = [f'robot{i}' if i % 2 == 0 else f'person{i}' for i in range(agent_count)]
        self.kind: Dict[str, str] = {}
        self.inside: Dict[str, str] = {}
        containers: List[str] = []
        holders: List[str] = []
        container_budget = individuals // 5
        while len(containers) + 3 <= container_budget:
            number = len(containers)
            if number % 9 == 0:
                cupboard = f'cupboard{number}'
                self.kind[cupboard] = 'Cupboard'
                containers.append(cupboard)
                for side in range(2):
                    drawer = f'drawer{number}_{side}'
                    self.kind[drawer] = 'Drawer'
                    self.inside[drawer] = cupboard
                    containers.append(drawer)
                    holders.append(drawer)
            else:
                kind = CONTAINER_KINDS[number % len(CONTAINER_KINDS)]
                name = f'{kind.lower()}{number}'
                self.kind[name] = kind
                containers.append(name)
                holders.append(name)
        self.containers = containers
        used = len(self.kitchens) + len(self.agents) + len(containers)
        self.tableware = []
        for i in range(individuals - used):
            kind = TABLEWARE_KINDS[i % len(TABLEWARE_KINDS)]
            name = f'{kind.lower()}{i}'
            self.kind[name] = kind
            self.tableware.append(name)
        filled = holders[:len(holders) // 2]
        for i, item in enumerate(self.tableware):
            self.inside[item] = filled[i % len(filled)]
        for i, agent in enumerate(self.agents):
            self.inside[agent] = self.kitchens[i % len(self.kitchens)]
        self._empty = [h for h in holders[len(holders) // 2:]]
        self._movable = [item for item in self.tableware if self.kind[item] == 'Cup']

    def write(self, folder: pathlib.Path, name: str = 'kitchen') -> pathlib.Path:
        """The kitchen ontology (functional syntax) in `folder`, beside a copy of SOMA's files and
        catalog (the node reads only allowed folders: a test's or benchmark's scratch); its path."""
        folder.mkdir(parents=True, exist_ok=True)
        for source in soma_data().iterdir():
            if source.suffix in ('.owl', '.xml') and not (folder / source.name).exists():
                shutil.copyfile(source, folder / source.name)
        lines = [
            f'Prefix(:=<{KITCHEN}>)', f'Prefix(SOMA:=<{SOMA}>)', f'Prefix(dul:=<{DUL}>)',
            f'Ontology(<{KITCHEN_IRI}>', f'Import(<{SOMA_HOME_IRI}>)',
            f'Declaration(Class(:{DEFINED_CLASS}))',
            f'EquivalentClasses(:{DEFINED_CLASS} ObjectIntersectionOf(SOMA:DesignedContainer '
            'ObjectSomeValuesFrom(SOMA:containsObject SOMA:Cup)))',
        ]
        for kitchen in self.kitchens:
            lines.append(f'Declaration(NamedIndividual(:{kitchen}))')
            lines.append(f'ClassAssertion(SOMA:Kitchen :{kitchen})')
        for agent in self.agents:
            kind = 'SOMA:ArtificialAgent' if agent.startswith('robot') else 'dul:Person'
            lines.append(f'Declaration(NamedIndividual(:{agent}))')
            lines.append(f'ClassAssertion({kind} :{agent})')
        for item in self.containers + self.tableware:
            lines.append(f'Declaration(NamedIndividual(:{item}))')
            lines.append(f'ClassAssertion(SOMA:{self.kind[item]} :{item})')
        for item, container in self.inside.items():
            lines.append(f'ObjectPropertyAssertion(SOMA:isInsideOf :{item} :{container})')
        lines.append(')')
        path = folder / f'{name}.ofn'
        path.write_text('\n'.join(lines) + '\n')
        return path

    @property
    def moves_left(self) -> int:
        return len(self._empty)

    def next_move(self) -> Move:
        """Move a cup that shares its container with another cup into the next empty one."""
        if not self._empty:
            raise RuntimeError('no empty container left to move into')
        cups: Dict[str, int] = {}
        for item in self._movable:
            cups[self.inside[item]] = cups.get(self.inside[item], 0) + 1
        while cups[self.inside[self._movable[-1]]] < 2:
            self._movable.pop()
        cup = self._movable.pop()
        move = Move(cup, self._empty.pop(0), self.inside[cup])
        self.inside[cup] = move.new
        return move

    def containers_with_cup(self) -> List[str]:
        """The individuals a complete reasoner finds in ContainerWithCup, by short name."""
        found = set()
        for item, container in self.inside.items():
            if self.kind.get(item) != 'Cup':
                continue
            while container is not None:  # containment is transitive
                found.add(container)
                container = self.inside.get(container)
        return sorted(found)
