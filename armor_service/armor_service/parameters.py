# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The node's parameters, each declared once: the core's settings and the node's own.

The core's settings come from its catalogue (armor_contract's catalogue.json, checked against
the core by tests/test_catalogue.py), so a setting added in Setting.java becomes a parameter
without a line here. The node's own parameters (how it starts and supervises the core, what it
preloads) are declared below in the same shape. Every parameter is typed; those not live are
read-only. README's parameter table is generated from both lists (make catalogue).
"""

import os
import shlex
import tempfile
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Tuple

from armor_contract import catalogue
from rcl_interfaces.msg import ParameterDescriptor, ParameterType

_ROS_TYPES = {
    'boolean': ParameterType.PARAMETER_BOOL, 'integer': ParameterType.PARAMETER_INTEGER,
    'double': ParameterType.PARAMETER_DOUBLE, 'string': ParameterType.PARAMETER_STRING,
    'string_array': ParameterType.PARAMETER_STRING_ARRAY,
}


def path_list(value: Any) -> List[str]:
    """A directory list as users type it: a string array, one path, or paths joined by ':'."""
    if isinstance(value, str):
        return [part for part in value.split(os.pathsep) if part.strip()]
    return list(value)


def name_list(value: Any) -> List[str]:
    """Names as typed: a string array, or one string of names separated by commas or spaces."""
    if isinstance(value, str):
        return [part for part in value.replace(',', ' ').split() if part]
    return list(value)


def option_list(value: Any) -> List[str]:
    """Command-line options as typed: a string array, or one string split as by a shell."""
    if isinstance(value, str):
        return shlex.split(value)
    return list(value)


@dataclass(frozen=True)
class Parameter:
    """One parameter of the node.

    Attributes:
        name: the parameter's name (for a core setting, the setting's key).
        type: a catalogue type: boolean, integer, double, string, string_array.
        default: its default (a callable computes it when the node starts).
        description: what it sets.
        read_only: whether it is read only at start (changing it later has no effect).
        core: whether it is handed to the core as a setting.
        also_string: a string is accepted too and converted by this function.
        default_text: how the README shows a default computed at start.
    """

    name: str
    type: str
    default: Any
    description: str
    read_only: bool = True
    core: bool = False
    also_string: Optional[Callable[[Any], List[str]]] = None
    default_text: Optional[str] = None

    def descriptor(self) -> ParameterDescriptor:
        """The ROS descriptor: type, meaning, read-only (dynamic where a string is taken too)."""
        descriptor = ParameterDescriptor(description=self.description, read_only=self.read_only)
        if self.also_string is not None:
            descriptor.dynamic_typing = True
        else:
            descriptor.type = _ROS_TYPES[self.type]
        return descriptor

    def initial(self) -> Any:
        """The default, computed now if it is computed at start."""
        return self.default() if callable(self.default) else self.default


# Defaults that suit a node better than the core's own (which suit tests and embedding).
_NODE_DEFAULTS: Dict[str, Tuple[Callable[[], Any], str]] = {
    'allowed_dirs': (lambda: [os.getcwd(), os.path.expanduser('~'), tempfile.gettempdir()],
                     'working dir, home, temp dir'),
    # One folder of ARMOR's own, made 0700 at start: nothing a client writes lands among the
    # user's files, code or dotfiles unless the operator says where (docs/security.md).
    'write_dirs': (lambda: [os.path.join(os.path.expanduser('~'), 'armor_files')],
                   '`~/armor_files` (made 0700 at start)'),
    'protected_dirs': (lambda: [], '(none; the installation always is)'),
    'state_dir': (lambda: '', '`$XDG_DATA_HOME/armor_ros2/domain<ID>/<node name>`'),
    # The user's own: the installed plugins come with installed_plugins, whatever is set here.
    'plugin_dirs': (lambda: [], None),
}
_NODE_DESCRIPTIONS = {
    'allowed_dirs': ' (a string array, one path, or paths joined by ":")',
    'write_dirs': ' (a string array, one path, or paths joined by ":")',
    'protected_dirs': ' (a string array, one path, or paths joined by ":")',
    'state_dir': ' (empty: the default directory)',
    'plugin_dirs': ' (a string array, one path, or paths joined by ":"), loaded besides the '
                   'installed plugins (installed_plugins)',
}
_ALSO_STRING = {'allowed_dirs': path_list, 'write_dirs': path_list, 'protected_dirs': path_list,
                'plugin_dirs': path_list}
# Parameters of earlier releases still accepted: name -> (the parameter whose list it joins).
DEPRECATED_ALIASES = {'plugin_dir': 'plugin_dirs'}


def core_parameters() -> Tuple[Parameter, ...]:
    """One parameter per setting of the core's catalogue."""
    made = []
    for setting in catalogue.load().settings:
        default, text = _NODE_DEFAULTS.get(setting.key, (setting.default, None))
        made.append(Parameter(
            setting.key, setting.type, default,
            setting.description + _NODE_DESCRIPTIONS.get(setting.key, ''),
            read_only=setting.read_only, core=True, also_string=_ALSO_STRING.get(setting.key),
            default_text=text))
    return tuple(made)


NODE_PARAMETERS: Tuple[Parameter, ...] = (
    Parameter('core_start_timeout_s', 'double', 600.0,
              'longest wait for the core to start and restore its references'),
    Parameter('request_timeout_s', 'double', 0.0,
              'longest wait for the core per request (0 = none)', read_only=False),
    Parameter('core_jar', 'string', '', "path of the core's jar (empty: $ARMOR_CORE_JAR)",
              default_text='`$ARMOR_CORE_JAR`'),
    # The serial collector halves the core's peak memory against G1 (bench/REPORT.md, part 6).
    Parameter('jvm_options', 'string_array',
              ['-Xmx4g', '-XX:+UseSerialGC', '-XX:+ExitOnOutOfMemoryError'],
              'options of the core JVM, as a string array or one string split as a shell does; '
              'out of memory restarts the core; an -Xshare or -XX:SharedArchiveFile option '
              "replaces the class archive beside the jar (armor-core.jsa, made by make setup)",
              also_string=option_list),
    Parameter('executor_threads', 'integer', 16, 'directives answered at once'),
    Parameter('preload_file', 'string', '', 'ontology loaded at start and after a core restart'),
    Parameter('preload_reference', 'string', 'default',
              'reference name of the preloaded ontology (make run uses robotics)'),
    Parameter('preload_iri', 'string', '', "its ontology IRI (empty: the file's own)"),
    Parameter('preload_reasoner', 'string', '', 'its reasoner (empty: default_reasoner)'),
    Parameter('preload_buffered_manipulation', 'boolean', False,
              'its changes wait for APPLY'),
    Parameter('preload_buffered_reasoner', 'boolean', False,
              'its reasoner sees changes only at REASON'),
    Parameter('extensions', 'string_array', ['sit'],
              'Python extensions to load (entry points of group armor_service.extensions; '
              'a string array or names separated by commas); sit is the scene service '
              '(docs/scenes.md): name it too when you set this', also_string=name_list),
    Parameter('installed_plugins', 'boolean', True,
              'also load the plugins make setup installed (`$ARMOR_PLUGIN_DIRS`: the PDDL '
              'bridge), whatever plugin_dirs says'),
    Parameter('plugin_dir', 'string', '',
              'deprecated since 0.3.0: one directory, added to plugin_dirs'),
    Parameter('subscription_idle_s', 'double', 5.0,
              "a subscription whose topic has had no subscriber this long ends (its client "
              "went away)", read_only=False),
    # Each live subscription costs the node a publisher and the core a query after every change
    # of its reference: one client's flood must not slow every other (docs/security.md).
    Parameter('subscriptions_per_client', 'integer', 100,
              'most live subscriptions one client_name may hold; then 226 (0 = no limit)',
              read_only=False),
    Parameter('web_port', 'integer', 0,
              'TCP port of the live, read-only web view of every reference (0 = off; make run '
              'uses 8080; docs/web-view.md)'),
    # The scene service's relation thresholds (sit extension, docs/scenes.md); each request's
    # directive carries the values it was answered with, so a restart replays it exactly.
    Parameter('sit_position_threshold', 'double', 0.03,
              'scene service: metres two centres must differ by to be right/behind/above, and '
              'within which they lie along an axis', read_only=False),
    Parameter('sit_axis_threshold', 'double', 0.05,
              'scene service: how nearly two axes must be parallel or perpendicular, and the '
              'squared distance within which a centre is on an axis', read_only=False),
    Parameter('web_host', 'string', '127.0.0.1',
              'address the web view listens on; any but a loopback address lets every machine '
              'that reaches it read every reference (docs/web-view.md)'),
)


def all_parameters() -> Tuple[Parameter, ...]:
    """The core's settings, then the node's own parameters."""
    return core_parameters() + NODE_PARAMETERS


def core_settings(value: Callable[[str], Any], warn: Callable[[str], None]) -> Dict[str, Any]:
    """The settings handed to the core: each core parameter's value, deprecated aliases joined.

    Args:
        value: the value of a parameter, by name, as the node read it.
        warn: says that a deprecated parameter was used and what replaces it.

    Returns:
        Setting key -> value.
    """
    settings = {p.name: value(p.name) for p in core_parameters()}
    for alias, target in DEPRECATED_ALIASES.items():
        given = value(alias)
        if given:
            warn(f'parameter {alias} is deprecated: use {target} (a list); {given} is added to it')
            settings[target] = [*settings[target], *path_list(given)]
    if value('installed_plugins'):
        # Setting plugin_dirs to add a plugin must not drop the planner bridge unnoticed.
        installed = path_list(os.environ.get('ARMOR_PLUGIN_DIRS', ''))
        settings['plugin_dirs'] = [*installed, *(directory for directory in settings['plugin_dirs']
                                                 if directory not in installed)]
    return settings
