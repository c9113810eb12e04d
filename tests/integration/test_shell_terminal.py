# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""armor shell at a terminal (issue 11 items 7 and 13), driven through a pseudo-terminal."""

import pytest
from terminal import Terminal

PROMPT = 'armor:robotics> '


@pytest.fixture
def shell(armor):
    terminal = Terminal(['-m', 'armor_client.cli', 'shell', 'robotics'])
    terminal.wait_for(PROMPT)
    yield terminal
    terminal.type('quit\n')
    assert terminal.close() == 0, terminal.screen


def test_tab_completes_a_word_and_the_space_after_it(shell):
    shell.type('QUERY IND CL\t')
    shell.wait_for('CLASS ')
    shell.type('Room\n')
    answer = shell.wait_for(PROMPT)
    assert 'QUERY IND CLASS Room' in shell.screen, shell.screen
    assert 'kitchen' in answer and 'bedroom' in answer, answer


def test_sparql_columns_carry_the_query_variable_names(shell):
    shell.type('QUERY SPARQL "SELECT ?who ?room WHERE { ?who '
               '<http://www.example.org/robotics#isIn> ?room }"\n')
    answer = shell.wait_for(PROMPT)
    header = next(line for line in answer.splitlines() if line.startswith('who'))
    assert header.split() == ['who', 'room'], answer
    rows = answer.splitlines()[answer.splitlines().index(header) + 2:]
    assert any(line.split()[0] == 'robot1' and len(line.split()) == 2 for line in rows), answer


def test_use_of_an_unknown_reference_fails_at_once(shell):
    shell.type('use nosuchref\n')
    answer = shell.wait_for(PROMPT)
    assert "no reference named 'nosuchref' is loaded" in answer and 'robotics' in answer, answer
    shell.type('QUERY IND CLASS Robot\n')
    assert 'robot1' in shell.wait_for(PROMPT)


def test_a_name_new_to_the_reference_is_noted_with_the_names_it_is_close_to(shell):
    shell.type('QUERY IND CLASS Robott\n')
    answer = shell.wait_for(PROMPT)
    assert "note: new to the reference: class 'Robott' (did you mean Robot?)" in answer, answer


def test_tab_completes_the_commands_of_the_nodes_plugins(shell):
    # The PDDL bridge is a plugin the node loads by default: the shell learned it at start.
    shell.type('QUERY PD\t')
    shell.wait_for('PDDL ')
    shell.type('PRO\t')
    shell.wait_for('PROBLEM ')
    shell.type('"{domain: d, types: [Robot]}"\n')
    answer = shell.wait_for(PROMPT)
    assert '(define (problem robotics)' in answer and 'robot1 - robot' in answer, answer
