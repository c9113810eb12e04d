# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Kill the core or the whole node at random moments while clients write; count what was lost.

    python tests/integration/fault_injection.py --kills 100 --target core
    python tests/integration/fault_injection.py --kills 100 --target node
    python tests/integration/fault_injection.py --recovery-individuals 10000

A writer sends single ADDs, atomic lists of two ADDs, and lists that must fail, and records
which were acknowledged. After the kills the reference is audited: every acknowledged change
must be there, no list may be half there, and nothing of a failed list may be there.
"""

import argparse
import dataclasses
import os
import pathlib
import random
import signal
import sys
import tempfile
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

from conftest import NS, start_node  # noqa: E402
from ontology_factory import write_abox  # noqa: E402

REFERENCE = 'durable'
CALL_TIMEOUT_S = 15.0


@dataclasses.dataclass
class Audit:
    kills: int = 0
    acknowledged_singles: int = 0
    acknowledged_lists: int = 0
    failed_lists: int = 0
    unanswered: int = 0
    lost: int = 0
    half_applied_lists: int = 0
    failed_list_leaks: int = 0
    recovery_s: list = dataclasses.field(default_factory=list)

    def summary(self) -> str:
        worst = max(self.recovery_s) if self.recovery_s else 0.0
        median = sorted(self.recovery_s)[len(self.recovery_s) // 2] if self.recovery_s else 0.0
        return (f'kills={self.kills} acknowledged: singles={self.acknowledged_singles} '
                f'lists={self.acknowledged_lists}; failed lists={self.failed_lists}; '
                f'unanswered={self.unanswered}; LOST={self.lost} '
                f'HALF-APPLIED LISTS={self.half_applied_lists} '
                f'FAILED-LIST LEAKS={self.failed_list_leaks}; recovery median {median:.2f} s, '
                f'worst {worst:.2f} s')


class Campaign:
    """One node, one writer, one killer; the node is restarted when the target is the node."""

    def __init__(self, scratch: pathlib.Path, target: str, seed: int):
        from armor_client import ArmorTransport
        self.scratch = scratch
        self.target = target
        self.random = random.Random(seed)
        self.namespace = f'/durable_{target}'
        self.node = start_node(scratch, namespace=self.namespace)
        self.armor = ArmorTransport(namespace=self.namespace, service_wait_s=120.0)
        self.audit = Audit()
        self.singles, self.lists, self.failed = set(), set(), set()
        self.stop = threading.Event()
        ontology = write_abox(scratch / 'durable.owl', rooms=5, robots=5)
        loaded = self._call('LOAD', 'FILE', '', str(ontology), '', 'false', 'HERMIT', 'true',
                            timeout_s=300)
        assert loaded.success, f'{loaded.exit_code} {loaded.error_description}'

    def _call(self, command, primary, secondary, *args, timeout_s=CALL_TIMEOUT_S):
        from armor_client import directive
        return self.armor.call(directive('writer', REFERENCE, command, primary, secondary, args),
                               timeout_s=timeout_s)

    def write(self) -> None:
        from armor_client import ArmorError, directive
        i = 0
        while not self.stop.is_set():
            i += 1
            try:
                if i % 7 == 0:
                    answer = self.armor.call_list([
                        directive('writer', REFERENCE, 'ADD', 'IND', 'CLASS', [f'bad{i}', 'Robot']),
                        directive('writer', REFERENCE, 'ADD', 'IND', 'CLASS', [f'bad{i}'])],
                        timeout_s=CALL_TIMEOUT_S)
                    self.failed.add(i)
                elif i % 5 == 0:
                    answer = self.armor.call_list([
                        directive('writer', REFERENCE, 'ADD', 'IND', 'CLASS', [f'pair{i}a', 'Robot']),
                        directive('writer', REFERENCE, 'ADD', 'IND', 'CLASS', [f'pair{i}b', 'Robot'])],
                        timeout_s=CALL_TIMEOUT_S)
                    if answer.success:
                        self.lists.add(i)
                else:
                    if self._call('ADD', 'IND', 'CLASS', f'single{i}', 'Robot').success:
                        self.singles.add(i)
            except ArmorError:
                self.audit.unanswered += 1

    def kill_once(self) -> None:
        time.sleep(self.random.uniform(0.2, 1.2))
        if self.target == 'core':
            os.kill(self.node.core_pid(), signal.SIGKILL)
        else:
            self.node.process.kill()
            self.node.process.wait()
            self.node.stop()
            self.node = start_node(self.scratch, namespace=self.namespace)
        self.audit.kills += 1
        started = time.monotonic()
        while time.monotonic() - started < 300:
            try:
                if self._call('QUERY', 'IND', 'CLASS', 'Robot').success:
                    break
            except Exception:  # the node may not be discoverable yet
                pass
            time.sleep(0.05)
        self.audit.recovery_s.append(time.monotonic() - started)

    def run(self, kills: int) -> Audit:
        writer = threading.Thread(target=self.write, daemon=True)
        writer.start()
        try:
            for _ in range(kills):
                self.kill_once()
            time.sleep(0.5)
        finally:
            self.stop.set()
            writer.join(timeout=60)
        present = set(self._call('QUERY', 'IND', 'CLASS', 'Robot').queried_objects)

        def has(name):
            return f'<{NS}{name}>' in present
        self.audit.acknowledged_singles = len(self.singles)
        self.audit.acknowledged_lists = len(self.lists)
        self.audit.failed_lists = len(self.failed)
        self.audit.lost = sum(not has(f'single{i}') for i in self.singles) + sum(
            not (has(f'pair{i}a') and has(f'pair{i}b')) for i in self.lists)
        attempted_pairs = {int(n.split('pair')[1][:-2]) for n in present if '#pair' in n}
        self.audit.half_applied_lists = sum(has(f'pair{i}a') != has(f'pair{i}b')
                                            for i in attempted_pairs)
        self.audit.failed_list_leaks = sum(has(f'bad{i}') for i in self.failed)
        return self.audit

    def close(self) -> None:
        self.armor.close()
        self.node.stop()


def measure_recovery(scratch: pathlib.Path, individuals: int) -> float:
    """Seconds from SIGKILL of the core until a reference of this many individuals answers."""
    from armor_client import ArmorTransport, directive
    node = start_node(scratch, namespace='/recovery')
    armor = ArmorTransport(namespace='/recovery', service_wait_s=120.0)
    try:
        rooms = individuals // 5
        abox = write_abox(scratch / 'big.owl', rooms=rooms, robots=individuals - rooms)
        assert armor.call(directive('m', 'big', 'LOAD', 'FILE', '',
                                    [str(abox), '', 'false', 'ELK', 'true']),
                          timeout_s=600).success
        for i in range(200):
            armor.call(directive('m', 'big', 'ADD', 'IND', 'CLASS', [f'extra{i}', 'Robot']))
        os.kill(node.core_pid(), signal.SIGKILL)
        started = time.monotonic()
        while True:
            answer = armor.call(directive('m', 'big', 'QUERY', 'IND', 'CLASS', ['Robot']),
                                timeout_s=600)
            if answer.success:
                assert len(answer.queried_objects) == individuals - rooms + 201
                return time.monotonic() - started
            time.sleep(0.05)
    finally:
        armor.close()
        node.stop()


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--kills', type=int, default=100)
    parser.add_argument('--target', choices=('core', 'node'), default='core')
    parser.add_argument('--seed', type=int, default=1)
    parser.add_argument('--recovery-individuals', type=int, default=0,
                        help='instead of kills, time the recovery of a reference this large')
    options = parser.parse_args()
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-faults-'))
    if options.recovery_individuals:
        seconds = measure_recovery(scratch, options.recovery_individuals)
        print(f'recovery of a reference of {options.recovery_individuals} individuals '
              f'(+200 journaled changes) after SIGKILL of the core: {seconds:.2f} s')
        return 0
    campaign = Campaign(scratch, options.target, options.seed)
    try:
        audit = campaign.run(options.kills)
    finally:
        campaign.close()
    print(f'target={options.target} {audit.summary()}')
    return 0 if audit.lost == audit.half_applied_lists == audit.failed_list_leaks == 0 else 1


if __name__ == '__main__':
    sys.exit(main())
