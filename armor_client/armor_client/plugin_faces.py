# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Methods for the commands a node's plugins add, made at run time from its catalogue's faces.

The built-in commands' methods are generated when the client is built (faces.py); a plugin's
commands are known only to the node that loaded it. A session therefore asks its node for the
catalogue (GET CATALOGUE) once, when a reference is first asked for a method it does not have
(or when ``learn_plugin_methods()`` is called), and adds one method per plugin command with a
face to the reference class of that session only: ``ref.greet('kitchen')`` then sends the
plugin's directive and reads its answer exactly as a generated method of the same face does
(entities as names, typed values, Manchester text, or nothing for a change). ``help()``,
``inspect.signature`` and ``dir()`` see those methods; arguments are checked before anything
is sent. A face whose method name the client already has (a built-in method, another plugin's)
is refused: not added, with a warning naming both, and ``learn_plugin_methods()`` lists it,
unless the client's method was written by hand for that very command (``@written_for``: the
installed plugins' composites, such as ``pddl_problem``), which is kept without a word.
"""

import inspect
import warnings
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Sequence, TypeVar

from armor_client.answers import Answers
from armor_client.values import Value
from armor_contract.catalogue import Command, FaceParameter

_RETURNS = {'none': None, 'entities': List[str], 'values': List[Value],
            'expressions': List[str]}
_READERS: Dict[str, Callable[[Answers], Callable[[Any], Any]]] = {
    'none': lambda answers: Answers.nothing,
    'entities': lambda answers: answers.entities,
    'values': lambda answers: answers.values,
    'expressions': lambda answers: answers.expressions,
}

Method = TypeVar('Method', bound=Callable[..., Any])


def written_for(command: str) -> Callable[[Method], Method]:
    """Mark a method written by hand for a plugin's command (``'QUERY PDDL PROBLEM'``).

    That command's face then adds no method and is not reported as refused: the hand-written
    one (which reads the answer better than a face can) answers it.
    """
    def mark(method: Method) -> Method:
        method._plugin_command = command  # type: ignore[attr-defined]
        return method
    return mark


@dataclass
class PluginMethods:
    """What a node's catalogue added to a session's references.

    Attributes:
        added: method name -> the plugin command it sends.
        refused: command name (``QUERY GREETING``) -> why its face got no method.
    """

    added: Dict[str, Command] = field(default_factory=dict)
    refused: Dict[str, str] = field(default_factory=dict)


def add_methods(classes: Dict[type, type], commands: Sequence[Command],
                known: PluginMethods) -> PluginMethods:
    """Add a method for each plugin command of ``commands`` with a face to a session's classes.

    Args:
        classes: the session's own reference class, then its batch class, each mapped to the
            client's class it derives from (whose methods a plugin may not replace); a batch
            gets the changes only.
        commands: the node's catalogue.
        known: what earlier calls added: kept when this catalogue has the same command, removed
            from the classes when it does not (a node restarted without that plugin).

    Returns:
        ``known``, with what this catalogue added and refused.
    """
    for name, added in list(known.added.items()):
        if added not in commands:
            for session_class in classes:
                if name in vars(session_class):
                    delattr(session_class, name)
            del known.added[name]
    known.refused.clear()
    for command in commands:
        face = command.face
        if face is None or command.origin == 'core' or known.added.get(face.method) == command:
            continue
        # Batches queue changes: a query's method is the references' only.
        targets = list(classes.items()) if face.answer == 'none' else list(classes.items())[:1]
        if all(_written_for(built_in, face.method) == command.name for _, built_in in targets):
            continue
        taken = next((why for why in (_taken(built_in, face.method) for _, built_in in targets)
                      if why), '') or _added_by(known, face.method)
        if taken:
            reason = (f'{command.name} (plugin {command.origin}) gets no method {face.method}(): '
                      f'{taken}; send it with call()')
            known.refused[command.name] = reason
            warnings.warn(reason, RuntimeWarning, stacklevel=3)
            continue
        method = face_method(command)
        for session_class, _ in targets:
            setattr(session_class, face.method, method)
        known.added[face.method] = command
    return known


def _written_for(built_in: type, method: str) -> str:
    return getattr(getattr(built_in, method, None), '_plugin_command', '')


def _taken(built_in: type, method: str) -> str:
    if hasattr(built_in, method):
        return f'{built_in.__name__} already has {method}()'
    return ''


def _added_by(known: PluginMethods, method: str) -> str:
    other = known.added.get(method)
    return f'{other.name} (plugin {other.origin}) has that method' if other else ''


def face_method(command: Command) -> Callable[..., Any]:
    """The method of a plugin command's face, as a generated method of that face would be."""
    face = command.face
    assert face is not None
    kind = (inspect.Parameter.VAR_POSITIONAL if command.variadic
            else inspect.Parameter.POSITIONAL_OR_KEYWORD)
    signature = inspect.Signature(
        [inspect.Parameter('self', inspect.Parameter.POSITIONAL_OR_KEYWORD)]
        + [inspect.Parameter(p.name, kind, annotation=int if p.type == 'int' else str)
           for p in face.parameters],
        return_annotation=_RETURNS[face.answer])
    reader = _READERS[face.answer]

    def method(self: Any, *args: Any, **kwargs: Any) -> Any:
        armor = getattr(self, 'armor', None)  # a reference's session (a batch has none)
        if armor is not None and armor._plugin_methods_stale():
            # The node restarted, maybe with other plugins: call what its catalogue says now
            # (this method again, another face of that name, or an AttributeError).
            armor._plugin_method(face.method)
            return getattr(self, face.method)(*args, **kwargs)
        try:
            bound = signature.bind(self, *args, **kwargs)
        except TypeError as e:
            raise TypeError(f'{face.method}(): {e}') from None
        values = []
        for parameter in face.parameters:
            given = bound.arguments.get(parameter.name, ())
            for value in (given if command.variadic else (given,)):
                values.append(_argument(face.method, parameter, value))
        # A batch queues the directive and reads no answer (it has no ``answers``).
        return self._execute(command.words, values,
                             reader(self.answers) if face.answer != 'none' else Answers.nothing)

    method.__name__ = method.__qualname__ = face.method
    method.__signature__ = signature  # type: ignore[attr-defined]
    method.__doc__ = _docstring(command)
    return method


def _argument(method: str, parameter: FaceParameter, value: Any) -> str:
    """One argument as sent; a value of the wrong type is refused before anything is sent."""
    if parameter.type == 'int':
        if isinstance(value, bool) or not isinstance(value, (int, str)):
            raise TypeError(f'{method}(): {parameter.name} must be a whole number, '
                            f'not {type(value).__name__}')
        try:
            return str(int(value))
        except ValueError:
            raise TypeError(f'{method}(): {parameter.name} must be a whole number, '
                            f'not {value!r}') from None
    if not isinstance(value, str):
        raise TypeError(f'{method}(): {parameter.name} must be a str, not {type(value).__name__}')
    return value


def _docstring(command: Command) -> str:
    summary = command.summary
    lines = [f'{summary[:1].upper()}{summary[1:]} ({command.name}; plugin {command.origin}).']
    face = command.face
    assert face is not None
    if face.parameters:
        names = list(command.required)
        lines += ['', 'Args:']
        lines += [f'    {p.name}: {", ".join(names) if command.variadic else names[i]}.'
                  for i, p in enumerate(face.parameters)]
    return '\n'.join(lines)
