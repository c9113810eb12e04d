# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The armor verbs' help and the shell's completion, without a node."""

import io

from armor_client import commands
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


@pytest.fixture
def shipped_catalogue(monkeypatch):
    """Only the shipped commands: a test before this one in the process may have learned a
    node's plugins (commands.learn), which a shell then offers too."""
    shipped = commands.load().commands
    monkeypatch.setattr(commands, 'COMMANDS', shipped)
    monkeypatch.setattr(commands, '_BY_WORDS', {
        words: command for command in shipped for words in (command.words, *command.aliases)})


def completer() -> Completer:
    return Completer(lambda: ['Robot', 'robot1', 'isIn', 'kitchen'], lambda: ['robotics', 'map'])


@pytest.mark.parametrize('line, expected', [
    ('', ['ADD', 'APPLY', 'CREATE', 'DISJOINT', 'DROP', 'EXPLAIN', 'GET', 'LOAD', 'LOG', 'MAKE',
          'MOUNT',
          'QUERY', 'REASON', 'REMOVE', 'RENAME', 'REPLACE', 'SAVE', 'UNMOUNT', 'help', 'names',
          'quit', 'refs', 'use']),
    ('QU', ['QUERY']), ('qu', ['QUERY', 'quit']), ('QUERY IND C', ['CLASS']),
    ('QUERY IND CLASS R', ['Robot']), ('QUERY OBJECTPROP IND is', ['isIn']),
    ('QUERY OBJECTPROP IND isIn rob', ['robot1']), ('use ', ['map', 'robotics']),
    ('help QUERY CLASS S', ['SUPER']), ('FLY ', []),
    ('ADD DATAPROP IND level robot1 L', ['LONG']),
])
def test_completion_offers_commands_then_names(line, expected, shipped_catalogue):
    assert completer().candidates(line) == expected


def test_tables_align_columns_and_count_rows():
    out = io.StringIO()
    print_table(['who', 'level'], [['alice', 80], ['bob', None], ['carol', True]], out)
    assert out.getvalue().splitlines() == [
        'who    level', '-----  -----', 'alice  80', 'bob', 'carol  true', '(3 rows)']


@pytest.mark.parametrize('typed, sent', [
    # Issue 35 item 3: a misspelt spec is no argument of a shorter command.
    ('QUERY IND CLAS Room', (('QUERY', 'IND', 'CLAS'), ['Room'])),
    ('query ind clas Room', (('query', 'ind', 'clas'), ['Room'])),
    ('QUERRY IND CLASS Room', (('QUERRY', 'IND', 'CLASS'), ['Room'])),
    ('REPLACE DATAPRP IND batteryLevel robot1 INTEGER 75 80',
     (('REPLACE', 'DATAPRP', 'IND'), ['batteryLevel', 'robot1', 'INTEGER', '75', '80'])),
    ('QUERY IND CLAS -- Room', (('QUERY', 'IND', 'CLAS'), ['Room'])),
])
def test_a_misspelt_spec_is_sent_as_typed_so_that_the_node_names_the_closest(typed, sent):
    from armor_client import commands
    assert commands.split_directive(typed.split())[0] is None
    assert commands.as_typed(typed.split()) == sent


@pytest.mark.parametrize('typed, words, arguments', [
    ('QUERY IND robot1', ('QUERY', 'IND', ''), ['robot1']),
    ('QUERY IND C1', ('QUERY', 'IND', ''), ['C1']),          # an individual named like a spec
    ('QUERY IND CLAS', ('QUERY', 'IND', ''), ['CLAS']),      # one argument: it may be a name
    ('QUERY IND CLASS Room', ('QUERY', 'IND', 'CLASS'), ['Room']),
])
def test_arguments_that_fit_the_command_stay_arguments(typed, words, arguments):
    from armor_client import commands
    command, split = commands.split_directive(typed.split())
    assert (command.words, split) == (words, arguments)


@pytest.mark.parametrize('words, trailing, sent', [
    (['IND', 'CLASS', 'OccupiedRoom'], [], (('QUERY', 'IND', 'CLASS'), ['OccupiedRoom'])),
    (['QUERY', 'IND', 'CLASS'], ['OccupiedRoom'], (('QUERY', 'IND', 'CLASS'), ['OccupiedRoom'])),
    (['IND', 'CLAS', 'Room'], [], (('QUERY', 'IND', 'CLAS'), ['Room'])),
    (['ADD', 'IND', 'CLASS'], ['r', 'Robot'], (('ADD', 'IND', 'CLASS'), ['r', 'Robot'])),
])
def test_query_and_watch_read_a_query_alike(words, trailing, sent):
    from armor_client.cli.common import query_words
    assert query_words(words, trailing) == sent
