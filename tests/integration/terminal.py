# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Run a command in a pseudo-terminal, as a person at a keyboard would, and read its screen."""

import os
import pty
import select
import subprocess
import sys
import time
from typing import Sequence


class Terminal:
    """A process whose stdin, stdout and stderr are one pseudo-terminal.

    Args:
        argv: the command after the Python interpreter (``['-m', 'armor_client.cli', ...]``).
    """

    def __init__(self, argv: Sequence[str]):
        self._master, slave = pty.openpty()
        self.process = subprocess.Popen([sys.executable, *argv], stdin=slave, stdout=slave,
                                        stderr=slave, close_fds=True,
                                        env={**os.environ, 'TERM': 'dumb'})
        os.close(slave)
        self.screen = ''
        self._matched_to = 0

    def wait_for(self, text: str, timeout_s: float = 60.0) -> str:
        """Read until text appears after what the last wait matched; returns the screen from there.

        What one read brings may hold the next awaited text too: it counts, as on a screen.
        """
        start = self._matched_to
        deadline = time.monotonic() + timeout_s
        while text not in self.screen[start:]:
            if time.monotonic() > deadline:
                raise AssertionError(f'{text!r} did not appear; screen:\n{self.screen}')
            ready, _, _ = select.select([self._master], [], [], 0.1)
            if ready:
                try:
                    self.screen += os.read(self._master, 4096).decode('utf-8', 'replace')
                except OSError:
                    break
        found = self.screen.index(text, start) if text in self.screen[start:] else len(self.screen)
        self._matched_to = found + len(text)
        return self.screen[start:]

    def type(self, keys: str) -> None:
        os.write(self._master, keys.encode())

    def close(self, timeout_s: float = 20.0) -> int:
        """Wait for the process to end (killing it after timeout_s); its exit status."""
        try:
            code = self.process.wait(timeout_s)
        except subprocess.TimeoutExpired:
            self.process.kill()
            code = self.process.wait()
        os.close(self._master)
        return code
