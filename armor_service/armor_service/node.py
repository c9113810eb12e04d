# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ArmorService: the ROS 2 face of the knowledge core.

The node translates between armor_msgs and the core's frames and supervises the core
process; it holds no ontology logic. Run it with ``armor serve`` (ROS arguments pass
through, e.g. ``armor serve --ros-args -p default_reasoner:=PELLET -r __ns:=/robot1``).
"""

import concurrent.futures
import difflib
import json
import os
import signal
import sys

from armor_contract.events import CHANGE_QOS, CHANGE_TOPIC
from armor_contract.exit_codes import ExitCode
from armor_contract.services import DIRECTIVE_SERVICE, LIST_SERVICE, SERVICE_QOS
from armor_contract.spinning import spin_while
from armor_msgs.msg import ArmorChange
from armor_msgs.srv import ArmorDirective, ArmorDirectiveList
from armor_service import core_ops, wire
from armor_service.callback_guard import guarded
from armor_service.core_process import CoreProcess, CoreUnavailable
from armor_service.extensions import load_extensions
from armor_service.installation import code_dirs
from armor_service.parameters import all_parameters, core_settings, Parameter
from armor_service.subscriptions import SubscriptionTopics
import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.exceptions import InvalidParameterTypeException
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions

# The client name of the directives the node sends on its own (preloading, restoring).
NODE_CLIENT = 'armor_service'


class ArmorService(Node):
    """Serves ARMOR's two services; publishes armor_changes; serves subscriptions to answers."""

    def __init__(self):
        super().__init__('armor_service')
        self._web_view = None
        self._armor_parameters = {p.name: p for p in all_parameters()}
        self._declare_parameters()
        settings = core_settings(self._value, self.get_logger().warning)
        settings['state_dir'] = settings['state_dir'] or self._default_state_dir()
        # Whatever protected_dirs says, no directive writes into the code the node runs.
        settings['protected_dirs'] = [*settings['protected_dirs'], *code_dirs()]
        self._core = CoreProcess(
            self._core_jar(), settings, jvm_options=tuple(self._value('jvm_options')),
            start_timeout_s=self._value('core_start_timeout_s'), logger=self.get_logger(),
            on_ready=self._on_core_ready)
        # Each callback blocks until the core answers. A reentrant group on a multi-threaded
        # executor lets a slow REASON on one reference wait while queries on others (and on
        # the same one, which the core serialises per reference) are answered meanwhile.
        group = ReentrantCallbackGroup()
        # Before the core starts: the preload's LOAD is a change too.
        self._change_publisher = self.create_publisher(ArmorChange, CHANGE_TOPIC, CHANGE_QOS)
        self._core.add_event_listener(self.on_core_event)
        self._answer_topics = SubscriptionTopics(
            self, self._core, group, lambda: self._value('subscription_idle_s'),
            lambda: self._value('subscriptions_per_client'))
        self._core.start()
        self.create_service(ArmorDirective, DIRECTIVE_SERVICE,
                            guarded(self.directive_callback, self.get_logger(),
                                    f'service {DIRECTIVE_SERVICE}', _refuse_directive),
                            qos_profile=SERVICE_QOS, callback_group=group)
        self.create_service(ArmorDirectiveList, LIST_SERVICE,
                            guarded(self.directive_list_callback, self.get_logger(),
                                    f'service {LIST_SERVICE}', _refuse_list),
                            qos_profile=SERVICE_QOS, callback_group=group)
        self._extensions = load_extensions(self, self._value('extensions'))
        self._web_view = self._start_web_view()
        self.get_logger().info(
            f'ARMOR ready: services {self.resolve_service_name(DIRECTIVE_SERVICE)} and '
            f'{self.resolve_service_name(LIST_SERVICE)}, changes on '
            f'{self.resolve_topic_name(CHANGE_TOPIC)}; core pid '
            f'{self._core.pid}. Try: armor call {self._value("preload_reference") or "REF"} '
            'QUERY IND CLASS -- Room'
            + (f'. Web view: {self._web_view.url}' if self._web_view else ''))

    def directive_callback(self, request, response):
        try:
            reply = core_ops.answer(self._core.request,
                                    wire.directive_to_json(request.armor_request),
                                    self._request_timeout())
            response.armor_response = wire.response_from_json(reply)
        except CoreUnavailable as error:
            response.armor_response = wire.error_response(ExitCode.CORE_UNAVAILABLE, str(error))
        except wire.FrameTooLarge as error:
            response.armor_response = wire.error_response(ExitCode.TOO_LARGE, str(error))
        except concurrent.futures.TimeoutError:
            response.armor_response = self._timed_out()
        self._answered([request.armor_request])
        return response

    def directive_list_callback(self, request, response):
        directives = [wire.directive_to_json(r) for r in request.armor_requests]
        try:
            reply = core_ops.answer_list(self._core.request, directives,
                                         self._request_timeout())
            response.success = reply['success']
            response.is_consistent = reply['is_consistent']
            response.armor_responses = [wire.response_from_json(r)
                                        for r in reply['armor_responses']]
        except CoreUnavailable as error:
            response.success = False
            response.armor_responses = [wire.error_response(ExitCode.CORE_UNAVAILABLE, str(error))
                                        for _ in directives]
        except wire.FrameTooLarge as error:
            response.success = False
            response.armor_responses = [wire.error_response(ExitCode.TOO_LARGE, str(error))
                                        for _ in directives]
        except concurrent.futures.TimeoutError:
            response.success = False
            response.armor_responses = [self._timed_out() for _ in directives]
        self._answered(request.armor_requests)
        return response

    def _answered(self, requests) -> None:
        """Tell the web view: its list of recent directives follows them all, not changes only."""
        if self._web_view is not None:
            self._web_view.directives_answered([r.reference_name for r in requests])

    def on_core_event(self, event: dict) -> None:
        """Publish what the core announces (on its event thread, in the core's order)."""
        if event.get('event') == 'change':
            self._change_publisher.publish(wire.change_from_json(event))

    def shutdown_core(self) -> None:
        self._extensions.close()
        self._answer_topics.end_all()
        if self._web_view is not None:
            self._web_view.stop()
        self._core.stop()

    def _start_web_view(self):
        """The live web page (armor_service/web) when web_port is set; None when it is off."""
        port = self._value('web_port')
        if port == 0:
            return None
        if not 0 < port < 65536:
            raise RuntimeError('parameter web_port must be 0 (off) or a TCP port from 1 to '
                               f'65535, got {port}')
        from armor_service.web import WebView
        from armor_service.web.server import WebViewError
        view = WebView(self._core, self._value('web_host'), port,
                       request_timeout_s=self._request_timeout, logger=self.get_logger())
        try:
            view.start()
        except WebViewError as error:
            # The robot's services matter more than the page: they run without it.
            self.get_logger().error(f'{error}; the node serves ROS without the web view '
                                    '(set web_port to a free port)')
            return None
        return view

    def _timed_out(self):
        answer = wire.error_response(
            ExitCode.TIMEOUT, f'no answer from the core within request_timeout_s='
            f'{self._value("request_timeout_s")}; the directive may still complete')
        answer.timeout = True
        return answer

    def _request_timeout(self):
        seconds = self._value('request_timeout_s')
        return seconds if seconds > 0 else None

    def _on_core_ready(self, send) -> None:
        """Bring a new core to where the last one was: the preload, then the subscriptions."""
        self._preload(send)
        self._answer_topics.register_again(send)

    def _state_damage(self, send) -> list:
        """What the core's state directory could not restore or cannot keep (GET STATE DAMAGE)."""
        answer = core_ops.answer(send, core_ops.directive(NODE_CLIENT, '', 'GET', 'STATE',
                                                          'DAMAGE'))
        damage = [json.loads(line) for line in answer['queried_objects']]
        for entry in damage:
            self.get_logger().error(f'state damage: {json.dumps(entry)}')
        return damage

    def _preload(self, send) -> None:
        """Load the preload file into a new core, before it takes any request."""
        damage = self._state_damage(send)
        path = self._value('preload_file')
        if not path:
            return
        name = self._value('preload_reference')
        lost = [d for d in damage if d.get('reference') == name and d.get('restored') is False]
        if lost:
            # Loading the file over it would hide the loss: the robot's changes would seem gone
            # for no reason.
            problems = '; '.join(lost[-1].get('problems', []))
            self.get_logger().error(
                f'reference "{name}" could not be restored from the state directory '
                f'({problems}); NOT preloading {path} over it. Its files '
                f'are in {lost[-1].get("kept_in")}. To start from {path} anyway, move that folder '
                'away (keep it to recover by hand) and restart, or start with '
                '-p restore_state:=false')
            return
        answer = core_ops.answer(send, core_ops.directive(NODE_CLIENT, '', 'GET', 'ALL', 'REFS'))
        restored = name in answer['queried_objects']
        load = core_ops.directive(
            NODE_CLIENT, name, 'LOAD', 'FILE', '',
            [os.path.abspath(path), self._value('preload_iri'),
             str(self._value('preload_buffered_manipulation')).lower(),
             self._value('preload_reasoner'),
             str(self._value('preload_buffered_reasoner')).lower()])
        reply = core_ops.answer(send, load)
        if not reply['success']:
            raise RuntimeError(f'preloading {path} failed: {reply["exit_code"]} '
                               f'{reply["error_description"]}')
        if restored:
            # LOAD of the same file reuses the reference: the file was not read again.
            self.get_logger().info(
                f'reference "{name}" restored with the changes of earlier sessions, not reloaded '
                f'from {path}; start with -p restore_state:=false (make run-clean) for a clean '
                'start')
        else:
            self.get_logger().info(f'preloaded {path} as reference "{name}"')

    def _default_state_dir(self) -> str:
        """One directory per ROS domain and node name: two nodes never share journals."""
        data_home = os.environ.get('XDG_DATA_HOME') or os.path.expanduser('~/.local/share')
        node = self.get_fully_qualified_name().strip('/').replace('/', '__')
        domain = 'domain' + (os.environ.get('ROS_DOMAIN_ID') or '0')
        return os.path.join(data_home, 'armor_ros2', domain, node)

    def _core_jar(self) -> str:
        jar = self._value('core_jar') or os.environ.get('ARMOR_CORE_JAR', '')
        if not jar or not os.path.isfile(jar):
            raise RuntimeError(
                f'knowledge core jar not found ({jar or "unset"}): set the core_jar parameter '
                'or source install/setup.bash, which exports ARMOR_CORE_JAR')
        return jar

    def _value(self, name):
        value = self.get_parameter(name).value
        parameter = self._armor_parameters.get(name)
        if parameter is not None and parameter.also_string is not None:
            return parameter.also_string(value)
        return value

    def _declare_parameters(self) -> None:
        """Declare every parameter, typed; refuse unknown names and values of other types."""
        for parameter in self._armor_parameters.values():
            try:
                self.declare_parameter(parameter.name, parameter.initial(), parameter.descriptor())
            except InvalidParameterTypeException as error:
                raise RuntimeError(f'parameter {parameter.name} must be of type {parameter.type}: '
                                   f'{error}') from error
            if parameter.also_string is not None:
                self._check_string_or_array(parameter)
        known = set(self._armor_parameters) | {'use_sim_time'}
        unknown = sorted(set(self._parameter_overrides) - known)
        if unknown:
            hints = []
            for name in unknown:
                close = difflib.get_close_matches(name, self._armor_parameters, 1)
                hints.append(f'{name} (did you mean {close[0]}?)' if close else name)
            raise RuntimeError(f'unknown parameter(s): {", ".join(hints)}; see the parameter '
                               'table of the README')

    def _check_string_or_array(self, parameter: Parameter) -> None:
        value = self.get_parameter(parameter.name).value
        if not isinstance(value, str) and not (isinstance(value, (list, tuple)) and all(
                isinstance(item, str) for item in value)):
            raise RuntimeError(f'parameter {parameter.name} must be a string array or one string, '
                               f'got {value!r}')


def _refuse_directive(request, response, description: str) -> None:
    response.armor_response = wire.error_response(ExitCode.INTERNAL_ERROR, description)


def _refuse_list(request, response, description: str) -> None:
    response.success = False
    response.armor_responses = [wire.error_response(ExitCode.INTERNAL_ERROR, description)
                                for _ in request.armor_requests]


def main(args=None, on_ready=None):
    """Serve until interrupted; on_ready(node) is called once the node serves."""
    # Ctrl-C and SIGTERM end the spin here, not in rclpy's handler: rclpy's would invalidate the
    # context first, and the lines the core says while it stops could no longer reach /rosout.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    node = None
    try:
        node = ArmorService()
        if on_ready is not None:
            on_ready(node)
        executor = MultiThreadedExecutor(num_threads=node.get_parameter('executor_threads').value)
        executor.add_node(node)
        spin_while(executor, rclpy.ok, timeout_s=1.0)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    except (RuntimeError, CoreUnavailable) as error:
        print(f'armor_service: {error}', file=sys.stderr)
        sys.exit(1)
    finally:
        if node is not None:
            node.shutdown_core()
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
