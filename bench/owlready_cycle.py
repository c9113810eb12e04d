# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The reasoning cycle with owlready2, what a Python robot developer would pick instead of ARMOR.

    python bench/owlready_cycle.py ABOX_FILE INDIVIDUALS hermit|pellet CYCLES

Loads the ABox bench/abox.py wrote, reasons once, then repeats "move one agent, sync_reasoner,
ask for the OccupiedRoom instances" CYCLES times. owlready2 runs its bundled HermiT or Pellet
in a new JVM on every sync_reasoner call, which is part of what this measures. Prints one JSON
object per stage on stdout as it goes, so a caller that stops it at a time limit keeps every
figure reached so far.
"""

import json
import pathlib
import sys
import time

from abox import NS, RoboticsABox


def emit(**fields):
    print(json.dumps(fields), flush=True)


def main():
    path, individuals, reasoner, cycles = (sys.argv[1], int(sys.argv[2]), sys.argv[3],
                                           int(sys.argv[4]))
    import owlready2
    sync = {'hermit': owlready2.sync_reasoner_hermit,
            'pellet': owlready2.sync_reasoner_pellet}[reasoner]
    workload = RoboticsABox(individuals)
    world = owlready2.World()

    start = time.perf_counter()
    world.get_ontology(pathlib.Path(path).as_uri()).load()
    robotics = world.get_namespace(NS)
    emit(stage='load', seconds=time.perf_counter() - start)

    def reason():
        # Property values are not needed for the question; asking for them costs a lot more.
        sync(world, infer_property_values=False, debug=0)

    start = time.perf_counter()
    reason()
    emit(stage='first', seconds=time.perf_counter() - start)
    for _ in range(min(cycles, workload.moves_left)):
        move = workload.next_move()
        start = time.perf_counter()
        robotics[move.agent].isIn = [robotics[move.new_room]]
        changed = time.perf_counter()
        reason()
        reasoned = time.perf_counter()
        answer = sorted(room.name for room in robotics.OccupiedRoom.instances())
        queried = time.perf_counter()
        emit(stage='cycle', change=changed - start, reason=reasoned - changed,
             query=queried - reasoned, total=queried - start,
             correct=answer == workload.occupied_rooms())


if __name__ == '__main__':
    main()
