#!/usr/bin/env python3
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The knowledge core's catalogue, and the files that follow it.

    python tools/catalogue.py          # write what is generated from the core (make catalogue)
    python tools/catalogue.py --check  # say what differs from the core, exit 1 if anything

The core (``java -jar armor-core.jar --catalogue``) owns the commands, exit codes and settings.
Generated from it: armor_contract/armor_contract/catalogue.json (the Python catalogue, CLI
parsing and completion read it). Checked against it: the command and exit-code tables of
docs/commands.md (they carry hand-written examples). tests/test_catalogue.py runs the check.
"""

import argparse
import difflib
import itertools
import json
import os
import pathlib
import re
import subprocess
import sys
from typing import Dict, Iterable, List, Set

REPO = pathlib.Path(__file__).resolve().parents[1]
CATALOGUE_JSON = REPO / 'armor_contract' / 'armor_contract' / 'catalogue.json'
COMMANDS_DOC = REPO / 'docs' / 'commands.md'
COMMAND_SECTIONS = ('## References and utilities', '## Manipulations', '## Queries')


def core_jar() -> pathlib.Path:
    """The installed core jar (install/setup.bash exports ARMOR_CORE_JAR)."""
    jar = os.environ.get('ARMOR_CORE_JAR') or str(REPO / 'install' / 'armor_core' / 'armor-core.jar')
    return pathlib.Path(jar)


def core_catalogue_text(jar: pathlib.Path) -> str:
    """What the core prints for --catalogue (with the built-in command groups only)."""
    return subprocess.run(['java', '-jar', str(jar), '--catalogue'], check=True,
                          capture_output=True, text=True, timeout=120).stdout


def _alternatives(cell: str) -> List[str]:
    """The commands a docs table cell names, its shorthand expanded.

    ``ADD/REMOVE OBJECTPROP DOMAIN / RANGE`` is four commands: `` / `` replaces the last words
    of the first part (or the whole of it, when as long), ``A/B`` is either word, ``[W]`` an
    optional word, ``(or X)`` an alias.
    """
    names: List[str] = []
    cell = cell.strip().strip('`')
    for alias in re.findall(r'\(or ([^)]*)\)', cell):
        names += _alternatives(alias)
    cell = re.sub(r'\s*\(or [^)]*\)', '', cell)
    parts = [part.split() for part in cell.split(' / ')]
    spelled = [parts[0]] + [part if len(part) >= len(parts[0]) else parts[0][:-len(part)] + part
                            for part in parts[1:]]
    for words in spelled:
        choices = [[''] + [w[1:-1]] if w.startswith('[') else w.split('/') for w in words]
        for combination in itertools.product(*choices):
            names.append(' '.join(w for w in combination if w))
    return names


def _table_rows(text: str) -> Iterable[List[str]]:
    for line in text.splitlines():
        if line.startswith('|') and not line.startswith('|---'):
            yield [cell.strip() for cell in line.strip().strip('|').split('|')]


def _section(doc: str, heading: str) -> str:
    start = doc.index(heading + '\n')
    following = doc.find('\n## ', start + len(heading))
    return doc[start:following if following >= 0 else len(doc)]


def documented_commands(doc: str) -> Set[str]:
    """Every command the command tables of docs/commands.md name (aliases included)."""
    names: Set[str] = set()
    for heading in COMMAND_SECTIONS:
        for row in _table_rows(_section(doc, heading)):
            if row[0] != 'command':
                names.update(_alternatives(row[0]))
    return names


def documented_exit_codes(doc: str) -> Set[int]:
    """The codes of the exit-code table of docs/commands.md."""
    return {int(row[0]) for row in _table_rows(_section(doc, '## Exit codes')) if row[0].isdigit()}


def differences(core_text: str) -> List[str]:
    """Everything that disagrees with the core's catalogue, one finding per line."""
    found: List[str] = []
    core = json.loads(core_text)
    shipped = CATALOGUE_JSON.read_text() if CATALOGUE_JSON.exists() else ''
    if shipped.strip() != core_text.strip():
        diff = difflib.unified_diff(shipped.splitlines(), core_text.splitlines(),
                                    str(CATALOGUE_JSON.relative_to(REPO)), 'the core', lineterm='', n=1)
        found.append('catalogue.json differs from the core (run make catalogue):\n' + '\n'.join(
            itertools.islice(diff, 60)))
    names: Dict[str, str] = {}
    for command in core['commands']:
        name = ' '.join(w for w in command['words'] if w)
        names[name] = name
        for alias in command['aliases']:
            names[' '.join(w for w in alias.split() if w != '-')] = name
    doc = COMMANDS_DOC.read_text()
    documented = documented_commands(doc)
    for name in sorted(set(names.values()) - documented):
        found.append(f'docs/commands.md has no row for {name}')
    for name in sorted(documented - set(names)):
        found.append(f'docs/commands.md names {name}, which the core does not answer')
    codes = {entry['code'] for entry in core['exit_codes']}
    for code in sorted(codes - documented_exit_codes(doc)):
        found.append(f'docs/commands.md#exit-codes has no row for {code}')
    for code in sorted(documented_exit_codes(doc) - codes):
        found.append(f'docs/commands.md#exit-codes lists {code}, which the core does not have')
    return found


def main(argv: List[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--check', action='store_true', help='write nothing; exit 1 on a difference')
    options = parser.parse_args(argv)
    core_text = core_catalogue_text(core_jar())
    if not options.check:
        CATALOGUE_JSON.write_text(core_text)
        print(f'wrote {CATALOGUE_JSON.relative_to(REPO)}')
    found = differences(core_text)
    for finding in found:
        print(finding, file=sys.stderr)
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
