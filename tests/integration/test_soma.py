# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""KnowRob's upper ontology over ROS 2 (issue 36): a kitchen of 40 individuals on SOMA-HOME and
DUL is loaded, changed, reasoned on and asked within a generous bound, with the right answers.
A regression check, not a timing claim: bench/soma.py measures (bench/REPORT.md, section 11).
Before issue 36 the REASON alone ran for over 300 s on 12 individuals.
"""

import time

import pytest
from conftest import start_node
from soma_kitchen import DEFINED_CLASS, SOMA, KitchenABox

pytestmark = pytest.mark.runs_for_minutes(4)

# Generous: the reasoning takes about 65 s of CPU for the LOAD, the move and REASON (with the
# schema's classification on the other core); on a 2-core machine shared with other work (load
# average 25) the whole test took 758 s, every answer right. The node's reasoner time limit is
# the same bound, so such a machine slows the test down instead of failing it with 211 (the
# default 30 s is a robot's setting, not this check's). Before issue 36 REASON alone ran for
# over 300 s on 12 individuals (the figure).
BOUND_S = 900
INSIDE = f'<{SOMA}isInsideOf>'
NAMESPACE = '/soma_test'


def names(answer) -> list:
    return sorted(iri.rstrip('>').rsplit('#', 1)[-1] for iri in answer.queried_objects)


@pytest.fixture(scope='module')
def soma_node(tmp_path_factory):
    node = start_node(tmp_path_factory.mktemp('soma'), '-p',
                      f'reasoner_timeout_ms:={BOUND_S * 1000}', namespace=NAMESPACE)
    yield node
    node.stop()


@pytest.fixture
def call(soma_node):
    from armor_client import ArmorTransport, directive
    transport = ArmorTransport(namespace=NAMESPACE, service_wait_s=120.0)

    def send(reference, words, *args, timeout_s=120):
        command, primary, secondary = (words.split() + ['', '', ''])[:3]
        return transport.call(directive('test', reference, command, primary, secondary, args),
                              timeout_s=timeout_s)
    yield send
    transport.close()


def test_a_kitchen_on_soma_home_answers_a_change_reason_and_query(soma_node, call):
    kitchen = KitchenABox(40)
    path = kitchen.write(soma_node.scratch / 'soma')
    started = time.monotonic()
    try:
        loaded = call('soma_kitchen', 'LOAD FILE', str(path), '', 'false', 'HERMIT', 'false',
                      timeout_s=BOUND_S)
        assert loaded.success, f'{loaded.exit_code} {loaded.error_description}'
        statement = loaded.error_description
        assert statement.startswith('profile: '), statement
        assert ' classes, ' in statement and 'reasoning in modules: ' in statement, statement
        first = call('soma_kitchen', 'QUERY IND CLASS', DEFINED_CLASS, timeout_s=BOUND_S)
        assert names(first) == kitchen.containers_with_cup()

        move = kitchen.next_move()
        moved = call('soma_kitchen', 'REPLACE OBJECTPROP IND', INSIDE, move.item, move.new,
                     move.old, timeout_s=BOUND_S)
        assert moved.success, moved.error_description
        reasoned = call('soma_kitchen', 'REASON', timeout_s=BOUND_S)
        assert reasoned.success and reasoned.is_consistent, reasoned.error_description
        after = call('soma_kitchen', 'QUERY IND CLASS', DEFINED_CLASS, timeout_s=BOUND_S)
        assert names(after) == kitchen.containers_with_cup()
        assert move.new in names(after) and names(after) != names(first)
        elapsed = time.monotonic() - started
        print(f'{statement}; LOAD to the last answer in {elapsed:.1f} s')
        assert elapsed < BOUND_S, elapsed
    finally:
        # DROP also stops the schema's classification if it still runs in the background.
        call('soma_kitchen', 'DROP', timeout_s=120)
