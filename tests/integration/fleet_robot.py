# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A robot of the fleet test: a Python client on its own host, driven line by line.

    ip netns exec <host> python fleet_robot.py CLIENT_NAME TIMEOUT_S

Reads one JSON request per line on stdin and answers one JSON line on stdout:
  {"op": "call", "reference": "fleet" | null, "method": "instances", "args": [...]}
      a method of Armor (reference null) or of Reference, as a program would call it;
  {"op": "batch", "reference": "fleet", "changes": [["add_individual", [...]], ...]}
      the changes sent as one atomic list;
  {"op": "watch", "reference": "fleet", "query": "QUERY IND CLASS OccupiedRoom"}
      subscribe to a query's answer and to the reference's change topic, keeping what arrives;
  {"op": "heard"}  what the watches received so far: answer changes and change events;
and answers {"value": ...} or {"error": "ArmorMountError", "exit_code": 102, "description":
"..."}, with "seconds" (the call's round trip) in both. One handler per op (OPS): a new kind
of request, such as a subscription to change events, is one more function there.
"""

import json
import sys
import time
from typing import Any, Callable, Dict, List

from armor_client import Armor, ArmorError


def call(armor: Armor, request: Dict[str, Any]) -> Any:
    target = armor if request.get('reference') is None else armor.reference(request['reference'])
    return getattr(target, request['method'])(*request.get('args', []))


def batch(armor: Armor, request: Dict[str, Any]) -> Any:
    with armor.reference(request['reference']).batch() as changes:
        for method, args in request['changes']:
            getattr(changes, method)(*args)
    return changes.consistent


HEARD: Dict[str, List[Any]] = {'answers': [], 'changes': []}
WATCHES: List[Any] = []


def watch(armor: Armor, request: Dict[str, Any]) -> Any:
    reference = armor.reference(request['reference'])
    WATCHES.append(armor.changes(lambda change: HEARD['changes'].append(
        [change.revision, change.client, [d.command for d in change.directives],
         list(change.missed)]), reference=request['reference']))
    WATCHES.append(reference.subscribe(request['query'], lambda change: HEARD['answers'].append(
        [change.revision, sorted(change.added), sorted(change.removed), change.missed])))
    return WATCHES[-1].answer


def heard(armor: Armor, request: Dict[str, Any]) -> Any:
    return HEARD


OPS: Dict[str, Callable[[Armor, Dict[str, Any]], Any]] = {
    'call': call, 'batch': batch, 'watch': watch, 'heard': heard}


def answer(armor: Armor, request: Dict[str, Any]) -> Dict[str, Any]:
    started = time.perf_counter()
    try:
        value = OPS[request['op']](armor, request)
        reply: Dict[str, Any] = {'value': value if value is None or isinstance(
            value, (bool, int, float, str, list, dict)) else repr(value)}
    except ArmorError as error:
        reply = {'error': type(error).__name__, 'exit_code': error.exit_code,
                 'description': error.description}
    reply['seconds'] = time.perf_counter() - started
    return reply


def main() -> None:
    client_name, timeout_s = sys.argv[1], float(sys.argv[2])
    with Armor(client_name, timeout_s=timeout_s, service_wait_s=60) as armor:
        print(json.dumps({'ready': True}), flush=True)
        for line in sys.stdin:
            print(json.dumps(answer(armor, json.loads(line))), flush=True)


if __name__ == '__main__':
    main()
