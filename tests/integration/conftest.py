# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Fixtures that start the real ARMOR node as a separate process and call it over ROS 2."""

import fcntl
import json
import os
import pathlib
import random
import subprocess
import threading
import time

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
ONTOLOGIES = REPO / 'ontologies'
TEST_ONTOLOGIES = REPO / 'tests' / 'ontologies'
NS = 'http://www.example.org/robotics#'


def domains_in_use() -> set:
    """DDS domains that have a participant on this machine, whoever started it.

    An RTPS participant of domain d binds UDP ports from 7400 + 250 * d (discovery and user
    traffic, 250 ports a domain); a bound port there means someone is on that domain. Ports of
    other programs that fall in a domain's range only make a domain look taken, never free.
    """
    taken = set()
    for table in ('/proc/net/udp', '/proc/net/udp6'):
        try:
            lines = pathlib.Path(table).read_text().splitlines()[1:]
        except OSError:
            continue
        for line in lines:
            port = int(line.split()[1].rsplit(':', 1)[1], 16)
            if port >= 7400:
                taken.add((port - 7400) // 250)
    return taken


def reserve_domain() -> str:
    """A DDS domain no other test run and no running node on this machine is using, held until
    this process ends (or until release_domain).

    Two runs in one domain would each reach the other's node (a request goes to every server of
    a service name), and so would a run in the domain of a user's own node: the domain the user
    exported, domain 0 and every domain with a participant are never chosen. Child processes
    inherit ROS_DOMAIN_ID and so share this run's domain.
    """
    avoid = domains_in_use() | {0}
    exported = os.environ.get('ROS_DOMAIN_ID', '')
    if exported.isdigit():
        avoid.add(int(exported))
    start = random.Random(os.getpid()).randint(1, 232)
    for offset in range(232):
        domain = (start + offset) % 232 + 1
        if domain in avoid:
            continue
        handle = open(f'/tmp/armor-ros-domain-{domain}.lock', 'w')
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            handle.close()
            continue
        _DOMAIN_LOCKS[str(domain)] = handle
        return str(domain)
    raise RuntimeError('every DDS domain 1-232 is in use or held by another test run')


def release_domain(domain: str) -> None:
    """Let other runs have a domain this process reserved."""
    _DOMAIN_LOCKS.pop(domain).close()


_DOMAIN_LOCKS = {}
# Chosen before rclpy starts: a ROS_DOMAIN_ID the user exported for their own node (make run)
# is the one domain the tests must stay out of. Only a process this run started itself (a
# client script of a load test) keeps the domain it inherited: ARMOR_TEST_DOMAIN marks it.
# A worker of a parallel run (pytest-xdist) reserves its own even when the run's controller,
# which loads this file too when test files are named on its command line, reserved one.
_inherited = os.environ.get('ROS_DOMAIN_ID')
_worker = os.environ.get('PYTEST_XDIST_WORKER', '')
if (not _inherited or os.environ.get('ARMOR_TEST_DOMAIN') != _inherited
        or os.environ.get('ARMOR_TEST_DOMAIN_WORKER', '') != _worker):
    os.environ['ROS_DOMAIN_ID'] = os.environ['ARMOR_TEST_DOMAIN'] = reserve_domain()
    os.environ['ARMOR_TEST_DOMAIN_WORKER'] = _worker
# armor call's relays started by tests end soon after the run (and at its end, below).
os.environ['ARMOR_CALL_RELAY_IDLE_S'] = '60'


def _minutes(item) -> float:
    marker = item.get_closest_marker('runs_for_minutes')
    return (marker.args[0] if marker.args else 1) if marker else 0


def pytest_collection_modifyitems(items):
    """The longest files first (runs_for_minutes(N)): workers take files in this order
    (tools/test.sh keeps it with --no-loadscope-reorder), so that none starts near the end."""
    items.sort(key=_minutes, reverse=True)


@pytest.fixture(scope='session', autouse=True)
def _stop_call_relay():
    yield
    from armor_client.cli import call_relay
    call_relay.stop()


def call_service(client, request, timeout_s: float = 120.0):
    """The answer of an rclpy service client spun by another thread; fails after timeout_s."""
    done = threading.Event()
    future = client.call_async(request)
    future.add_done_callback(lambda _: done.set())
    assert done.wait(timeout_s), f'no answer from {client.srv_name}'
    return future.result()


def iri(name: str) -> str:
    return f'<{NS}{name}>'


def iris(*names: str) -> list:
    return sorted(iri(n) for n in names)


C1_ALONE = ['-XX:TieredStopAtLevel=1']
# The benchmarks the suite runs (bench/harness.py) add it to their nodes' options too.
os.environ.setdefault('ARMOR_BENCH_EXTRA_JVM_OPTIONS', json.dumps(C1_ALONE))


def suite_jvm_options() -> list:
    """The node's default JVM options, with the JIT's C1 compiler alone.

    The suite's cores live for seconds to a minute: the optimising compiler (C2) spent more than
    half of their CPU time compiling code they did not run long enough to pay it back (four test
    files: 84 CPU-s in the cores with it, 43 without; the SOMA test 82 CPU-s either way).
    Robots keep the default; a test's own jvm_options come later and replace these.
    """
    from armor_service.node_harness import default_jvm_options
    return [*default_jvm_options(), *C1_ALONE]


def start_node(scratch: pathlib.Path, *ros_args: str, namespace: str = '', **process):
    """A node preloading robotics.owl as "robotics", reading and writing in scratch only.

    Its state directory is scratch/state, so it restores nothing but its own earlier state; its
    working directory is scratch/cwd (no file directly in a working directory is ever written).
    A node started beside the session's node needs a namespace of its own: two nodes serving
    one service name would both receive every request. ``process``: command_prefix and env of
    ArmorNodeProcess (a node on another host, with its own DDS settings).
    """
    if namespace:
        ros_args = (*ros_args, '-r', f'__ns:={namespace}')
    from armor_service.node_harness import ArmorNodeProcess
    node = ArmorNodeProcess(scratch / 'armor_service.log', [
        '-p', f'jvm_options:={json.dumps(suite_jvm_options())}',
        '-p', f'preload_file:={ONTOLOGIES / "robotics.owl"}', '-p', 'preload_reference:=robotics',
        '-p', f'allowed_dirs:=["{ONTOLOGIES}", "{TEST_ONTOLOGIES}", "{scratch}"]',
        '-p', f'write_dirs:={scratch}', '-p', f'state_dir:={scratch / "state"}', *ros_args],
        cwd=_made(scratch / 'cwd'), **process)
    node.scratch = scratch
    return node


def cmake_built(folder: pathlib.Path, program: str) -> pathlib.Path:
    """A C++ program built from folder's CMakeLists.txt as a user builds it; its path.

    find_package(armor_cpp) finds install/armor_cpp through the environment of install/setup.bash.
    """
    for step in (['cmake', '-S', str(folder), '-B', str(folder / 'build')],
                 ['cmake', '--build', str(folder / 'build')]):
        built = subprocess.run(step, capture_output=True, text=True, timeout=600)
        assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    return folder / 'build' / program


def _made(folder: pathlib.Path) -> pathlib.Path:
    folder.mkdir(parents=True, exist_ok=True)
    return folder


@pytest.fixture(scope='session', autouse=True)
def _rclpy_for_the_session():
    """rclpy's default context, started once per test process and ended at its end.

    An ArmorTransport that finds rclpy not started starts it and shuts it down when it closes:
    the first test of a worker that made its own transport would otherwise end the context under
    the session's transport, made meanwhile (every later test of that worker then failed with
    InvalidHandle when the files ran longest first).
    """
    import rclpy
    if not rclpy.ok():
        rclpy.init()
    yield
    rclpy.try_shutdown()


@pytest.fixture(scope='session')
def armor_node(tmp_path_factory):
    node = start_node(tmp_path_factory.mktemp('armor'))
    yield node
    node.stop()


@pytest.fixture(scope='session')
def armor(armor_node):
    """An ArmorTransport connected to the session's node, ready to call."""
    from armor_client import ArmorTransport, directive
    transport = ArmorTransport(service_wait_s=90.0)
    response = transport.call(directive('test', '', 'GET', 'ALL', 'REFS'), timeout_s=120)
    assert response.success, armor_node.log()
    yield transport
    transport.close()


def call_words(transport, reference: str, words: str, *args, client: str = 'test',
               timeout_s: float = 120.0):
    """transport's answer to 'COMMAND PRIMARY SECONDARY' with args on a reference."""
    from armor_client import directive
    command, primary, secondary = (words.split() + ['', '', ''])[:3]
    return transport.call(directive(client, reference, command, primary, secondary, list(args)),
                          timeout_s=timeout_s)


def first_call_after_start(transport, reference: str, words: str, *args,
                           deadline_s: float = 300.0):
    """A read sent to a node just started (again), asked again until answered.

    A transport that knew the node's earlier run can send its first request before the new
    server is matched, and that request is lost: an attempt waits 20 s, not the whole deadline,
    and after it the transport proves the new node's response path before asking again.
    """
    deadline = time.monotonic() + deadline_s
    while True:
        try:
            return call_words(transport, reference, words, *args, timeout_s=20.0)
        except Exception:  # noqa: BLE001 - asked again until the deadline
            if time.monotonic() > deadline:
                raise


@pytest.fixture
def call(armor):
    """call('REF', 'COMMAND PRIMARY SECONDARY', *args) -> ArmorDirectiveRes."""
    def send(reference, words, *args, client='test', timeout_s=120):
        return call_words(armor, reference, words, *args, client=client, timeout_s=timeout_s)
    return send
