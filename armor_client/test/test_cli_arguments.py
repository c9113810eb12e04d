# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The armor command's argument handling, without a running node."""

from armor_client.cli import build_parser, main
import pytest


def test_every_verb_has_help(capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(['--help'])
    assert exit_info.value.code == 0
    out = capsys.readouterr().out
    assert 'serve' in out and 'call' in out


def test_call_rejects_more_than_three_words_before_the_separator(capsys):
    assert main(['call', 'ref', 'QUERY', 'IND', 'CLASS', 'Room']) == 2
    assert 'after "--"' in capsys.readouterr().err


def test_call_words_and_options_parse():
    args = build_parser().parse_args(['call', '--client', 'me', 'robotics', 'QUERY', 'IND'])
    assert (args.reference, args.words, args.client) == ('robotics', ['QUERY', 'IND'], 'me')
