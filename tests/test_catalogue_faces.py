# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A query command added by one Java registration is known everywhere after make catalogue.

In a scratch copy of the repository, the test registers QUERY IND COUNT with its face in
Queries.java, rebuilds the core's jar from that one file (javac against the installed jar, in
place of the slower ``make setup``), and runs tools/catalogue.py with it as ``make catalogue``
does. Then, with nothing else edited: the Python client's references have a typed method that
sends the command, the C++ client's Reference has one (a program calling it compiles against
the scratch headers), the command line parses and completes the command, and
docs/commands.md has a row for it.
"""

import os
import pathlib
import re
import shutil
import subprocess
import sys
import textwrap

import pytest

REPO = pathlib.Path(__file__).resolve().parents[1]
JAR = pathlib.Path(os.environ.get('ARMOR_CORE_JAR')
                   or REPO / 'install' / 'armor_core' / 'armor-core.jar')
QUERIES = pathlib.Path('core/src/main/java/io/github/armor/core/command/builtin/Queries.java')
REGISTRATION = '''
        table.command("QUERY IND COUNT").args("class")
                .summary("the instances of the class, counted")
                .face("instance_count", Face.Answer.VALUES, "cls")
                .query(c -> c.ok(java.util.List.of(String.valueOf(
                        Inferences.instances(c.reference(), c.owlClass(0), false).size()))));
'''
CPP_FLAGS = REPO / 'build' / 'armor_cpp' / 'CMakeFiles' / 'armor_cpp.dir' / 'flags.make'


def _tracked() -> list:
    listed = subprocess.run(['git', 'ls-files', '-z', '--cached', '--others',
                             '--exclude-standard'],
                            cwd=REPO, capture_output=True, check=True).stdout.decode()
    return [name for name in listed.split('\0') if name and (REPO / name).is_file()]


def _copy(scratch: pathlib.Path) -> None:
    """The repository's files (tracked or new, as they are in the working tree), and its jar."""
    for name in _tracked():
        source = REPO / name
        if source.is_file():
            target = scratch / name
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target)
    (scratch / 'jar').mkdir()
    shutil.copy2(JAR, scratch / 'jar' / 'armor-core.jar')
    (scratch / 'jar' / 'lib').symlink_to(JAR.parent / 'lib')


def _register_and_build(scratch: pathlib.Path) -> pathlib.Path:
    """The one Java registration, compiled into the scratch copy of the jar."""
    queries = scratch / QUERIES
    text = queries.read_text()
    anchor = '        registerIndividualQueries(table);\n'
    imports = 'import io.github.armor.core.command.CommandTable;\n'
    assert anchor in text and imports in text
    text = text.replace(imports, imports + 'import io.github.armor.core.command.Face;\n')
    queries.write_text(text.replace(anchor, anchor + REGISTRATION))
    jar = scratch / 'jar' / 'armor-core.jar'
    classes = scratch / 'classes'
    subprocess.run(['javac', '-nowarn', '-proc:none', '-d', str(classes), '-cp', str(jar),
                    str(queries)], check=True, capture_output=True, timeout=300)
    subprocess.run(['jar', 'uf', str(jar), '-C', str(classes), '.'], check=True, timeout=120)
    return jar


@pytest.fixture(scope='module')
def scratch(tmp_path_factory):
    if not JAR.exists():
        pytest.fail(f'{JAR} is missing: run make setup')
    root = tmp_path_factory.mktemp('repo')
    _copy(root)
    jar = _register_and_build(root)
    env = {**os.environ, 'ARMOR_CORE_JAR': str(jar)}
    done = subprocess.run([sys.executable, 'tools/catalogue.py'], cwd=root, env=env,
                          capture_output=True, text=True, timeout=300)
    # It writes everything, then names what it cannot write (the docs' example to edit).
    assert 'wrote' in done.stdout, done.stdout + done.stderr
    return root


def _python(scratch: pathlib.Path, code: str) -> str:
    """Runs code with the scratch copy's Python packages first on the path."""
    path = os.pathsep.join([str(scratch / 'armor_client'), str(scratch / 'armor_contract'),
                            os.environ.get('PYTHONPATH', '')])
    done = subprocess.run([sys.executable, '-c', textwrap.dedent(code)], capture_output=True,
                          text=True, timeout=120, env={**os.environ, 'PYTHONPATH': path})
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_the_python_client_has_a_typed_method_that_sends_it(scratch):
    out = _python(scratch, '''
        import inspect
        import armor_client.faces
        from armor_client.reference import Armor
        from armor_msgs.msg import ArmorDirectiveRes
        assert armor_client.faces.__file__.startswith(%r), armor_client.faces.__file__

        class Recording:
            sent = []
            def call(self, request, timeout_s=None):
                self.sent.append((request.command, request.primary_command_spec,
                                  request.secondary_command_spec, list(request.args)))
                return ArmorDirectiveRes(success=True, is_consistent=True,
                                         queried_objects=['"3"^^xsd:integer'])
            def close(self):
                pass

        transport = Recording()
        reference = Armor('me', transport=transport).reference('robotics')
        print(inspect.signature(reference.instance_count))
        print(reference.instance_count('Room'))
        print(transport.sent)
        print(inspect.getdoc(reference.instance_count).splitlines()[0])
    ''' % str(scratch))
    signature, answer, sent, doc = out.splitlines()
    assert signature == '(cls: str) -> List[Union[int, float, bool, str]]'
    assert answer == '[3]'
    assert sent == "[('QUERY', 'IND', 'COUNT', ['Room'])]"
    assert doc == 'The instances of the class, counted (QUERY IND COUNT).'


def test_the_cpp_client_has_the_method(scratch):
    if not CPP_FLAGS.exists():
        pytest.fail('the C++ client was never built here: run make cpp')
    flags = dict(line.split(' = ', 1) for line in CPP_FLAGS.read_text().splitlines()
                 if ' = ' in line and not line.startswith('#'))
    includes = flags['CXX_INCLUDES'].replace(f'-I{REPO}/armor_cpp/include',
                                             f'-I{scratch}/armor_cpp/include')
    assert f'{scratch}/armor_cpp/include' in includes
    program = scratch / 'count.cpp'
    program.write_text(textwrap.dedent('''
        #include <string>
        #include <type_traits>
        #include <vector>
        #include "armor_cpp/armor.hpp"
        std::vector<armor::Value> count(const armor::Reference & reference)
        {
          return reference.instance_count(std::string("Room"));
        }
        static_assert(armor::contract::QUERY_IND_COUNT.kind == armor::contract::Kind::Query);
        int main() {return 0;}
    '''))
    done = subprocess.run(['c++', '-std=gnu++17', '-fsyntax-only', *flags['CXX_DEFINES'].split(),
                           *includes.split(), str(program)], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]


def test_the_command_line_parses_and_completes_it(scratch):
    out = _python(scratch, '''
        from armor_client import commands
        command, args = commands.split_directive(['QUERY', 'IND', 'COUNT', 'Room'])
        print(command.name, args, 'COUNT' in commands.next_words(['QUERY', 'IND']))
    ''')
    assert out.strip() == "QUERY IND COUNT ['Room'] True"


def test_the_docs_have_a_row_for_it(scratch):
    doc = (scratch / 'docs' / 'commands.md').read_text()
    assert re.search(r'^\| QUERY IND COUNT \| class \| the instances of the class, counted \|',
                     doc, re.MULTILINE)


def test_nothing_but_the_registration_was_edited_by_hand(scratch):
    """Every other file that differs from the repository's was written by make catalogue."""
    generated = {'armor_contract/armor_contract/catalogue.json',
                 'armor_client/armor_client/faces.py', 'armor_cpp/include/armor_cpp/faces.hpp',
                 'armor_cpp/include/armor_cpp/contract.hpp', 'docs/commands.md', str(QUERIES)}
    changed = {name for name in _tracked()
               if (scratch / name).read_bytes() != (REPO / name).read_bytes()}
    assert changed <= generated and str(QUERIES) in changed, changed
