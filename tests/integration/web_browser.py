# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Debian's chromium driven by Playwright, for the web view's tests and bench/web_view.py.

Playwright's own browser download cannot work on a machine that reaches only package
registries, so it drives the system browser tools/setup.sh installs, headless.
"""

import os
import socket

CHROMIUM = '/usr/bin/chromium'
CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
                 '--disable-background-networking', '--disable-component-update',
                 '--disable-sync']


def launch(playwright, *extra_args: str, executable: str = CHROMIUM):
    """A headless chromium (Playwright Browser); fails plainly when the browser is missing."""
    if not os.access(CHROMIUM, os.X_OK):
        raise RuntimeError(f'{CHROMIUM} is missing: make test (tools/setup.sh browser) installs Debian\'s chromium')
    return playwright.chromium.launch(executable_path=executable,
                                      args=[*CHROMIUM_ARGS, *extra_args])


def free_port() -> int:
    """A TCP port on the loopback interface that nothing listens on now."""
    with socket.socket() as probe:
        probe.bind(('127.0.0.1', 0))
        return probe.getsockname()[1]
