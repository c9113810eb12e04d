# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The clients' methods of the catalogue's commands, generated from their faces.

A command's face (its method name, parameters and what it answers) comes with its registration
in the core (``CommandTable.Builder.face``, exported as ``"face"`` in the catalogue), or, for
the built-in commands registered before faces existed, from
armor_contract/armor_contract/faces.json. tools/catalogue.py writes from them:

- armor_client/armor_client/faces.py: ManipulationFaces (mixed into the references and the
  batches) and QueryFaces (mixed into the references), typed, a docstring from each summary;
- armor_cpp/include/armor_cpp/faces.hpp: the same methods for the C++ Reference and Batch.

Commands without a face are composites written by hand (operations.py, armor.cpp) or reached
through ``call``.
"""

import json
import pathlib
from typing import Callable, Dict, Iterable, List, Sequence

REPO = pathlib.Path(__file__).resolve().parents[1]
BUILT_IN_FACES = REPO / 'armor_contract' / 'armor_contract' / 'faces.json'
PYTHON_FACES = REPO / 'armor_client' / 'armor_client' / 'faces.py'
CPP_FACES = REPO / 'armor_cpp' / 'include' / 'armor_cpp' / 'faces.hpp'

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


def _file(core: dict, parts: Sequence[str], manipulation: Method, query: Method) -> str:
    """parts[0], the manipulations' methods, parts[1], the queries' methods, then parts[2:]."""
    faced = faced_commands(core)
    lines = [parts[0].rstrip('\n')]
    lines += [line for c in faced if c['kind'] == 'manipulation' for line in manipulation(c)]
    lines.append(parts[1].rstrip('\n'))
    lines += [line for c in faced if c['kind'] == 'query' for line in query(c)]
    lines += [part.rstrip('\n') for part in parts[2:]]
    return '\n'.join(lines) + '\n'


def python_module(core: dict) -> str:
    return _file(core, [PYTHON_HEAD, PYTHON_QUERIES], _python_method, _python_method)


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
    for p in command['face']['parameters']:
        name = CPP_RENAMED.get(p['name'], p['name'])
        names.append(f'std::to_string({name})' if p['type'] == 'int' else name)
    return names


def _cpp_manipulation(command: dict) -> Iterable[str]:
    face = command['face']
    yield f'  // {_sentence(command)}'
    yield from _wrapped(f'  decltype(auto) {face["method"]}(', _cpp_parameters(command), ')',
                        '    ', 100)
    change = 'change_all' if command['args']['variadic'] else 'change'
    yield from _wrapped(f'  {{return {change}<contract::{_constant(command)}>(',
                        _cpp_arguments(command), ');}', '    ', 100)


def _cpp_query(command: dict) -> Iterable[str]:
    face = command['face']
    yield f'  // {_sentence(command)}'
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

#include "armor_cpp/contract.hpp"
#include "armor_cpp/values.hpp"

namespace armor
{

template<typename Derived>
class ManipulationFaces
{
public:
'''

CPP_MANIPULATION_TAIL = '''
protected:
  ~ManipulationFaces() = default;

  // For Manipulations' hand-written changes too (this->template change<...>).
  template<const contract::Command & C, typename ... Args>
  decltype(auto) change(const Args & ... args)
  {
    static_assert(C.kind == contract::Kind::Manipulation, "not a manipulation in the catalogue");
    static_assert(C.accepts(static_cast<int>(sizeof...(Args))),
      "the core's catalogue gives this command another number of arguments");
    return static_cast<Derived &>(*this).send_change(C, std::vector<std::string>{args ...});
  }

  template<const contract::Command & C>
  decltype(auto) change_all(const std::vector<std::string> & args)
  {
    static_assert(C.kind == contract::Kind::Manipulation && C.variadic,
      "not a variadic manipulation in the catalogue");
    return static_cast<Derived &>(*this).send_change(C, args);
  }
};

template<typename Derived>
class QueryFaces
{
public:
'''

CPP_TAIL = '''
protected:
  ~QueryFaces() = default;
};

}  // namespace armor

#endif  // ARMOR_CPP__FACES_HPP_
'''


def cpp_header(core: dict) -> str:
    return _file(core, [CPP_HEAD, CPP_MANIPULATION_TAIL, CPP_TAIL], _cpp_manipulation, _cpp_query)


def generated(core: dict) -> Dict[pathlib.Path, str]:
    """Each generated file and the text it must hold."""
    return {PYTHON_FACES: python_module(core), CPP_FACES: cpp_header(core)}
