# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A plugin jar in plugin_dir adds a command group and a reasoner factory to a running node.

The jar is built here from two tiny classes (javac against the installed core), so the test
shows what a plugin author does: implement CommandGroup or OWLReasonerFactory, list the group
in META-INF/services, drop the jar in the directory.
"""

import os
import pathlib
import subprocess
import sys
import zipfile

from armor_client import Armor, ArmorTransport, commands, directive
from conftest import ONTOLOGIES, start_node

HELLO = '''package example;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.CommandGroup;
import io.github.armor.core.command.CommandTable;
import java.util.List;
public final class HelloCommands implements CommandGroup {
    public void register(CommandTable table) {
        table.command("QUERY HELLO").args("name").summary("greets someone")
                .global(c -> Response.ok(true, List.of("hello " + c.arg(0))));
    }
}
'''
FACTORY = '''package example;
public final class TinyReasonerFactory extends org.semanticweb.HermiT.ReasonerFactory {}
'''


def build_plugin(work: pathlib.Path) -> pathlib.Path:
    jar = pathlib.Path(os.environ['ARMOR_CORE_JAR'])
    classpath = os.pathsep.join([str(jar), str(jar.parent / 'lib' / '*')])
    sources = work / 'src' / 'example'
    sources.mkdir(parents=True)
    (sources / 'HelloCommands.java').write_text(HELLO)
    (sources / 'TinyReasonerFactory.java').write_text(FACTORY)
    classes = work / 'classes'
    subprocess.run(['javac', '-d', str(classes), '-cp', classpath,
                    *map(str, sources.glob('*.java'))], check=True, timeout=120)
    plugins = work / 'plugins'
    plugins.mkdir()
    with zipfile.ZipFile(plugins / 'hello.jar', 'w') as archive:
        for compiled in classes.rglob('*.class'):
            archive.write(compiled, compiled.relative_to(classes).as_posix())
        archive.writestr('META-INF/services/io.github.armor.core.command.CommandGroup',
                         'example.HelloCommands\n')
    return plugins


def test_a_plugin_jar_adds_a_command_and_a_reasoner(tmp_path):
    plugins = build_plugin(tmp_path / 'build')
    node = start_node(tmp_path, '-p', f'plugin_dir:={plugins}', namespace='/plugged')
    try:
        transport = ArmorTransport(namespace='/plugged', service_wait_s=90.0)
        hello = transport.call(directive('t', '', 'QUERY', 'HELLO', '', ['world']), timeout_s=120)
        assert hello.success, node.log()
        assert list(hello.queried_objects) == ['hello world']
        loaded = transport.call(directive(
            't', 'tiny', 'LOAD', 'FILE', '', [str(ONTOLOGIES / 'robotics.owl'),
                                              'http://www.example.org/robotics', 'false',
                                              'example.TinyReasonerFactory', 'false']),
            timeout_s=120)
        assert loaded.success, loaded.error_description
        # The plugin's factory (HermiT under another name) infers what the built-in HermiT does.
        rooms, expected = (transport.call(directive('t', reference, 'QUERY', 'IND', 'CLASS',
                                                    ['OccupiedRoom']), timeout_s=120)
                           for reference in ('tiny', 'robotics'))
        assert rooms.success and list(rooms.queried_objects) == list(expected.queried_objects)
        assert len(rooms.queried_objects) >= 1
        transport.close()
        # Clients learn the plugin's command from the running node: the typed client, and
        # armor query, which parses with the catalogue.
        with Armor('t', namespace='/plugged') as armor:
            answered = armor.catalogue()
        assert 'QUERY HELLO' in {command.name for command in answered.commands}
        assert 'QUERY HELLO' not in {command.name for command in commands.COMMANDS}
        shown = subprocess.run(
            [sys.executable, '-m', 'armor_client.cli', 'query', '--namespace', '/plugged',
             'robotics', 'HELLO', 'world'], capture_output=True, text=True, timeout=120)
        assert shown.returncode == 0, shown.stderr
        assert 'hello world' in shown.stdout
    finally:
        node.stop()


def test_without_the_plugin_the_factory_class_is_unknown(call):
    refused = call('nope', 'LOAD FILE', str(ONTOLOGIES / 'robotics.owl'), '', 'false',
                   'example.TinyReasonerFactory', 'false')
    assert refused.exit_code == 210 and 'plugin_dir' in refused.error_description
