# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Plain rclpy clients with the default service QoS, as ported ROS 1 code calls the node.

A short version of bench/default_clients.py (issue 20, item 6): client processes with one
request in flight get every answer; a flood loses requests in the client's own queues, and
the change history (GET REF CHANGES) lets it resend exactly what was not applied.
"""

import pathlib
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / 'bench'))

import default_clients  # noqa: E402


@pytest.fixture
def coordinator(armor):
    """A default-QoS client of the session's node (started by `armor`), for setup and audits
    (rclpy is started for the session by conftest)."""
    caller = default_clients.DefaultClient(default_clients.service_name(''),
                                           'default_qos_coordinator')
    yield caller
    caller.close()


def test_sequential_default_clients_get_every_answer(tmp_path, coordinator):
    figures = default_clients.run_sequential('', tmp_path, clients=2, directives=200,
                                             query_every=8, timeout_s=10,
                                             coordinator=coordinator)
    assert figures['sent'] == 400 and figures['errors'] == 0, figures
    assert figures['answered'] == 400, figures  # no request lost, no answer lost
    audit = figures['recovery']
    assert audit['history_missed'] == 0, audit  # the follower saw every change ...
    assert audit['missing'] == audit['unexpected'] == audit['listed_twice'] == 0, audit
    assert audit['applied_twice'] == 0, audit  # ... and none twice


def test_recovery_resends_only_the_changes_the_history_does_not_show(coordinator):
    """20 ADDs applied whose answers the client ignores, 20 it never sent: it must tell them
    apart from the history alone, resend the 20, and leave each individual added once."""
    reference, me = 'default_qos_recovery', 'recovering_client'
    default_clients.create(coordinator, reference)
    since = default_clients.revision(coordinator, me, reference)
    for i in range(20):
        answer = coordinator.call(default_clients.request(
            me, reference, 'ADD IND CLASS', f'applied{i}', default_clients.CLASS), 30)
        assert answer is not None and answer.success
    unanswered = [f'applied{i}' for i in range(20)] + [f'never_sent{i}' for i in range(20)]
    figures = default_clients.recover(coordinator, me, reference, since, unanswered, 30)
    assert figures == {'unanswered_adds': 40, 'applied_via_history': 20, 'resent': 20,
                       'undecidable': 0, 'window_missed': 0}, figures
    history, missed = default_clients.changes_since(coordinator, me, reference, since)
    assert missed == 0
    assert default_clients.added_by(history, me) == {name: 1 for name in unanswered}
    audit = default_clients.audit(coordinator, reference, unanswered,
                                  default_clients.added_by(history), missed)
    assert audit == {'missing': 0, 'unexpected': 0, 'listed_twice': 0, 'applied_twice': 0,
                     'history_missed': 0}, audit


def test_a_flood_recovers_through_the_change_history_exactly_once(coordinator):
    # 2,000: a flood of 1,000 often arrives whole; 800 a reference keeps each reference's whole
    # flood in its history (the latest 1,000 changes).
    figures = default_clients.run_flood('', directives=2000, per_reference=800, quiet_s=5,
                                        timeout_s=10, coordinator=coordinator)
    assert figures['sent'] == 2000 and figures['errors'] == 0, figures
    unanswered = figures['sent'] - figures['answered']
    recovery = figures['recovery']
    assert recovery['unanswered_adds'] == unanswered, figures
    # Every unanswered ADD was decided from the history alone: found applied, or resent.
    assert recovery['window_missed'] == 0 and recovery['undecidable'] == 0, recovery
    assert recovery['applied_via_history'] == figures['answers_lost'], figures
    assert recovery['resent'] >= figures['requests_lost'], figures
    assert recovery['history_missed'] == 0, recovery
    # Every individual present once, none applied twice.
    assert recovery['missing'] == recovery['unexpected'] == recovery['listed_twice'] == 0, recovery
    assert recovery['applied_twice'] == 0, recovery
