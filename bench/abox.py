# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A robotics ABox of any size on the TBox of ontologies/robotics.owl, and its workload.

The robot's real workload is "an agent moved: change one fact, reason, ask who is where".
`RoboticsABox` writes the ontology file and plays that workload, two moves at a time: the
first takes an agent out of a room it shares with another agent and into an empty room (the
room becomes occupied), the second walks that agent on into an occupied room (the room it left
is empty again). So the inferred answer to "which rooms are occupied" (the defined class
OccupiedRoom) changes every cycle and is known exactly beforehand, and every other cycle a
room must leave it: a reasoner that keeps a stale inference is wrong on that cycle.
"""

import dataclasses
import pathlib
from typing import Dict, List

from answers import ROBOTICS_OCCUPIED_ROOMS

REPO = pathlib.Path(__file__).resolve().parents[1]
TBOX = REPO / 'ontologies' / 'robotics.owl'
NS = 'http://www.example.org/robotics#'


@dataclasses.dataclass
class Move:
    """One changed fact: `agent` isIn `new_room` instead of `old_room`."""

    agent: str
    new_room: str
    old_room: str


class RoboticsABox:
    """N individuals: a fifth rooms in a corridor chain, the rest robots and people.

    Agents start two or more to a room in the first half of the rooms; the second half is empty,
    which leaves room for one move per empty room.
    """

    def __init__(self, individuals: int):
        if individuals < 10:
            raise ValueError('an ABox needs at least 10 individuals')
        self.individuals = individuals
        self.rooms = [f'room{i}' for i in range(individuals // 5)]
        agent_count = individuals - len(self.rooms)
        self.agents = [f'bot{i}' if i % 4 else f'person{i}' for i in range(agent_count)]
        occupied = self.rooms[:len(self.rooms) // 2]
        self.location: Dict[str, str] = {
            agent: occupied[i % len(occupied)] for i, agent in enumerate(self.agents)}
        self._occupied = occupied
        self._empty_rooms = self.rooms[len(occupied):]
        self._movable = list(self.agents)
        # The agent alone in the room it was just moved into, which the next move empties.
        self._visitor = None
        self._moves = 0

    def write(self, path: pathlib.Path) -> pathlib.Path:
        """The TBox plus this ABox as one RDF/XML file."""
        lines = []
        for index, room in enumerate(self.rooms):
            link = (f'<connectedTo rdf:resource="{NS}{self.rooms[index - 1]}"/>' if index else '')
            lines.append(f'<owl:NamedIndividual rdf:about="{NS}{room}">'
                         f'<rdf:type rdf:resource="{NS}Room"/>{link}</owl:NamedIndividual>')
        for agent in self.agents:
            kind = 'Person' if agent.startswith('person') else 'Robot'
            lines.append(f'<owl:NamedIndividual rdf:about="{NS}{agent}">'
                         f'<rdf:type rdf:resource="{NS}{kind}"/>'
                         f'<isIn rdf:resource="{NS}{self.location[agent]}"/></owl:NamedIndividual>')
        tbox = TBOX.read_text()
        path.write_text(tbox.replace('</rdf:RDF>', '\n'.join(lines) + '\n</rdf:RDF>'))
        return path

    @property
    def moves_left(self) -> int:
        """Two per room empty at the start: one fills it, the next empties it again."""
        return 2 * len(self._empty_rooms) + (self._visitor is not None)

    def next_move(self) -> Move:
        """The next move (remembered): fill the next empty room, or empty the last one filled."""
        self._moves += 1
        if self._visitor is not None:
            agent, self._visitor = self._visitor, None
            # On into an occupied room (a different one each time): the room it leaves is empty.
            move = Move(agent, self._occupied[self._moves % len(self._occupied)],
                        self.location[agent])
        else:
            if not self._empty_rooms:
                raise RuntimeError('no empty room left to move into')
            occupants: Dict[str, int] = {}
            for room in self.location.values():
                occupants[room] = occupants.get(room, 0) + 1
            while occupants[self.location[self._movable[-1]]] < 2:
                self._movable.pop()
            agent = self._movable.pop()
            move = Move(agent, self._empty_rooms.pop(0), self.location[agent])
            self._visitor = agent
        self.location[agent] = move.new_room
        return move

    def occupied_rooms(self) -> List[str]:
        """The rooms a correct reasoner must classify as OccupiedRoom, by short name."""
        return sorted(set(self.location.values()) | set(ROBOTICS_OCCUPIED_ROOMS))
