# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Robots on several machines sharing one ARMOR service, over real networks of this machine.

Three hosts made of Linux network namespaces cabled to one virtual switch (hosts.py): the
node runs on "server", a robot (fleet_robot.py, the Python client in a process of its own) on
each of "robot1" and "robot2". They find each other by DDS discovery across the veth links,
with ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET (install/setup.bash chooses LOCALHOST unless told)
and Fast DDS's UDP transport only, so nothing can go through shared memory instead of the
links. Directives, atomic lists and mounts work across hosts; then a robot holding a mount
loses its cable and the node's mount lease (mount_lease_s) releases the mount for the other.

Each check is a test function on the module's ``fleet``: a check of change events across
hosts is one more function that sends the robots a new kind of request (one more handler in
fleet_robot.OPS). Without root or network namespaces the module is skipped, saying why.
"""

import json
import os
import pathlib
import selectors
import subprocess
import sys
import time
from typing import Any, Dict, List, Optional

from conftest import ONTOLOGIES, release_domain, REPO, reserve_domain, start_node
import hosts
import pytest

pytestmark = pytest.mark.skipif(hosts.unavailable() is not None,
                                reason=f'no virtual hosts: {hosts.unavailable()}')

LEASE_S = 8
ROBOTICS = str(ONTOLOGIES / 'robotics.owl')
ROBOT = pathlib.Path(__file__).with_name('fleet_robot.py')
QUERY_ROOMS = REPO / 'build' / 'armor_cpp' / 'query_rooms'


def cross_host_environment(domain: str, **extra: str) -> Dict[str, str]:
    """What a process on a virtual host needs to reach the others over DDS."""
    return {**os.environ, 'ROS_DOMAIN_ID': domain, 'ARMOR_TEST_DOMAIN': domain,
            'ROS_AUTOMATIC_DISCOVERY_RANGE': 'SUBNET', 'FASTDDS_BUILTIN_TRANSPORTS': 'UDPv4',
            **extra}


class Robot:
    """A client process on a host, answering fleet_robot.py requests."""

    def __init__(self, virtual_hosts: hosts.VirtualHosts, host: str, client_name: str,
                 env: Dict[str, str], timeout_s: float = 5.0):
        self.host = host
        self.client_name = client_name
        self.process = subprocess.Popen(
            virtual_hosts.command(host, sys.executable, str(ROBOT), client_name, str(timeout_s)),
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
            env=env)
        self._lines = selectors.DefaultSelector()
        self._lines.register(self.process.stdout, selectors.EVENT_READ)
        assert self._read(60.0) == {'ready': True}

    def _read(self, wait_s: float) -> Dict[str, Any]:
        if not self._lines.select(wait_s):
            raise TimeoutError(f'{self.host} did not answer within {wait_s} s')
        line = self.process.stdout.readline()
        assert line, f'{self.host} stopped'
        return json.loads(line)

    def send(self, **request: Any) -> None:
        """Send one request without waiting for its answer (see answer())."""
        self.process.stdin.write(json.dumps(request) + '\n')
        self.process.stdin.flush()

    def answer(self, wait_s: float = 120.0) -> Dict[str, Any]:
        """The answer to the oldest request not answered yet (value or error, and seconds)."""
        return self._read(wait_s)

    def request(self, wait_s: float = 120.0, **request: Any) -> Dict[str, Any]:
        """Send one request and wait for its answer."""
        self.send(**request)
        return self.answer(wait_s)

    def call(self, method: str, *args: Any, reference: Optional[str] = 'fleet') -> Any:
        """A client method's value; AssertionError with ARMOR's error when it failed."""
        answer = self.request(op='call', reference=reference, method=method, args=list(args))
        assert 'error' not in answer, f'{self.host}: {method}{args} failed: {answer}'
        return answer['value']

    def refused(self, method: str, *args: Any, reference: Optional[str] = 'fleet'
                ) -> Dict[str, Any]:
        """The error a client method raised (AssertionError when it succeeded)."""
        answer = self.request(op='call', reference=reference, method=method, args=list(args))
        assert 'error' in answer, f'{self.host}: {method}{args} succeeded: {answer}'
        return answer

    def stop(self) -> None:
        self.process.stdin.close()
        try:
            self.process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


class Fleet:
    """The hosts, the node on "server" and the two robots."""

    def __init__(self, scratch: pathlib.Path):
        self.domain = reserve_domain()
        self.env = cross_host_environment(self.domain)
        self.hosts = hosts.VirtualHosts(['server', 'robot1', 'robot2'])
        self.robots: List[Robot] = []
        self.node = start_node(scratch, '-p', f'mount_lease_s:={LEASE_S}',
                               command_prefix=self.hosts.command('server'), env=self.env)
        self.robot1 = self._robot('robot1')
        self.robot2 = self._robot('robot2')

    def _robot(self, host: str) -> Robot:
        robot = Robot(self.hosts, host, f'{host}_planner', self.env)
        self.robots.append(robot)
        return robot

    def close(self) -> None:
        for robot in self.robots:
            robot.stop()
        self.node.stop()
        self.hosts.remove()
        release_domain(self.domain)


@pytest.fixture(scope='module')
def fleet(tmp_path_factory):
    made = Fleet(tmp_path_factory.mktemp('fleet'))
    try:
        made.robot1.call('load_file', 'fleet', ROBOTICS, reference=None)
        yield made
    finally:
        made.close()


def test_directives_from_one_host_are_seen_on_another(fleet):
    assert {'fleet', 'robotics'} <= set(fleet.robot2.call('references', reference=None))
    fleet.robot1.call('replace_object_value', 'isIn', 'alice', 'bedroom', 'corridor1')
    assert fleet.robot2.call('instances', 'OccupiedRoom') == ['bedroom', 'kitchen']
    assert fleet.robot2.call('data_values', 'batteryLevel', 'robot1') == [80]


def test_an_atomic_list_from_one_host_is_all_or_nothing_on_another(fleet):
    answer = fleet.robot2.request(op='batch', reference='fleet', changes=[
        ['add_individual_to_class', ['bob', 'Person']],
        ['add_object_value', ['isIn', 'bob', 'kitchen']]])
    assert answer.get('value') is True, answer
    assert 'bob' in fleet.robot1.call('dl_instances', 'Person and isIn value kitchen')
    failed = fleet.robot2.request(op='batch', reference='fleet', changes=[
        ['add_individual_to_class', ['dave', 'Person']],
        ['add_data_value', ['batteryLevel', 'dave', 'eighty', 'INTEGER']]])
    assert failed['error'] == 'ArmorArgumentError' and failed['exit_code'] == 101, failed
    assert 'dave' not in fleet.robot1.call('instances', 'Person')


def test_change_events_and_inferred_answers_reach_another_host(fleet):
    """robot2 watches; robot1, on another host, moves a person: robot2 hears the change and
    the room the reasoner now infers occupied, with the revision both hold at."""
    fleet.robot2.call('replace_object_value', 'isIn', 'alice', 'corridor1',
                      fleet.robot2.call('object_values', 'isIn', 'alice')[0])
    watched = fleet.robot2.request(op='watch', reference='fleet',
                                   query='QUERY IND CLASS OccupiedRoom')
    assert watched.get('value') == ['kitchen'], watched
    fleet.robot1.call('replace_object_value', 'isIn', 'alice', 'bedroom', 'corridor1')
    revision = None
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        heard = fleet.robot2.request(op='heard')['value']
        moves = [c for c in heard['changes'] if c[1] == 'robot1_planner' and c[2] == ['REPLACE']]
        appeared = [a for a in heard['answers'] if a[1] == ['bedroom']]
        if moves and appeared:
            revision = moves[-1][0]
            break
        time.sleep(0.2)
    assert revision is not None, heard
    assert appeared[-1][0] == revision and appeared[-1][2] == [] and appeared[-1][3] == 0
    assert all(not c[3] for c in heard['changes']), heard   # no missed revisions


def test_a_mount_taken_on_one_host_keeps_the_other_out(fleet):
    fleet.robot1.call('mount')
    refused = fleet.robot2.refused('add_individual_to_class', 'intruder', 'Person')
    assert (refused['error'], refused['exit_code']) == ('ArmorMountError', 102)
    assert fleet.robot2.call('mounted_by', 'fleet', reference=None) == 'robot1_planner'
    assert 'intruder' not in fleet.robot2.call('instances', 'Person')
    fleet.robot1.call('unmount')
    fleet.robot2.call('add_individual_to_class', 'carol', 'Person')
    assert 'carol' in fleet.robot1.call('instances', 'Person')


def test_the_cpp_client_answers_across_hosts(fleet):
    ran = subprocess.run(fleet.hosts.command('robot2', str(QUERY_ROOMS)), env=fleet.env,
                         capture_output=True, text=True, timeout=120)
    assert ran.returncode == 0, ran.stderr
    occupied = fleet.robot1.call('instances', 'OccupiedRoom', reference='robotics')
    assert [line.split(' ', 1)[0] for line in ran.stdout.splitlines()[:-1]] == occupied


def test_a_mount_held_by_a_robot_that_lost_its_link_is_released_by_the_lease(fleet):
    fleet.robot1.call('load_file', 'fleet_lease', ROBOTICS, reference=None)
    fleet.robot1.call('mount', reference='fleet_lease')
    last_heard = time.monotonic()
    refused = fleet.robot2.refused('add_individual', 'box1', reference='fleet_lease')
    assert refused['exit_code'] == 102
    fleet.hosts.unplug('robot1')
    try:
        # The robot keeps trying meanwhile; its call times out, since its cable is out.
        fleet.robot1.send(op='call', reference='fleet_lease', method='instances', args=['Room'])
        refusals = 0
        while True:
            answer = fleet.robot2.request(op='call', reference='fleet_lease',
                                          method='add_individual', args=['box1'])
            if 'error' not in answer:
                break
            assert answer['exit_code'] == 102, answer
            refusals += 1
            assert time.monotonic() - last_heard < LEASE_S + 20, 'the lease never released'
            time.sleep(0.5)
        released_after = time.monotonic() - last_heard
        cut_off = fleet.robot1.answer()
        assert cut_off.get('error') == 'ArmorCallTimeout', cut_off
    finally:
        fleet.hosts.plug('robot1')
    assert refusals > 0 and released_after >= LEASE_S - 0.5, (refusals, released_after)
    assert fleet.robot2.call('mounted_by', 'fleet_lease', reference=None) is None
    assert 'expired after' in fleet.node.log()
    # Back on the network, the robot finds its mount gone (203), and the other's change kept.
    lost = fleet.robot1.refused('unmount', reference='fleet_lease')
    assert (lost['error'], lost['exit_code']) == ('ArmorMountError', 203), lost
    assert 'box1' in fleet.robot1.call('instances', 'http://www.w3.org/2002/07/owl#Thing',
                                       reference='fleet_lease')


def test_without_multicast_a_discovery_server_connects_the_hosts(tmp_path):
    domain = reserve_domain()
    virtual_hosts = hosts.VirtualHosts(['server', 'robot'])
    virtual_hosts.block_multicast()
    server_address = f'{virtual_hosts.address["server"]}:11811'
    with_server = cross_host_environment(domain, ROS_DISCOVERY_SERVER=server_address)
    discovery_server = subprocess.Popen(
        virtual_hosts.command('server', 'fast-discovery-server', '42', '-l',
                              virtual_hosts.address['server'], '-p', '11811'),
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=with_server)
    node = start_node(tmp_path, command_prefix=virtual_hosts.command('server'), env=with_server)
    try:
        query = ['armor', 'call', '--no-relay', 'robotics', 'QUERY', 'IND', 'CLASS', '--', 'Room']
        found = subprocess.run(virtual_hosts.command('robot', *query[:3], '--wait', '90',
                                                     *query[3:]),
                               env=with_server, capture_output=True, text=True, timeout=150)
        assert found.returncode == 0, found.stderr + node.log()[-2000:]
        assert found.stdout.splitlines()[1:] == ['<http://www.example.org/robotics#bedroom>',
                                                 '<http://www.example.org/robotics#kitchen>']
        cpp = subprocess.run(virtual_hosts.command('robot', str(QUERY_ROOMS)), env=with_server,
                             capture_output=True, text=True, timeout=120)
        assert cpp.returncode == 0 and cpp.stdout.startswith('kitchen'), cpp.stderr
        by_multicast = subprocess.run(
            virtual_hosts.command('robot', *query[:3], '--wait', '6', *query[3:]),
            env=cross_host_environment(domain), capture_output=True, text=True, timeout=60)
        assert by_multicast.returncode != 0, 'multicast discovery worked on a blocked switch'
    finally:
        node.stop()
        discovery_server.terminate()
        discovery_server.wait(timeout=20)
        virtual_hosts.remove()
        release_domain(domain)
