# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Writes robotics ABoxes of any size on the TBox of ontologies/robotics.owl.

Realising 800 rooms and 4,000 robots takes JFact about 6 s here: long enough for tests that
need a REASON still running while they act.
"""

import pathlib

from conftest import ONTOLOGIES


def write_abox(path: pathlib.Path, rooms: int, robots: int) -> pathlib.Path:
    """The robotics TBox plus `rooms` rooms and `robots` robots, robot i in room i % rooms."""
    tbox = (ONTOLOGIES / 'robotics.owl').read_text()
    individuals = []
    for i in range(rooms):
        individuals.append(
            f'<owl:NamedIndividual rdf:about="http://www.example.org/robotics#room{i}">'
            '<rdf:type rdf:resource="http://www.example.org/robotics#Room"/>'
            '</owl:NamedIndividual>')
    for i in range(robots):
        individuals.append(
            f'<owl:NamedIndividual rdf:about="http://www.example.org/robotics#bot{i}">'
            '<rdf:type rdf:resource="http://www.example.org/robotics#Robot"/>'
            f'<isIn rdf:resource="http://www.example.org/robotics#room{i % rooms}"/>'
            '</owl:NamedIndividual>')
    path.write_text(tbox.replace('</rdf:RDF>', '\n'.join(individuals) + '\n</rdf:RDF>'))
    return path
