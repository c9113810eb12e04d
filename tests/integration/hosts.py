# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Separate hosts on this machine: Linux network namespaces cabled to one virtual switch.

Each host is a network namespace with its own loopback and one interface, ``eth0``
(10.88.0.<n>/24), joined by a veth pair to a port of a bridge that lives in a namespace of its
own (the switch), so no host is special. What runs in a host (``hosts.command(name, ...)``)
sees only that network: DDS discovery and traffic between hosts cross the veth links, and
``unplug``/``plug`` pull and put back a host's cable at the switch. ``block_multicast`` makes
the switch drop multicast between hosts, as many real networks (Wi-Fi, clouds) do.

Needs root (CAP_NET_ADMIN and CAP_SYS_ADMIN) and iproute2; ``unavailable()`` says why not.
Everything is created under names unique to this process and removed by ``remove()``.
"""

import itertools
import os
import shutil
import subprocess
from typing import Dict, List, Optional, Sequence

SUBNET = '10.88.0'
_sets = itertools.count()


def _ip(*args: str) -> None:
    subprocess.run(['ip', *args], check=True, capture_output=True, text=True, timeout=30)


def unavailable() -> Optional[str]:
    """Why virtual hosts cannot be made here, or None when they can."""
    if os.geteuid() != 0:
        return 'network namespaces need root (the test machines run the suite as root)'
    if shutil.which('ip') is None:
        return "iproute2's ip command is not installed (Debian: apt-get install iproute2)"
    probe = f'armor-probe-{os.getpid()}'
    try:
        _ip('netns', 'add', probe)
    except subprocess.CalledProcessError as error:
        return f'ip netns add is refused here: {error.stderr.strip()}'
    _ip('netns', 'del', probe)
    return None


class VirtualHosts:
    """Hosts cabled to one switch; ``address[name]`` is each host's IPv4 address.

    Args:
        names: the hosts to make, in order (addresses 10.88.0.1, .2, ...).
    """

    def __init__(self, names: Sequence[str]):
        self.tag = f'armor{os.getpid()}-{next(_sets)}'
        self.switch = f'{self.tag}-switch'
        self.namespace: Dict[str, str] = {name: f'{self.tag}-{name}' for name in names}
        self.address: Dict[str, str] = {
            name: f'{SUBNET}.{number}' for number, name in enumerate(names, start=1)}
        self._made: List[str] = []
        try:
            self._make(list(names))
        except BaseException:
            self.remove()
            raise

    def _make(self, names: List[str]) -> None:
        _ip('netns', 'add', self.switch)
        self._made.append(self.switch)
        _ip('-n', self.switch, 'link', 'add', 'br0', 'type', 'bridge')
        # Every multicast frame goes to every port (no IGMP snooping without a querier).
        _ip('-n', self.switch, 'link', 'set', 'br0', 'type', 'bridge', 'mcast_snooping', '0')
        _ip('-n', self.switch, 'link', 'set', 'br0', 'up')
        for name in names:
            namespace = self.namespace[name]
            _ip('netns', 'add', namespace)
            self._made.append(namespace)
            _ip('-n', namespace, 'link', 'set', 'lo', 'up')
            _ip('link', 'add', self.port(name), 'netns', self.switch, 'type', 'veth',
                'peer', 'name', 'eth0', 'netns', namespace)
            _ip('-n', self.switch, 'link', 'set', self.port(name), 'master', 'br0', 'up')
            _ip('-n', namespace, 'addr', 'add', f'{self.address[name]}/24', 'dev', 'eth0')
            _ip('-n', namespace, 'link', 'set', 'eth0', 'up')
            # DDS discovery multicasts to 239.255.0.1: that needs a route out of eth0.
            _ip('-n', namespace, 'route', 'add', '224.0.0.0/4', 'dev', 'eth0')

    @staticmethod
    def port(name: str) -> str:
        """The switch's port for a host (an interface name, at most 15 characters)."""
        return f'p-{name}'[:15]

    def command(self, name: str, *argv: str) -> List[str]:
        """The argv that runs a program on a host."""
        return ['ip', 'netns', 'exec', self.namespace[name], *argv]

    def unplug(self, name: str) -> None:
        """Pull a host's cable: nothing reaches it or leaves it until plug()."""
        _ip('-n', self.switch, 'link', 'set', self.port(name), 'down')

    def plug(self, name: str) -> None:
        """Put a host's cable back."""
        _ip('-n', self.switch, 'link', 'set', self.port(name), 'up')

    def block_multicast(self) -> None:
        """Make the switch forward no multicast between hosts (unicast still flows)."""
        for name in self.namespace:
            subprocess.run(['bridge', '-n', self.switch, 'link', 'set', 'dev', self.port(name),
                            'mcast_flood', 'off'], check=True, capture_output=True, timeout=30)

    def remove(self) -> None:
        """Delete the hosts and the switch (stop what runs on them first)."""
        for namespace in reversed(self._made):
            subprocess.run(['ip', 'netns', 'del', namespace], capture_output=True, timeout=30)
        self._made = []
