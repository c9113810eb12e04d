# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The clients' methods of the catalogue's commands, generated from their faces.

A command's face (its method name, parameters and what it answers) comes with its registration
in the core (``CommandTable.Builder.face``, exported as ``"face"`` in the catalogue), or, for
the built-in commands registered before faces existed, from
armor_contract/armor_contract/faces.json. tools/catalogue.py writes from them:

- armor_client/armor_client/faces.py: ManipulationFaces (mixed into the references and the
  batches) and QueryFaces (mixed into the references), typed, a docstring from each summary;
- armor_cpp/include/armor_cpp/faces.hpp: the same methods for the C++ Reference and Batch;
- armor_cpp/include/armor_cpp/plugins.hpp: the methods of the installed plugins' commands
  (plugins/*), on armor::plugins::Reference and Batch, derived from armor::Reference and Batch.

Commands without a face are composites written by hand (operations.py, armor.cpp) or reached
through ``call``. A C++ method must exist when the program is compiled, so the user of another
plugin makes its header from a catalogue that has it (docs/extending.md):

    python tools/faces.py --cpp-plugins CATALOGUE.json --namespace hello > hello_faces.hpp

CATALOGUE.json is what a node answers to GET CATALOGUE (``armor call - GET CATALOGUE --raw``)
or the core prints for ``--catalogue '{"plugin_dirs": [...]}'``; ``-`` reads it from stdin.
"""

import argparse
import json
import pathlib
import re
import sys
import textwrap
from typing import Callable, Dict, Iterable, List, Sequence

REPO = pathlib.Path(__file__).resolve().parents[1]
BUILT_IN_FACES = REPO / 'armor_contract' / 'armor_contract' / 'faces.json'
PYTHON_FACES = REPO / 'armor_client' / 'armor_client' / 'faces.py'
CPP_FACES = REPO / 'armor_cpp' / 'include' / 'armor_cpp' / 'faces.hpp'
CPP_PLUGINS = REPO / 'armor_cpp' / 'include' / 'armor_cpp' / 'plugins.hpp'
# The hand-written C++ classes whose method names a plugin's face may not take.
CPP_HAND_WRITTEN = [REPO / 'armor_cpp' / 'include' / 'armor_cpp' / name
                    for name in ('armor.hpp', 'manipulations.hpp')]

PYTHON_RETURNS = {'none': 'None', 'entities': 'List[str]', 'values': 'List[Value]',
                  'expressions': 'List[str]'}
PYTHON_READERS = {'none': 'Answers.nothing', 'entities': 'self.answers.entities',
                  'values': 'self.answers.values', 'expressions': 'self.answers.expressions'}
CPP_RETURNS = {'entities': 'std::vector<std::string>', 'values': 'std::vector<Value>',
               'expressions': 'std::vector<std::string>'}
# What writes one command's method, as lines.
Method = Callable[[dict], Iterable[str]]
# C++ keywords and names the generated code uses, as parameter names.
CPP_RENAMED = {'new': 'new_name', 'old': 'old_name', 'class': 'cls', 'delete': 'deleted'}


def faced_commands(core: dict) -> List[dict]:
    """The catalogue's commands that have a face, each with it under "face", in catalogue order."""
    built_in: Dict[str, dict] = json.loads(BUILT_IN_FACES.read_text())['faces']
    keys = {command['key'] for command in core['commands']}
    unknown = sorted(set(built_in) - keys)
    if unknown:
        raise ValueError(f'{BUILT_IN_FACES.name} gives a face to commands the core does not '
                         f'have: {", ".join(unknown)}')
    faced = []
    methods: Dict[str, str] = {}
    for command in core['commands']:
        face = command.get('face')
        if face and command['key'] in built_in:
            raise ValueError(f'{command["key"]} has a face in its registration and in '
                             f'{BUILT_IN_FACES.name}')
        face = face or built_in.get(command['key'])
        if not face:
            continue
        if face['method'] in methods:
            raise ValueError(f'{command["key"]} and {methods[face["method"]]} both have '
                             f'method {face["method"]}')
        methods[face['method']] = command['key']
        faced.append({**command, 'face': face})
    return faced


def _words(command: dict) -> str:
    return ' '.join(w for w in command['words'] if w)


def _sentence(command: dict) -> str:
    summary = command['summary']
    return f'{summary[:1].upper()}{summary[1:]} ({_words(command)}).'


def _python_method(command: dict) -> Iterable[str]:
    face = command['face']
    variadic = command['args']['variadic']
    params = []
    for parameter in face['parameters']:
        kind = 'int' if parameter['type'] == 'int' else 'str'
        params.append(f'{"*" if variadic else ""}{parameter["name"]}: {kind}')
    values = [f'int({p["name"]})' if p['type'] == 'int' else p['name'] for p in face['parameters']]
    if variadic:
        args = values[0]
    else:
        args = f'({values[0]},)' if len(values) == 1 else f'({", ".join(values)})'
    yield ''
    yield from _wrapped(f'    def {face["method"]}(', ['self', *params],
                        f') -> {PYTHON_RETURNS[face["answer"]]}:', '    ' + ' ' * len(
                            f'def {face["method"]}('))
    if not face['parameters']:
        yield f'        """{_sentence(command)}"""'
    else:
        yield f'        """{_sentence(command)}'
        yield ''
        yield '        Args:'
        names = command['args']['required']
        for index, parameter in enumerate(face['parameters']):
            meaning = ', '.join(names) if variadic else names[index]
            yield f'            {parameter["name"]}: {meaning}.'
        yield '        """'
    yield from _wrapped('        return self._execute(',
                        [repr(tuple(command['words'])), args, PYTHON_READERS[face['answer']]],
                        ')', ' ' * 12)


def _wrapped(head: str, items: List[str], tail: str, indent: str, width: int = 99) -> List[str]:
    """``head + items + tail`` on one line, or with the items on lines of their own."""
    line = head + ', '.join(items) + tail
    if len(line) <= width:
        return [line]
    lines = [head.rstrip()]
    current = indent
    for index, item in enumerate(items):
        piece = item + (',' if index < len(items) - 1 else tail)
        if current.strip() and len(current) + 1 + len(piece) > width:
            lines.append(current)
            current = indent
        current += (' ' if current.strip() else '') + piece
    lines.append(current)
    return lines


PYTHON_HEAD = '''\
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
# Generated by make catalogue (tools/faces.py) from the faces of the core's catalogue: do not
# edit. A command's face is declared with its registration (or in armor_contract's faces.json).
"""The methods of the commands that have a face in the catalogue.

Mixed in like operations.py's hand-written ones: ``_execute(words, args, parse)`` sends (a
reference) or queues (a batch) the directive.
"""

from typing import Any, List, Sequence

from armor_client.answers import Answers, Parser, Words
from armor_client.values import Value


class ManipulationFaces:
    """The changes of the catalogue with a face (each refused with 102 under another's mount)."""

    def _execute(self, words: Words, args: Sequence[Any], parse: Parser) -> Any:
        raise NotImplementedError
'''

PYTHON_QUERIES = '''

class QueryFaces:
    """The queries of the catalogue with a face, answered from asserted and inferred knowledge."""

    answers: Answers

    def _execute(self, words: Words, args: Sequence[Any], parse: Parser) -> Any:
        raise NotImplementedError
'''


def _file(faced: List[dict], parts: Sequence[str], manipulation: Method, query: Method) -> str:
    """parts[0], the manipulations' methods, parts[1], the queries' methods, then parts[2:]."""
    lines = [parts[0].rstrip('\n')]
    lines += [line for c in faced if c['kind'] == 'manipulation' for line in manipulation(c)]
    lines.append(parts[1].rstrip('\n'))
    lines += [line for c in faced if c['kind'] == 'query' for line in query(c)]
    lines += [part.rstrip('\n') for part in parts[2:]]
    return '\n'.join(lines) + '\n'


def python_module(core: dict) -> str:
    return _file(faced_commands(core), [PYTHON_HEAD, PYTHON_QUERIES], _python_method,
                 _python_method)


def _constant(command: dict) -> str:
    return '_'.join(w for w in command['words'] if w)


def _cpp_parameters(command: dict) -> List[str]:
    face = command['face']
    if command['args']['variadic']:
        name = face['parameters'][0]['name']
        return [f'const std::vector<std::string> & {CPP_RENAMED.get(name, name)}']
    return [('int ' if p['type'] == 'int' else 'const std::string & ')
            + CPP_RENAMED.get(p['name'], p['name']) for p in face['parameters']]


def _cpp_arguments(command: dict) -> List[str]:
    names = []
    required = command['args']['required']
    for index, p in enumerate(command['face']['parameters']):
        name = CPP_RENAMED.get(p['name'], p['name'])
        if p['type'] == 'int':
            name = f'std::to_string({name})'
        elif command.get('origin', 'core') != 'core' and 'path' in required[index].split():
            # As every client sends a path (docs/commands.md#paths); the built-in faces take none.
            name = f'armor::path_argument({name})'
        names.append(name)
    return names


def _cpp_comment(text: str, indent: str = '  ') -> List[str]:
    prefix = indent + '// '
    return textwrap.wrap(text, 100, initial_indent=prefix, subsequent_indent=prefix,
                         break_on_hyphens=False)


def _cpp_manipulation(command: dict) -> Iterable[str]:
    face = command['face']
    yield from _cpp_comment(_sentence(command))
    yield from _wrapped(f'  decltype(auto) {face["method"]}(', _cpp_parameters(command), ')',
                        '    ', 100)
    change = 'change_all' if command['args']['variadic'] else 'change'
    yield from _wrapped(f'  {{return this->template {change}<contract::{_constant(command)}>(',
                        _cpp_arguments(command), ');}', '    ', 100)


def _cpp_query(command: dict) -> Iterable[str]:
    face = command['face']
    yield from _cpp_comment(_sentence(command))
    yield from _wrapped(f'  {CPP_RETURNS[face["answer"]]} {face["method"]}(',
                        _cpp_parameters(command), ') const', '    ', 100)
    yield '  {'
    yield from _wrapped(f'    return static_cast<const Derived &>(*this).{face["answer"]}(',
                        [f'contract::{_constant(command)}',
                         '{' + ', '.join(_cpp_arguments(command)) + '}'], ');', '      ', 100)
    yield '  }'


CPP_HEAD = '''\
// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Generated by make catalogue (tools/faces.py) from the faces of the core's catalogue: do not
// edit. A command's face is declared with its registration (or in armor_contract's faces.json).
//
// The methods of the commands that have a face: ManipulationFaces for Reference and Batch
// (through Manipulations, which decides what "send" means), QueryFaces for Reference (whose
// entities, values and expressions read an answer).
#ifndef ARMOR_CPP__FACES_HPP_
#define ARMOR_CPP__FACES_HPP_

#include <string>
#include <vector>

#include "armor_cpp/changes.hpp"
#include "armor_cpp/contract.hpp"
#include "armor_cpp/values.hpp"

namespace armor
{

template<typename Derived>
class ManipulationFaces : public Changes<Derived>
{
public:
'''

CPP_MANIPULATIONS_END = '''
protected:
  ~ManipulationFaces() = default;
};
'''

CPP_QUERIES_HEAD = '''
template<typename Derived>
class QueryFaces
{
public:
'''
CPP_MANIPULATION_TAIL = CPP_MANIPULATIONS_END + CPP_QUERIES_HEAD

CPP_TAIL = '''
protected:
  ~QueryFaces() = default;
};

}  // namespace armor

#endif  // ARMOR_CPP__FACES_HPP_
'''


def cpp_header(core: dict) -> str:
    return _file(faced_commands(core), [CPP_HEAD, CPP_MANIPULATION_TAIL, CPP_TAIL],
                 _cpp_manipulation, _cpp_query)


def generated(core: dict) -> Dict[pathlib.Path, str]:
    """Each generated file and the text it must hold."""
    return {PYTHON_FACES: python_module(core), CPP_FACES: cpp_header(core)}


CPP_PLUGINS_HEAD = '''\
// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Generated by {generator}
// from the faces of the plugins {origins}: do not edit.
//
// The methods of those plugins' commands (docs/extending.md): {namespace}::Reference is an
// armor::Reference with them added (and {namespace}::Batch an armor::Batch with their changes,
// when they have some); a node without the plugin of a command refuses it with 205
// (UNKNOWN_COMMAND).
//
//   {namespace}::Reference robotics = armor.reference("robotics");
#ifndef {guard}
#define {guard}

#include <string>
#include <vector>

#include "armor_cpp/armor.hpp"

namespace {namespace}
{{

using armor::Value;

// The plugins' commands, as contract.hpp declares the core's.
namespace contract
{{
using armor::contract::Command;
using armor::contract::Kind;
'''

CPP_PLUGINS_MANIPULATIONS = '''
template<typename Derived>
class ManipulationFaces : public armor::Changes<Derived>
{'''

CPP_PLUGINS_QUERIES = '''
template<typename Derived>
class QueryFaces
{'''

# What a class of methods ends with: its destructor, protected (a mixin only).
CPP_PLUGINS_CLASS_END = '''
protected:
  ~{cls}() = default;
}};'''

CPP_PLUGINS_BATCH = '''
// armor::Batch with the plugins' changes (each returns this batch, so calls chain).
class Batch : public armor::Batch, public {namespace}::ManipulationFaces<Batch>
{{
public:
  explicit Batch(const armor::Batch & batch)
  : armor::Batch(batch) {{}}

private:
  friend class armor::Changes<Batch>;
  Batch & send_change(const contract::Command & command, const std::vector<std::string> & args)
  {{
    armor::Batch::send_change(command, args);
    return *this;
  }}
}};'''

CPP_PLUGINS_REFERENCE = '''
// armor::Reference with the plugins' methods.
class Reference : public armor::Reference{bases}
{{
public:
  Reference(const armor::Reference & reference)  // NOLINT: converts armor.reference(...)
  : armor::Reference(reference) {{}}
{batch}
private:
{friends}
}};

}}  // namespace {namespace}

#endif  // {guard}
'''


def _cpp_command_constant(command: dict) -> Iterable[str]:
    args = command['args']
    words = ', '.join(json.dumps(word) for word in command['words'])
    yield from _cpp_comment(f'{command["summary"]} (plugin {command["origin"]})', '')
    yield from _wrapped(f'inline constexpr Command {_constant(command)}{{',
                        [words, f'Kind::{command["kind"].capitalize()}',
                         str(len(args['required'])), str(len(args['optional'])),
                         str(args['variadic']).lower(), str(command['changes_ontology']).lower()],
                        '};', '  ', 100)


def hand_written_cpp_methods() -> set:
    """The method names armor::Reference and Batch have besides the generated ones."""
    names = set()
    for header in CPP_HAND_WRITTEN:
        names.update(re.findall(r'\b([a-z_][a-z0-9_]*)\(', header.read_text()))
    return names


def plugin_faced_commands(catalogue: dict) -> List[dict]:
    """The plugins' commands of a catalogue that get a C++ method, in catalogue order.

    A face whose method name the client has already (a built-in method, another plugin's) gets
    none, as in the Python client: a warning on stderr names both.
    """
    core = {**catalogue, 'commands': [c for c in catalogue['commands'] if c['origin'] == 'core']}
    taken = {c['face']['method']: c['key'] for c in faced_commands(core)}
    taken.update({name: 'the hand-written C++ client' for name in hand_written_cpp_methods()
                  if name not in taken})
    faced = []
    for command in catalogue['commands']:
        face = command.get('face')
        if command['origin'] == 'core' or not face:
            continue
        if face['method'] in taken:
            print(f'{command["key"]} (plugin {command["origin"]}) gets no C++ method '
                  f'{face["method"]}(): {taken[face["method"]]} has it; send it with '
                  'Armor::call', file=sys.stderr)
            continue
        taken[face['method']] = command['key']
        faced.append(command)
    return faced


def cpp_plugin_header(catalogue: dict, namespace: str, generator: str) -> str:
    """A header with the C++ methods of the plugins' commands of a catalogue.

    Args:
        catalogue: a catalogue with plugins' commands (GET CATALOGUE, or --catalogue CONFIG).
        namespace: the C++ namespace of its Reference and Batch (``armor::plugins``, ``hello``).
        generator: how the header was made, said in its first lines.
    """
    if not re.fullmatch(r'[A-Za-z_]\w*(::[A-Za-z_]\w*)*', namespace) or namespace == 'armor':
        raise ValueError(f'not a C++ namespace of its own: {namespace}')
    faced = plugin_faced_commands(catalogue)
    changes = [c for c in faced if c['kind'] == 'manipulation']
    queries = [c for c in faced if c['kind'] == 'query']
    fields = {'namespace': namespace, 'generator': generator,
              'guard': re.sub(r'\W', '_', namespace).upper() + '__PLUGIN_FACES_HPP_',
              'origins': ', '.join(sorted({c['origin'] for c in faced})) or 'no plugin'}
    lines = [CPP_PLUGINS_HEAD.format(**fields)]
    lines += [line for c in faced for line in _cpp_command_constant(c)]
    lines.append('}  // namespace contract')
    # Only the classes the plugins' faces fill (a Batch only for changes).
    bases, friends = [], []
    for cls, opening, commands, method in (
            ('ManipulationFaces', CPP_PLUGINS_MANIPULATIONS, changes, _cpp_manipulation),
            ('QueryFaces', CPP_PLUGINS_QUERIES, queries, _cpp_query)):
        if commands:
            lines += [opening, 'public:']
            lines += [line for c in commands for line in method(c)]
            lines.append(CPP_PLUGINS_CLASS_END.format(cls=cls))
            bases.append(f'{namespace}::{cls}<Reference>')
    if changes:
        lines.append(CPP_PLUGINS_BATCH.format(**fields))
        friends.append('  friend class armor::Changes<Reference>;')
    if queries:
        friends.append(f'  friend class {namespace}::QueryFaces<Reference>;')
    batch = ''
    if changes:
        batch = ('\n  // A batch with the plugins\' changes too.\n'
                 '  Batch batch() const {return Batch(armor::Reference::batch());}\n')
    lines.append(CPP_PLUGINS_REFERENCE.format(
        bases=''.join(f',\n  public {base}' for base in bases), batch=batch,
        friends='\n'.join(friends), **fields).rstrip('\n'))
    return '\n'.join(lines) + '\n'


def installed_plugins_header(catalogue: dict) -> str:
    """armor_cpp's plugins.hpp: the methods of the plugins this repository installs."""
    return cpp_plugin_header(catalogue, 'armor::plugins', 'make catalogue (tools/faces.py)')


def main(argv: List[str]) -> int:
    parser = argparse.ArgumentParser(
        description='A C++ header with the methods of the plugins\' commands of a catalogue.')
    parser.add_argument('--cpp-plugins', metavar='CATALOGUE.json', required=True,
                        help="a catalogue with the plugins' commands (GET CATALOGUE); - for stdin")
    parser.add_argument('--namespace', required=True,
                        help="the C++ namespace of the header's Reference and Batch (hello)")
    parser.add_argument('--output', metavar='FILE', help='write there instead of stdout')
    options = parser.parse_args(argv)
    source = options.cpp_plugins
    text = sys.stdin.read() if source == '-' else pathlib.Path(source).read_text()
    header = cpp_plugin_header(json.loads(text), options.namespace,
                               f'tools/faces.py --cpp-plugins --namespace {options.namespace}')
    if options.output:
        pathlib.Path(options.output).write_text(header)
    else:
        sys.stdout.write(header)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
