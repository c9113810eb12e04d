# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A failing callback is logged and answered, never raised into rclpy's executor."""

from types import SimpleNamespace

from armor_contract.exit_codes import ExitCode
from armor_msgs.msg import ArmorDirectiveReq
from armor_msgs.srv import ArmorDirective, ArmorDirectiveList, ArmorSubscribe
from armor_service import node, subscriptions
from armor_service.callback_guard import guarded


class Log:
    def __init__(self):
        self.errors = []

    def error(self, text):
        self.errors.append(text)


def _broken(*args):
    raise KeyError('queried_objects')


def test_a_directive_whose_handling_fails_answers_220_and_is_logged():
    log = Log()
    callback = guarded(_broken, log, 'service /armor_interface_srv', node._refuse_directive)
    answer = callback(ArmorDirective.Request(), ArmorDirective.Response()).armor_response
    assert answer.exit_code == ExitCode.INTERNAL_ERROR and not answer.success
    assert "KeyError: 'queried_objects'" in answer.error_description
    assert len(log.errors) == 1 and 'Traceback' in log.errors[0]


def test_a_list_whose_handling_fails_answers_220_for_each_directive():
    request = ArmorDirectiveList.Request()
    request.armor_requests = [ArmorDirectiveReq(), ArmorDirectiveReq()]
    callback = guarded(_broken, Log(), 'service /armor_interface_serialized_srv',
                       node._refuse_list)
    response = callback(request, ArmorDirectiveList.Response())
    assert response.success is False
    assert [r.exit_code for r in response.armor_responses] == [ExitCode.INTERNAL_ERROR] * 2


def test_a_subscription_whose_handling_fails_is_refused_with_220():
    callback = guarded(_broken, Log(), 'service /armor_subscribe', subscriptions._refuse)
    response = callback(ArmorSubscribe.Request(), ArmorSubscribe.Response())
    assert response.success is False and response.exit_code == ExitCode.INTERNAL_ERROR


def test_a_failing_timer_is_logged_and_returns():
    log = Log()
    assert guarded(lambda: _broken(), log, 'the subscription sweep')() is None
    assert log.errors and 'the subscription sweep failed' in log.errors[0]


def test_a_callback_that_works_is_answered_as_it_answers():
    response = SimpleNamespace(value=None)

    def works(request, response):
        response.value = request
        return response

    assert guarded(works, Log(), 'x', node._refuse_directive)(7, response).value == 7
