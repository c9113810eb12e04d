#!/usr/bin/env python3
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Every public method of the Python and C++ clients with its signature, one per line.

    python tools/public_api.py > before.txt   # ... change the clients ...
    python tools/public_api.py | diff before.txt -

The clients' method names, signatures and return types are a public API (ROS 1 ports and
users' nodes call them): a refactoring of how they are made must leave this listing unchanged.
Python: every public callable of the client classes, through inspect (inherited ones included,
so a method moved to a generated base class lists the same). C++: each public method of the
client headers, read from the declarations (return type, name, parameter types), listed
under the class that offers it whichever header declares it.
"""

import inspect
import pathlib
import re
import sys
from typing import Iterable, List

REPO = pathlib.Path(__file__).resolve().parents[1]
PYTHON_CLASSES = [
    ('armor_client', ['Armor', 'AsyncArmor', 'Reference', 'AsyncReference', 'Batch']),
    ('armor_client.aio', ['AsyncArmor', 'AsyncReference', 'AsyncBatch']),
    ('armor_client.armor_api.armor_client', ['ArmorClient']),
    ('armor_client.armor_api.armor_manipulation_client', ['ArmorManipulationClient']),
    ('armor_client.armor_api.armor_query_client', ['ArmorQueryClient']),
    ('armor_client.armor_api.armor_utils_client', ['ArmorUtilsClient']),
]
CPP_HEADERS = ['armor.hpp', 'manipulations.hpp', 'faces.hpp']


def python_methods() -> Iterable[str]:
    import importlib
    for module_name, names in PYTHON_CLASSES:
        module = importlib.import_module(module_name)
        for name in names:
            cls = getattr(module, name, None)
            if cls is None:
                continue
            for attribute in sorted(dir(cls)):
                if attribute.startswith('_'):
                    continue
                value = getattr(cls, attribute)
                if not callable(value):
                    yield f'py {name}.{attribute} (attribute)'
                    continue
                try:
                    signature = str(inspect.signature(value))
                except (TypeError, ValueError):
                    signature = '(?)'
                # The module a type is defined in is no part of the API (answers.py took the
                # answer types from operations.py; both modules give them).
                signature = re.sub(r'armor_client\.(operations|answers)\.', '', signature)
                yield f'py {name}.{attribute}{signature}'


_DECLARATION = re.compile(r'^(.*?)\b(\w+)\((.*)\)\s*(const)?$', re.DOTALL)


def _declarations(body: str) -> str:
    """A class body without the bodies of its methods and without access labels."""
    kept, depth = [], 0
    for char in body:
        if char == '{':
            depth += 1
            kept.append(';' if depth == 1 else '')
        elif char == '}':
            depth -= 1
        elif depth == 0:
            kept.append(char)
    return re.sub(r'\b(public|private|protected):', ';', ''.join(kept))


def _normalise(text: str) -> str:
    return re.sub(r'\s+', ' ', text).replace('( ', '(').replace(' )', ')').strip()


def cpp_methods() -> Iterable[str]:
    """Public method declarations of the classes in the client headers (comments dropped)."""
    base = REPO / 'armor_cpp' / 'include' / 'armor_cpp'
    found: List[str] = []
    for header in CPP_HEADERS:
        path = base / header
        if not path.exists():
            continue
        text = re.sub(r'//[^\n]*', '', path.read_text())
        classes = r'\n(?:template<[^>]*>\s*)?class (?:\[\[\w+\]\] )?(\w+)[^;{]*\{(.*?)\n\};'
        for block in re.finditer(classes, text, re.DOTALL):
            cls, body = block.group(1), block.group(2)
            if cls.endswith('Faces'):
                cls = {'ManipulationFaces': 'Manipulations', 'QueryFaces': 'Reference'}[cls]
            public = re.split(r'\n\s*(?:private|protected):', body)[0] if 'public:' in body else ''
            for declaration in _declarations(public).split(';'):
                match = _DECLARATION.match(_normalise(declaration))
                if not match or match.group(1).startswith(('using', 'friend', 'template')):
                    continue
                returned = _normalise(match.group(1)).replace('explicit', '').strip()
                params = re.sub(r'\s*=\s*[^,]+', ' = default', match.group(3))
                types = ', '.join(re.sub(r'\s+\w+(?=( = default)?$)', '', p.strip())
                                  for p in params.split(',')) if params else ''
                const = ' const' if match.group(4) else ''
                found.append(f'cpp {cls}::{match.group(2)}({types}){const} -> '
                             f'{returned or "(constructor)"}')
    return sorted(set(found))


def main() -> int:
    for line in [*python_methods(), *cpp_methods()]:
        print(line)
    return 0


if __name__ == '__main__':
    sys.exit(main())
