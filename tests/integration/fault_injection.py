# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Faults under a writing node; count what was lost (nothing acknowledged may be).

    python tests/integration/fault_injection.py --kills 100 --target core   # or --target node
    python tests/integration/fault_injection.py --recovery-individuals 10000
    python tests/integration/fault_injection.py --storage                    # everything below
    python tests/integration/fault_injection.py --full-disk 400 --read-only 50 --junit-rounds 3

Kills: a writer sends single ADDs, atomic lists of two ADDs, and lists that must fail, and
records which were acknowledged; after the kills every acknowledged change must be there, no
list half there, nothing of a failed list there.

Storage (run as root: it mounts filesystems): the node's state directory on a 4 MiB tmpfs that
is filled up, then freed; on an ext4 image that turns read-only under the node (an ext4 error
with errors=remount-ro); then the JUnit campaigns (StorageFaultsTest, DamagedFilesTest) that fail
every I/O call in turn, cut the power at every call, fail every read of a restore and flip
bytes of every file, lengthened. Printed: faults injected by kind, changes attempted,
acknowledged, refused, acknowledged then lost (must be 0), restores that reported damage,
restores that silently differed (must be 0), seconds until changes are accepted again once
space returns.
"""

import argparse
import dataclasses
import errno
import json
import os
import pathlib
import random
import re
import signal
import subprocess
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


@dataclasses.dataclass
class StorageAudit:
    fault: str
    attempted: int = 0
    acknowledged: int = 0
    refused: int = 0
    other_codes: list = dataclasses.field(default_factory=list)
    memory_differs: int = 0
    refusal_reported: bool = False
    recovery_s: object = None
    lost: int = 0
    refused_present: int = 0
    damage_after_restart: list = dataclasses.field(default_factory=list)

    def summary(self) -> str:
        recovery = 'n/a' if self.recovery_s is None else f'{self.recovery_s:.3f} s'
        return (f'{self.fault}: changes attempted={self.attempted} acknowledged={self.acknowledged} '
                f'refused (225)={self.refused} other codes={self.other_codes} '
                f'refused but in memory={self.memory_differs} refusal in GET STATE DAMAGE='
                f'{self.refusal_reported}; accepted again after space returned: {recovery}; after a '
                f'restart: ACKNOWLEDGED THEN LOST={self.lost} refused but present='
                f'{self.refused_present} damage reported={len(self.damage_after_restart)}')


class FilesystemFaults:
    """A node whose state directory is on a small filesystem this process mounts (as root)."""

    NAMESPACE = '/storage_faults'

    def __init__(self, scratch: pathlib.Path):
        self.scratch = scratch
        self.mount = scratch / 'fs'
        self.mount.mkdir()
        self.image = None
        self.node = None
        self.armor = None

    def _start(self, *extra):
        from armor_client import ArmorTransport
        self.node = start_node(self.scratch, '-p', f'state_dir:={self.mount / "state"}',
                               '-p', 'checkpoint_every_changes:=5', *extra,
                               namespace=self.NAMESPACE)
        if self.armor is None:
            self.armor = ArmorTransport(namespace=self.NAMESPACE, service_wait_s=120.0)
        started = time.monotonic()
        while True:  # a restarted node takes a while to be discovered again
            try:
                if self._call('', 'GET', 'ALL', 'REFS').success:
                    return
            except Exception:  # noqa: BLE001 - retried until the deadline
                pass
            assert time.monotonic() - started < 300, self.node.log()
            time.sleep(0.2)

    def _call(self, reference, command, primary='', secondary='', *args):
        from armor_client import directive
        return self.armor.call(directive('writer', reference, command, primary, secondary,
                                         list(args)), timeout_s=CALL_TIMEOUT_S * 4)

    def _robots(self) -> set:
        answer = self._call('robotics', 'QUERY', 'IND', 'CLASS', 'Robot')
        assert answer.success, answer.error_description
        return {name[len(NS) + 1:-1] for name in answer.queried_objects}

    def _damage(self) -> list:
        return [json.loads(line) for line in
                self._call('', 'GET', 'STATE', 'DAMAGE').queried_objects]

    def _send(self, audit, name) -> bool:
        audit.attempted += 1
        answer = self._call('robotics', 'ADD', 'IND', 'CLASS', name, 'Robot')
        if answer.success:
            audit.acknowledged += 1
            return True
        if answer.exit_code == 225 and answer.error_description.startswith('not durable: '):
            audit.refused += 1
        else:
            audit.other_codes.append(answer.exit_code)
        return False

    def _restart_and_audit(self, audit, acknowledged, refused):
        self.node.stop()
        self._start()
        present = self._robots()
        audit.lost = len(acknowledged - present)
        audit.refused_present = len(refused & present)
        audit.damage_after_restart = self._damage()

    def full_disk(self, changes: int) -> StorageAudit:
        """Fill the filesystem, send changes, free it: 225 or acknowledged, never lost."""
        subprocess.run(['mount', '-t', 'tmpfs', '-o', 'size=4m', 'tmpfs', str(self.mount)],
                       check=True)
        self._start()
        audit = StorageAudit('disk full (4 MiB tmpfs)')
        filler = self.mount / 'filler'
        descriptor = os.open(filler, os.O_WRONLY | os.O_CREAT)
        for chunk in (1 << 16, 4096, 512, 1):
            try:
                while True:
                    os.write(descriptor, b'\0' * chunk)
            except OSError as error:
                assert error.errno == errno.ENOSPC, error
        os.close(descriptor)
        acknowledged, refused = set(), set()
        for i in range(changes):
            name = f'full{i}'
            (acknowledged if self._send(audit, name) else refused).add(name)
        in_memory = self._robots()
        audit.memory_differs = len(refused & in_memory) + len(acknowledged - in_memory)
        audit.refusal_reported = any(d.get('refusing_changes') for d in self._damage())
        filler.unlink()
        started = time.monotonic()
        for i in range(50):
            if self._send(audit, f'back{i}'):
                acknowledged.add(f'back{i}')
                audit.recovery_s = time.monotonic() - started
                break
            refused.add(f'back{i}')
            time.sleep(0.1)
        self._restart_and_audit(audit, acknowledged, refused)
        return audit

    def read_only(self, changes: int) -> StorageAudit:
        """An ext4 error under the node (errors=remount-ro): the filesystem turns read-only."""
        self.image = self.scratch / 'ext4.img'
        with open(self.image, 'wb') as out:
            out.truncate(32 << 20)
        subprocess.run(['mkfs.ext4', '-q', str(self.image)], check=True)
        subprocess.run(['mount', '-o', 'loop,errors=remount-ro', str(self.image), str(self.mount)],
                       check=True)
        self._start()
        audit = StorageAudit('filesystem turned read-only (ext4 error, errors=remount-ro)')
        acknowledged, refused = set(), set()
        for i in range(changes):
            if self._send(audit, f'before{i}'):
                acknowledged.add(f'before{i}')
        device = subprocess.run(['findmnt', '-n', '-o', 'SOURCE', str(self.mount)], check=True,
                                capture_output=True, text=True).stdout.strip()
        pathlib.Path(f'/sys/fs/ext4/{os.path.basename(device)}/trigger_fs_error').write_text(
            'armor fault injection\n')
        for i in range(changes):
            if not self._send(audit, f'after{i}'):
                refused.add(f'after{i}')
        in_memory = self._robots()
        audit.memory_differs = len(refused & in_memory) + len(acknowledged - in_memory)
        audit.refusal_reported = any(d.get('refusing_changes') for d in self._damage())
        # The operator's way back: stop, check the filesystem, mount it again, start.
        self.node.stop()
        self._unmount()
        subprocess.run(['e2fsck', '-fy', str(self.image)], capture_output=True)
        subprocess.run(['mount', '-o', 'loop', str(self.image), str(self.mount)], check=True)
        self._start()
        present = self._robots()
        audit.lost = len(acknowledged - present)
        audit.refused_present = len(refused & present)
        audit.damage_after_restart = self._damage()
        return audit

    def close(self) -> None:
        if self.armor is not None:
            self.armor.close()
        if self.node is not None:
            self.node.stop()
        self._unmount()

    def _unmount(self) -> None:
        """The core's JVM, stopped with its node, can hold the filesystem a moment longer."""
        deadline = time.monotonic() + 60
        while True:
            done = subprocess.run(['umount', str(self.mount)], capture_output=True, text=True)
            if done.returncode == 0 or 'not mounted' in done.stderr:
                return
            assert time.monotonic() < deadline, f'umount {self.mount}: {done.stderr}'
            time.sleep(0.2)


def junit_campaigns(rounds: int, stride: int) -> list:
    """Runs the core's storage campaigns, longer, and returns their FIGURES lines."""
    root = pathlib.Path(__file__).resolve().parents[2]
    result = subprocess.run(
        ['mvn', '-B', '-q', '-f', str(root / 'core' / 'pom.xml'), 'test',
         '-Dtest=StorageFaultsTest,DamagedFilesTest', f'-Darmor.faults.rounds={rounds}',
         '-Darmor.faults.stride=1', f'-Darmor.flip.stride={stride}',
         '-Dsurefire.failIfNoSpecifiedTests=false'],
        capture_output=True, text=True)
    reports = root / 'core' / 'target' / 'surefire-reports'
    text = result.stdout + ''.join(p.read_text() for p in reports.glob('*StorageFaultsTest-output.txt'))
    text += ''.join(p.read_text() for p in reports.glob('*DamagedFilesTest-output.txt'))
    lines = sorted(set(re.findall(r'FIGURES .*', text)))
    if result.returncode != 0:
        lines.append('JUNIT CAMPAIGNS FAILED:\n' + result.stdout[-4000:])
    return lines


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
    parser.add_argument('--storage', action='store_true',
                        help='instead of kills, the storage faults (full disk, read-only, JUnit)')
    parser.add_argument('--full-disk', type=int, default=200, help='changes sent to a full disk')
    parser.add_argument('--read-only', type=int, default=20,
                        help='changes before and after the filesystem turns read-only')
    parser.add_argument('--junit-rounds', type=int, default=3,
                        help='workload rounds of the JUnit campaigns (1 in make test)')
    parser.add_argument('--flip-stride', type=int, default=1,
                        help='flip every n-th byte of the files (11 in make test)')
    options = parser.parse_args()
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-faults-'))
    if options.storage or options.full_disk != 200 or options.read_only != 20:
        ok = True
        for campaign, size in (('full_disk', options.full_disk), ('read_only', options.read_only)):
            (scratch / campaign).mkdir()
            faults = FilesystemFaults(scratch / campaign)
            try:
                audit = getattr(faults, campaign)(size)
            finally:
                faults.close()
            print(audit.summary(), flush=True)
            ok &= audit.lost == audit.refused_present == audit.memory_differs == 0
        for line in junit_campaigns(options.junit_rounds, options.flip_stride):
            print(line, flush=True)
            lost = re.search(r'acknowledged_then_lost=(\d+)', line)
            ok &= 'FAILED' not in line and 'restores_silently_different=0' in line
            ok &= lost is None or lost.group(1) == '0'
        return 0 if ok else 1
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
