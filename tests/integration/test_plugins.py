# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Plugin jars in plugin_dirs add commands and reasoner factories to a running node.

The jars are built here as a plugin author builds them: the repository's example
(examples/plugins/hello_command, with its build.sh) and test plugins compiled with javac
against the installed core. Their commands run exactly like built-in ones over ROS 2: the
mount check (102), atomic lists (212 undoes them), the journal (a change survives a killed
core), exit codes, the reference lock; one that throws or loops answers (220, 211) within
plugin_timeout_ms, its change undone, and the node, the core and the reference stay usable.
"""

import asyncio
import inspect
import os
import pathlib
import queue
import signal
import subprocess
import sys
import threading
import time
import zipfile

from armor_client import Armor, ArmorTransport, commands, directive
from armor_client.aio import AsyncArmor
from conftest import cmake_built, iri, iris, ONTOLOGIES, REPO, start_node
import pytest

LIMIT_MS = 1500
LOCK_WAIT_MS = 500
# How long PluginGuard gives a plugin's thread to end after the interrupt, then after stop().
GRACE_S = 2.0

MARKS = '''package marks;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandGroup;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.command.Face;
import java.util.List;
import org.semanticweb.owlapi.model.AddAxiom;
public final class MarkCommands implements CommandGroup {
    private static long spins;
    private static void mark(CommandContext c) {
        c.change(List.of(new AddAxiom(c.reference().ontology(),
                c.factory().getOWLClassAssertionAxiom(c.owlClass(1), c.individual(0)))));
    }
    public void register(CommandTable table) {
        table.command("ADD MARK FAILING").args("ind", "class").summary("asserts, then throws")
                .manipulation(c -> { mark(c); throw new IllegalStateException("plugin bug"); });
        table.command("ADD MARK REFUSED").args("ind", "class").summary("asserts, then refuses")
                .manipulation(c -> { mark(c);
                    throw new ArmorException(ExitCode.BAD_DATA_TYPE, "refused by the plugin"); });
        table.command("ADD MARK LOOPING").args("ind", "class").summary("asserts, then spins")
                .manipulation(c -> { mark(c); while (true) { spins++; } });
        table.command("ADD MARK STUBBORN").args("ind", "class").summary("spins through stop()")
                .manipulation(c -> { mark(c);
                    while (true) {
                        try { while (true) { spins++; } } catch (Throwable ignored) { }
                    } });
        table.command("QUERY MARK CLASH").args("class").summary("a face whose method clients have")
                .face("instances", Face.Answer.ENTITIES, "cls").query(c -> c.ok(List.of()));
        table.command("QUERY MARK SLEEPING").args("ms").summary("holds the reference a while")
                .face("sleep_for", Face.Answer.VALUES, "ms:int")
                .query(c -> {
                    try { Thread.sleep(Long.parseLong(c.arg(0))); }
                    catch (InterruptedException e) { return c.ok(List.of("interrupted")); }
                    return c.ok(List.of("slept"));
                });
    }
}
'''
FACTORY = '''package marks;
public final class TinyReasonerFactory extends org.semanticweb.HermiT.ReasonerFactory {}
'''


def build_example(out: pathlib.Path) -> pathlib.Path:
    """The repository's example plugin, built by the reusable script (docs/extending.md)."""
    subprocess.run(['bash', str(REPO / 'examples' / 'plugins' / 'build.sh'),
                    str(REPO / 'examples' / 'plugins' / 'hello_command'), str(out), 'hello.jar'],
                   check=True, timeout=120, capture_output=True)
    return out


def build_marks(work: pathlib.Path, out: pathlib.Path) -> pathlib.Path:
    """A test plugin: commands that throw, refuse, loop and sleep, and a reasoner factory."""
    jar = pathlib.Path(os.environ['ARMOR_CORE_JAR'])
    classpath = os.pathsep.join([str(jar), str(jar.parent / 'lib' / '*')])
    sources = work / 'src' / 'marks'
    sources.mkdir(parents=True)
    (sources / 'MarkCommands.java').write_text(MARKS)
    (sources / 'TinyReasonerFactory.java').write_text(FACTORY)
    classes = work / 'classes'
    subprocess.run(['javac', '-d', str(classes), '-cp', classpath,
                    *map(str, sources.glob('*.java'))], check=True, timeout=120)
    out.mkdir(parents=True)
    with zipfile.ZipFile(out / 'marks.jar', 'w') as archive:
        for compiled in classes.rglob('*.class'):
            archive.write(compiled, compiled.relative_to(classes).as_posix())
        archive.writestr('META-INF/services/io.github.armor.core.command.CommandGroup',
                         'marks.MarkCommands\n')
    return out


@pytest.fixture(scope='module')
def plugged(tmp_path_factory):
    """A node with both plugin directories, given as one colon-separated string."""
    scratch = tmp_path_factory.mktemp('plugged')
    hello = build_example(scratch / 'hello')
    marks = build_marks(scratch / 'build', scratch / 'marks')
    node = start_node(scratch, '-p', f'plugin_dirs:={hello}:{marks}',
                      '-p', f'plugin_timeout_ms:={LIMIT_MS}',
                      '-p', f'lock_wait_ms:={LOCK_WAIT_MS}', namespace='/plugged')
    transport = ArmorTransport(namespace='/plugged', service_wait_s=90.0)
    assert transport.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=120).success, \
        node.log()
    yield node, transport
    transport.close()
    node.stop()


def send(transport, reference, words, *args, client='t'):
    command, primary, secondary = (words.split() + ['', '', ''])[:3]
    return transport.call(directive(client, reference, command, primary, secondary,
                                    [str(a) for a in args]), timeout_s=120)


def greeted(transport):
    answer = send(transport, 'robotics', 'QUERY GREETING')
    assert answer.success, answer.error_description
    return sorted(answer.queried_objects)


def test_the_example_plugin_adds_commands_clients_discover(plugged):
    node, armor = plugged
    hello = send(armor, '', 'QUERY HELLO', 'world')
    assert hello.success, node.log()
    assert list(hello.queried_objects) == ['hello world']
    with Armor('t', namespace='/plugged') as client:
        answered = client.catalogue()
    origins = {command.name: command.origin for command in answered.commands}
    assert origins['QUERY HELLO'] == 'hello.jar' and origins['ADD MARK LOOPING'] == 'marks.jar'
    assert origins['QUERY IND CLASS'] == 'core'
    # Issue 35 item 4: setting plugin_dirs adds to the installed plugins, the planner bridge stays.
    assert origins['QUERY PDDL PROBLEM'].startswith('armor-pddl'), origins
    assert 'QUERY HELLO' not in {command.name for command in commands.COMMANDS}
    # armor query parses with the node's catalogue, so it knows the plugin's command.
    shown = subprocess.run(
        [sys.executable, '-m', 'armor_client.cli', 'query', '--namespace', '/plugged',
         'robotics', 'HELLO', 'world'], capture_output=True, text=True, timeout=120)
    assert shown.returncode == 0, shown.stderr
    assert 'hello world' in shown.stdout


CLASH = (r'QUERY MARK CLASH \(plugin marks.jar\) gets no method instances\(\): '
         r'(Async)?Reference already has instances\(\)')


def test_a_plugin_command_with_a_face_is_a_method_of_python_references(plugged):
    """Issue 30: the node's catalogue gives a session's references its plugins' methods."""
    _, armor = plugged
    with Armor('faces', namespace='/plugged') as client, Armor('other', namespace='/plugged') as other:
        robotics = client.reference('robotics')
        with pytest.warns(RuntimeWarning, match=CLASH):
            assert robotics.greeted() == []  # the first name it lacks learns the catalogue
        robotics.greet('kitchen')
        assert robotics.greeted() == ['kitchen']
        assert robotics.greeting_sentences() == ['hello kitchen']
        assert robotics.sleep_for(10) == ['slept']
        with robotics.batch() as batch:  # a batch queues a plugin's change too
            batch.greet('bedroom')
        assert robotics.greeted() == ['bedroom', 'kitchen']
        assert str(inspect.signature(robotics.greet)) == '(individual: str) -> None'
        assert robotics.greet.__doc__.startswith(
            'Asserts that the individual was greeted (ADD GREETING; plugin hello.jar).')
        # Bad arguments are refused before anything is sent, naming what is wrong.
        with pytest.raises(TypeError, match=r"greet\(\): missing a required argument: 'individual'"):
            robotics.greet()
        with pytest.raises(TypeError, match=r"sleep_for\(\): ms must be a whole number, not 'soon'"):
            robotics.sleep_for('soon')
        with pytest.raises(TypeError, match=r'greet\(\): individual must be a str, not NoneType'):
            robotics.greet(None)
        with pytest.raises(AttributeError, match='nor does a plugin of the node give one'):
            robotics.no_such_method()
        # A face whose name the client has is refused: the built-in method keeps it.
        with pytest.warns(RuntimeWarning, match=CLASH):
            learned = client.learn_plugin_methods()
        assert {'greet', 'greeted', 'greeting_sentences', 'sleep_for'} <= set(learned.added)
        assert 'instances' not in learned.added and 'QUERY MARK CLASH' in learned.refused
        assert robotics.instances('Greeted') == ['bedroom', 'kitchen']
        # Another session has learned nothing: its references lack the methods until it asks.
        assert 'greet' not in vars(type(other.reference('robotics')))

    async def asynchronously():
        async with AsyncArmor('faces_aio', namespace='/plugged') as client:
            robotics = client.reference('robotics')
            assert await robotics.greeted() == ['bedroom', 'kitchen']
            await robotics.greet('corridor1')
            return await robotics.greeted()

    with pytest.warns(RuntimeWarning, match=CLASH):
        assert asyncio.run(asynchronously()) == ['bedroom', 'corridor1', 'kitchen']
    for room in ('kitchen', 'bedroom', 'corridor1'):
        assert send(armor, 'robotics', 'REMOVE IND CLASS', room, 'Greeted').success


def test_a_plugin_query_answers_from_the_published_state_while_the_reference_is_held(plugged):
    _, armor = plugged
    assert send(armor, 'robotics', 'ADD GREETING', 'kitchen').success
    assert greeted(armor) == [iri('kitchen')]  # reasoned: the state it publishes knows it
    holder = {}
    worker = threading.Thread(target=lambda: holder.setdefault(
        'answer', send(armor, 'robotics', 'QUERY MARK SLEEPING', 1200)))
    worker.start()
    time.sleep(0.3)
    started = time.monotonic()
    busy = send(armor, 'robotics', 'QUERY GREETING')
    took = time.monotonic() - started
    # A query of the plugin registered without a source waits for the reference, and gives up.
    waited = send(armor, 'robotics', 'QUERY GREETING SENTENCES')
    worker.join(timeout=60)
    assert list(holder['answer'].queried_objects) == ['slept']
    assert busy.success and list(busy.queried_objects) == [iri('kitchen')], busy.error_description
    assert busy.error_description.startswith('answered from reasoned state revision')
    assert took < LOCK_WAIT_MS / 1000, took
    assert waited.exit_code == 211, waited.error_description
    assert send(armor, 'robotics', 'REMOVE IND CLASS', 'kitchen', 'Greeted').success


def test_a_subscription_to_a_plugin_query_follows_the_form_it_names(plugged):
    _, armor = plugged
    changes = queue.Queue()
    with Armor('watcher', namespace='/plugged') as client:
        with client.reference('robotics').subscribe('QUERY GREETING SENTENCES', changes.put):
            assert changes.get(timeout=60).added == []
            assert send(armor, 'robotics', 'ADD GREETING', 'kitchen').success
            # The individuals greeted (QUERY GREETING), not the sentences.
            assert changes.get(timeout=60).added == ['kitchen']
    assert send(armor, 'robotics', 'REMOVE IND CLASS', 'kitchen', 'Greeted').success


def test_a_plugin_reasoner_factory_is_used_by_name(plugged):
    _, armor = plugged
    loaded = send(armor, 'tiny', 'LOAD FILE', ONTOLOGIES / 'robotics.owl',
                  'http://www.example.org/robotics', 'false', 'marks.TinyReasonerFactory', 'false')
    assert loaded.success, loaded.error_description
    # The plugin's factory (HermiT under another name) infers what the built-in HermiT does.
    rooms, expected = (send(armor, reference, 'QUERY IND CLASS', 'OccupiedRoom')
                       for reference in ('tiny', 'robotics'))
    assert rooms.success and list(rooms.queried_objects) == list(expected.queried_objects)
    assert len(rooms.queried_objects) >= 1


def test_a_plugin_change_is_mount_checked_and_undone_with_its_list(plugged):
    _, armor = plugged
    assert send(armor, 'robotics', 'MOUNT', client='holder').success
    try:
        refused = send(armor, 'robotics', 'ADD GREETING', 'kitchen', client='other')
        assert refused.exit_code == 102, refused.error_description
        assert greeted(armor) == []
    finally:
        assert send(armor, 'robotics', 'UNMOUNT', client='holder').success
    listed = armor.call_list([
        directive('t', 'robotics', 'ADD', 'GREETING', '', ['kitchen']),
        directive('t', 'robotics', 'QUERY', 'NOSUCH', '', [])], timeout_s=120)
    assert not listed.success
    assert listed.armor_responses[0].exit_code == 212, listed.armor_responses[0].error_description
    assert greeted(armor) == []


def test_what_a_plugin_throws_is_an_answer_and_changes_nothing(plugged):
    node, armor = plugged
    failed = send(armor, 'robotics', 'ADD MARK FAILING', 'robot7', 'Robot')
    assert failed.exit_code == 220, failed.error_description
    assert 'ADD MARK FAILING (plugin marks.jar) failed' in failed.error_description
    refused = send(armor, 'robotics', 'ADD MARK REFUSED', 'robot7', 'Robot')
    assert (refused.exit_code, refused.error_description) == (101, 'refused by the plugin')
    robots = send(armor, 'robotics', 'QUERY IND CLASS', 'Robot')
    assert robots.queried_objects == iris('robot1')
    assert node.process.poll() is None


def test_a_looping_plugin_is_stopped_at_its_limit_and_holds_nothing_after(plugged):
    node, armor = plugged
    core = node.core_pid()
    waited = {}

    def meanwhile():
        time.sleep(0.3)
        started = time.monotonic()
        # A question the last reasoned state cannot answer: QUERY IND CLASS it would, at once.
        waited['same'] = send(armor, 'robotics', 'QUERY OBJECTPROP IND', 'isIn', 'robot1')
        waited['same_s'] = time.monotonic() - started
        started = time.monotonic()
        waited['other'] = send(armor, 'tiny', 'QUERY IND CLASS', 'Robot')
        waited['other_s'] = time.monotonic() - started

    if send(armor, '', 'GET ALL REFS').queried_objects.count('tiny') == 0:
        assert send(armor, 'tiny', 'LOAD FILE', ONTOLOGIES / 'robotics.owl', '', 'false',
                    'HERMIT', 'false').success
    other = threading.Thread(target=meanwhile)
    started = time.monotonic()
    other.start()
    looped = send(armor, 'robotics', 'ADD MARK LOOPING', 'robot7', 'Robot')
    took = time.monotonic() - started
    other.join(timeout=60)
    assert looped.exit_code == 211 and looped.timeout, looped.error_description
    assert f'plugin_timeout_ms={LIMIT_MS}' in looped.error_description
    assert LIMIT_MS / 1000 <= took < LIMIT_MS / 1000 + 2 * GRACE_S + 2.0, took
    # Meanwhile the same reference waited lock_wait_ms and was refused; another one answered.
    assert waited['same'].exit_code == 211, waited['same'].error_description
    assert waited['same_s'] < LOCK_WAIT_MS / 1000 + 1.5
    assert waited['other'].success and waited['other_s'] < 1.5, waited
    # The loop's change is undone, the reference answers and changes, the same core serves.
    assert send(armor, 'robotics', 'QUERY IND CLASS', 'Robot').queried_objects == iris('robot1')
    assert send(armor, 'robotics', 'ADD GREETING', 'bedroom').success
    assert greeted(armor) == [iri('bedroom')]
    assert send(armor, 'robotics', 'REMOVE IND CLASS', 'bedroom', 'Greeted').success
    assert node.core_pid() == core
    assert 'ignored the interrupt at its time limit; stopping its thread' in node.log()


def test_a_plugin_holds_its_reference_like_a_built_in(plugged):
    _, armor = plugged
    holder = {}
    worker = threading.Thread(target=lambda: holder.setdefault(
        'answer', send(armor, 'robotics', 'QUERY MARK SLEEPING', 1000)))
    worker.start()
    time.sleep(0.3)
    busy = send(armor, 'robotics', 'ADD GREETING', 'kitchen')
    worker.join(timeout=60)
    assert busy.exit_code == 211 and 'stayed busy' in busy.error_description
    assert list(holder['answer'].queried_objects) == ['slept']
    assert greeted(armor) == []


def test_a_plugin_change_survives_a_killed_core(plugged):
    node, armor = plugged
    assert send(armor, 'robotics', 'ADD GREETING', 'kitchen').success
    first = node.core_pid()
    os.kill(first, signal.SIGKILL)
    deadline = time.monotonic() + 120
    while True:
        answer = send(armor, 'robotics', 'QUERY GREETING')
        if answer.success or time.monotonic() > deadline:
            break
        assert answer.exit_code == 216, answer.error_description
        time.sleep(0.2)
    assert list(answer.queried_objects) == [iri('kitchen')]
    assert node.core_pid() != first
    assert send(armor, 'robotics', 'REMOVE IND CLASS', 'kitchen', 'Greeted').success


def test_a_plugin_that_cannot_be_stopped_costs_a_core_restart_and_no_acknowledged_change(
        plugged):
    node, armor = plugged
    assert send(armor, 'robotics', 'ADD GREETING', 'office').success
    first = node.core_pid()
    # It swallows the ThreadDeath of stop(): the core cannot vouch for the reference and exits.
    stubborn = send(armor, 'robotics', 'ADD MARK STUBBORN', 'robot9', 'Robot')
    assert stubborn.exit_code == 216, stubborn.error_description
    deadline = time.monotonic() + 120
    while True:
        answer = send(armor, 'robotics', 'QUERY GREETING')
        if answer.success or time.monotonic() > deadline:
            break
        time.sleep(0.2)
    assert list(answer.queried_objects) == [iri('office')]
    assert send(armor, 'robotics', 'QUERY IND CLASS', 'Robot').queried_objects == iris('robot1')
    assert node.core_pid() != first and node.process.poll() is None
    assert 'ADD MARK STUBBORN (plugin marks.jar) cannot be stopped' in node.log()
    assert send(armor, 'robotics', 'REMOVE IND CLASS', 'office', 'Greeted').success


def test_plugin_dirs_as_an_array_and_the_deprecated_plugin_dir(tmp_path):
    hello = build_example(tmp_path / 'hello')
    marks = build_marks(tmp_path / 'build', tmp_path / 'marks')
    node = start_node(tmp_path, '-p', f'plugin_dirs:=["{marks}"]', '-p', f'plugin_dir:={hello}',
                      '-p', 'installed_plugins:=false', namespace='/plugged_alias')
    try:
        transport = ArmorTransport(namespace='/plugged_alias', service_wait_s=90.0)
        hello_answer = send(transport, '', 'QUERY HELLO', 'again')
        assert list(hello_answer.queried_objects) == ['hello again'], node.log()
        sleeping = send(transport, 'robotics', 'QUERY MARK SLEEPING', 1)
        assert list(sleeping.queried_objects) == ['slept']
        # installed_plugins:=false leaves the planner bridge out.
        assert send(transport, 'robotics', 'QUERY PDDL PROBLEM', '{}').exit_code == 205
        transport.close()
        assert 'parameter plugin_dir is deprecated: use plugin_dirs' in node.log()
    finally:
        node.stop()


def test_a_plugin_directory_that_does_not_exist_stops_the_node_naming_it(tmp_path):
    missing = tmp_path / 'nowhere'
    node = start_node(tmp_path, '-p', f'plugin_dirs:={missing}', namespace='/plugged_missing')
    try:
        assert node.process.wait(timeout=60) != 0
    finally:
        node.stop()
    assert f"plugin_dirs entry '{missing}' is not a directory" in node.log()


def test_without_the_plugin_the_factory_class_is_unknown(call):
    refused = call('nope', 'LOAD FILE', str(ONTOLOGIES / 'robotics.owl'), '', 'false',
                   'marks.TinyReasonerFactory', 'false')
    assert refused.exit_code == 210 and 'plugin_dirs' in refused.error_description


def _serving(armor, namespace, before, wait_s=90.0):
    """Wait until a node serves the namespace and the session's graph shows one not ``before``."""
    probe = ArmorTransport(namespace=namespace, service_wait_s=wait_s)
    try:
        assert probe.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=120).success
    finally:
        probe.close()
    deadline = time.monotonic() + wait_s
    while armor.transport.node_identity() in (before, frozenset()):
        assert time.monotonic() < deadline, 'the restarted node never showed in the ROS graph'
        time.sleep(0.2)
    return armor.transport.node_identity()


def test_a_session_learns_again_when_the_node_restarts_with_other_plugins(tmp_path):
    """Issue 30: no learn_plugin_methods() call; the node's restart is noticed by the session."""
    hello = build_example(tmp_path / 'hello')
    namespace = '/plugged_restart'

    def node_with(name, *plugins):
        dirs = ['-p', f'plugin_dirs:={":".join(map(str, plugins))}'] if plugins else []
        return start_node(tmp_path / name, *dirs, '-p', 'installed_plugins:=false',
                          namespace=namespace)

    node = node_with('first', hello)
    try:
        with Armor('restart', namespace=namespace, service_wait_s=90.0) as armor:
            first = _serving(armor, namespace, None)
            robotics = armor.reference('robotics')
            assert robotics.greeted() == []  # learned from the first node
            node.stop()
            node = node_with('second')  # the same namespace, without the plugin
            _serving(armor, namespace, first)
            with pytest.raises(AttributeError, match='nor does a plugin of the node give one'):
                robotics.greeted()
            assert 'greet' not in dir(robotics)
            second = armor.transport.node_identity()
            node.stop()
            node = node_with('third', hello)  # and with it again
            _serving(armor, namespace, second)
            robotics.greet('kitchen')
            assert robotics.greeted() == ['kitchen']
    finally:
        node.stop()


HELLO_PROGRAM = r'''
#include <iostream>
#include "hello_faces.hpp"
int main()
{
  armor::Options options;
  options.ns = "/plugged";
  options.service_wait = std::chrono::seconds(90);
  options.timeout = std::chrono::seconds(120);
  armor::Armor armor("hello_cpp", options);
  hello::Reference robotics = armor.reference("robotics");
  robotics.greet("bedroom");                            // ADD GREETING, a plugin's change
  robotics.batch().greet("kitchen").add_individual("hall").send();  // beside a built-in one
  for (const std::string & name : robotics.greeted()) {  // QUERY GREETING: ENTITIES
    std::cout << name << "\n";
  }
  std::cout << robotics.sleep_for(5).size() << " " << robotics.instances("Greeted").size() << "\n";
}
'''
HELLO_CMAKE = '''cmake_minimum_required(VERSION 3.8)
project(hello_client LANGUAGES CXX)
find_package(armor_cpp REQUIRED)
add_executable(hello_client hello_client.cpp)
target_include_directories(hello_client PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(hello_client armor_cpp::armor_cpp)
'''


def test_a_plugin_users_cpp_header_is_generated_from_the_nodes_catalogue(plugged, tmp_path):
    """Issue 30: docs/extending.md's commands give a C++ program the plugin's typed methods."""
    _, armor = plugged
    catalogue = subprocess.run(['armor', 'call', '--namespace', '/plugged', '--no-relay', '--raw',
                                '-', 'GET', 'CATALOGUE'], capture_output=True, text=True,
                               timeout=180, check=True).stdout
    made = subprocess.run([sys.executable, str(REPO / 'tools' / 'faces.py'), '--cpp-plugins', '-',
                           '--namespace', 'hello', '--output', str(tmp_path / 'hello_faces.hpp')],
                          input=catalogue, capture_output=True, text=True, timeout=60)
    assert made.returncode == 0, made.stderr
    # A face whose name the client has gets no method, as in Python.
    assert 'QUERY MARK CLASH (plugin marks.jar) gets no C++ method instances()' in made.stderr
    (tmp_path / 'hello_client.cpp').write_text(HELLO_PROGRAM)
    (tmp_path / 'CMakeLists.txt').write_text(HELLO_CMAKE)
    program = cmake_built(tmp_path, 'hello_client')
    try:
        ran = subprocess.run([str(program)], capture_output=True, text=True, timeout=300)
        assert ran.returncode == 0, ran.stderr
        assert ran.stdout.splitlines() == ['bedroom', 'kitchen', '1 2'], ran.stdout
        assert greeted(armor) == iris('bedroom', 'kitchen')
    finally:
        for room in ('kitchen', 'bedroom'):
            send(armor, 'robotics', 'REMOVE IND CLASS', room, 'Greeted')
        send(armor, 'robotics', 'REMOVE IND', 'hall')
