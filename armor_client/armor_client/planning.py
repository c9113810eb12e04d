# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The planner bridge's commands (the PDDL plugin the node loads by default; docs/pddl.md).

Mixed into every reference class (Reference, AsyncReference) like the contract's commands:
each method builds a directive and says how to read the answer; ``_execute`` sends it.
"""

import json
import os
from typing import Any, Callable, Mapping, Sequence, Tuple, Union

from armor_client.paths import absolute
from armor_client.plugin_faces import written_for

MappingArgument = Union[str, 'os.PathLike[str]', Mapping[str, Any]]


def mapping_argument(mapping: MappingArgument) -> str:
    """The mapping as the directive carries it: an absolute path, or the text itself.

    A dict is sent as JSON text (the plugin reads YAML and JSON); a string is a path (made
    absolute against the working directory, as every path argument is) unless it holds a line
    break or starts with '{' (then it is the mapping).
    """
    if isinstance(mapping, Mapping):
        return json.dumps(mapping)
    return absolute(os.fspath(mapping))


class PlannerBridge:
    """PDDL problems generated from what a reference knows, asserted and inferred."""

    def _execute(self, words: Tuple[str, str, str], args: Sequence[Any],
                 parse: Callable[[Any], Any]) -> Any:
        raise NotImplementedError

    @written_for('QUERY PDDL PROBLEM')
    def pddl_problem(self, mapping: MappingArgument) -> str:
        """A PDDL problem of this reference's state (QUERY PDDL PROBLEM).

        Args:
            mapping: a mapping file (a relative path is the caller's; the node reads it inside
                its allowed_dirs), its YAML or JSON text, or a dict: which classes become types
                and predicates, which properties predicates and fluents, and the goal
                (docs/pddl.md).

        Returns:
            The problem's text; the same state gives the same bytes.
        """
        # One string answers; joined, an answer without it reads as no text rather than failing.
        return self._execute(('QUERY', 'PDDL', 'PROBLEM'), [mapping_argument(mapping)],
                             lambda response: ''.join(response.queried_objects))

    def save_pddl_problem(self, mapping: MappingArgument, path: str) -> None:
        """Write that PDDL problem to a file on the node's machine (SAVE PDDL PROBLEM).

        Args:
            mapping: as for pddl_problem.
            path: where (a relative path is the caller's), inside the node's allowed_dirs.
        """
        arguments = [mapping_argument(mapping), absolute(path)]
        return self._execute(('SAVE', 'PDDL', 'PROBLEM'), arguments, lambda response: None)
