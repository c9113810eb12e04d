# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The armor verbs' help and the shell's completion, without a node."""

import io

from armor_client.cli import main, VERBS
from armor_client.cli.common import print_table
from armor_client.cli.shell import Completer
import pytest


@pytest.mark.parametrize('verb', VERBS)
def test_every_verb_has_its_help(verb, capsys):
    with pytest.raises(SystemExit) as exit_info:
        main([verb, '--help'])
    assert exit_info.value.code == 0
    assert f'usage: armor {verb}' in capsys.readouterr().out


def completer() -> Completer:
    return Completer(lambda: ['Robot', 'robot1', 'isIn', 'kitchen'], lambda: ['robotics', 'map'])


@pytest.mark.parametrize('line, expected', [
    ('', ['ADD', 'APPLY', 'CREATE', 'DISJOINT', 'DROP', 'GET', 'LOAD', 'LOG', 'MAKE', 'MOUNT',
          'QUERY', 'REASON', 'REMOVE', 'RENAME', 'REPLACE', 'SAVE', 'UNMOUNT', 'help', 'names',
          'quit', 'refs', 'use']),
    ('QU', ['QUERY']), ('qu', ['QUERY', 'quit']), ('QUERY IND C', ['CLASS']),
    ('QUERY IND CLASS R', ['Robot']), ('QUERY OBJECTPROP IND is', ['isIn']),
    ('QUERY OBJECTPROP IND isIn rob', ['robot1']), ('use ', ['map', 'robotics']),
    ('help QUERY CLASS S', ['SUPER']), ('FLY ', []),
    ('ADD DATAPROP IND level robot1 L', ['LONG']),
])
def test_completion_offers_commands_then_names(line, expected):
    assert completer().candidates(line) == expected


def test_tables_align_columns_and_count_rows():
    out = io.StringIO()
    print_table(['who', 'level'], [['alice', 80], ['bob', None], ['carol', True]], out)
    assert out.getvalue().splitlines() == [
        'who    level', '-----  -----', 'alice  80', 'bob', 'carol  true', '(3 rows)']
