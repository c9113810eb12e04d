# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Lost messages are reported, never skipped silently (issue 12); no ROS: the messages are fed."""

from types import SimpleNamespace

from armor_client.subscriptions import ChangeWatch, Subscription
from armor_msgs.msg import ArmorAnswer, ArmorChange
from armor_msgs.srv import ArmorSubscribe
from builtin_interfaces.msg import Time


class _Node:
    def create_subscription(self, *args, **kwargs):
        return object()

    def destroy_subscription(self, subscription):
        pass


def _transport():
    return SimpleNamespace(node=_Node(), namespace='', service_wait_s=1.0)


def test_a_change_watch_names_the_revisions_it_did_not_receive():
    received = []
    watch = ChangeWatch(_transport(), received.append)
    for reference, revision in (('a', 3), ('a', 4), ('b', 9), ('a', 7), ('a', 0), ('a', 1)):
        watch._received(ArmorChange(reference_name=reference, revision=revision,
                                    stamp=Time(sec=1, nanosec=5)))
    assert [(c.reference, c.revision, c.missed) for c in received] == [
        ('a', 3, ()), ('a', 4, ()), ('b', 9, ()), ('a', 7, (5, 6)), ('a', 0, ()), ('a', 1, ())]
    assert received[0].stamp_ns == 1_000_000_005


def test_a_change_watch_of_one_reference_ignores_the_others():
    received = []
    watch = ChangeWatch(_transport(), received.append, reference='b')
    for reference, revision in (('a', 1), ('b', 1), ('a', 2), ('b', 2)):
        watch._received(ArmorChange(reference_name=reference, revision=revision))
    assert [(c.reference, c.revision) for c in received] == [('b', 1), ('b', 2)]


def test_a_subscription_counts_missed_messages_and_keeps_its_answer():
    class Services:
        unsubscribed = []

        def subscribe(self, request, timeout_s):
            return ArmorSubscribe.Response(success=True, subscription_id='s1', topic='/t',
                                           revision=5, answer=['<http://x.org/o#kitchen>'])

        def unsubscribe(self, subscription_id, timeout_s):
            self.unsubscribed.append(subscription_id)
    services = Services()
    transport = _transport()
    transport.subscribe, transport.unsubscribe = services.subscribe, services.unsubscribe
    changes = []
    subscription = Subscription(transport, 'c', 'ref', 'QUERY IND CLASS OccupiedRoom',
                                changes.append)

    def message(sequence, revision, added=(), removed=()):
        subscription._received(ArmorAnswer(
            subscription_id='s1', sequence=sequence, revision=revision,
            added=[f'<http://x.org/o#{n}>' for n in added],
            removed=[f'<http://x.org/o#{n}>' for n in removed]))
    message(0, 5, added=['kitchen'])        # the first message repeats the service's answer
    message(1, 6, added=['bedroom'])
    message(4, 9, removed=['kitchen'])      # 2 and 3 never arrived
    message(3, 8, added=['hall'])           # late: already past it
    subscription._received(ArmorAnswer(     # the topic's previous subscription's message
        subscription_id='s0', sequence=7, revision=10, added=['<http://x.org/o#attic>']))
    assert [(c.revision, c.added, c.removed, c.missed, c.initial) for c in changes] == [
        (5, ['kitchen'], [], 0, True), (6, ['bedroom'], [], 0, False),
        (9, [], ['kitchen'], 2, False)]
    assert subscription.answer == ['bedroom'] and subscription.revision == 9
    subscription.close()
    subscription.close()
    assert Services.unsubscribed == ['s1']


def test_a_failing_callback_is_logged_and_the_next_change_still_delivered(caplog):
    delivered = []

    def callback(change):
        delivered.append(change.revision)
        raise RuntimeError('bug in the callback')
    watch = ChangeWatch(_transport(), callback)
    watch._received(ArmorChange(reference_name='a', revision=1))
    watch._received(ArmorChange(reference_name='a', revision=2))
    assert delivered == [1, 2]
    assert 'change callback failed' in caplog.text
