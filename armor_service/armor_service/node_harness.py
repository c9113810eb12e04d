# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A test and benchmark harness: an ARMOR node as a child process (what a launch file does).

For tests, benchmarks and scripts; a robot starts the node with launch/armor.launch.py.
"""

import pathlib
import signal
import subprocess
import sys
import time
from typing import List, Mapping, Optional, Sequence


def default_jvm_options() -> List[str]:
    """The node's default jvm_options, for harnesses that add options of their own to it."""
    from armor_service.parameters import NODE_PARAMETERS
    return list(next(p.default for p in NODE_PARAMETERS if p.name == 'jvm_options'))


class ArmorNodeProcess:
    """The ARMOR node (as `armor serve --ros-args ...`) in the background, output in a log file.

    Args:
        log_path: where the node's stdout and stderr go.
        ros_args: ROS arguments after --ros-args (-p name:=value, -r __ns:=/x, ...).
        cwd: working directory of the node (relative paths resolve against it).
        command_prefix: a command that runs the node, such as ``ip netns exec host1``.
        env: the node's environment (None: this process's).

    Unless ros_args set state_dir, the node keeps its journals in a `state` folder beside the
    log, so a scripted node never restores what another run left in the user's data directory.
    """

    def __init__(self, log_path: pathlib.Path, ros_args: Sequence[str] = (),
                 cwd: Optional[pathlib.Path] = None, command_prefix: Sequence[str] = (),
                 env: Optional[Mapping[str, str]] = None):
        self.log_path = pathlib.Path(log_path)
        ros_args = list(ros_args)
        if not any(arg.startswith('state_dir:=') for arg in ros_args):
            ros_args += ['-p', f'state_dir:={self.log_path.parent / "state"}']
        self._log = open(self.log_path, 'w')
        self.process = subprocess.Popen(
            [*command_prefix, sys.executable, '-m', 'armor_service.node', '--ros-args', *ros_args],
            stdout=self._log, stderr=subprocess.STDOUT, cwd=cwd, env=env)

    def core_pid(self, wait_s: float = 60.0) -> int:
        """PID of the node's Java core (waits while a core is being restarted)."""
        deadline = time.monotonic() + wait_s
        while time.monotonic() < deadline:
            for stat in pathlib.Path('/proc').glob('[0-9]*/stat'):
                try:
                    text = stat.read_text()
                except OSError:
                    continue
                name, rest = text.split('(', 1)[1].rsplit(')', 1)
                if name == 'java' and int(rest.split()[1]) == self.process.pid:
                    return int(stat.parent.name)
            time.sleep(0.1)
        raise RuntimeError(f'node {self.process.pid} has no Java core child')

    def log(self) -> str:
        return self.log_path.read_text()

    def stop(self, timeout_s: float = 20.0) -> None:
        """Ctrl-C the node (it stops its core), killing it if it does not exit in time."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(timeout=timeout_s)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self._log.close()
