# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Paths in directives: one rule for every client (docs/commands.md#paths).

The node reads and writes files on its own machine and refuses a relative path (213): its
working directory is not the caller's. So every client here makes a relative path argument
absolute against the caller's working directory before sending it: ``maps/home.owl`` means
the file the caller sees there, as ``open()`` would. Which arguments are paths, the catalogue
says (an argument with the word "path" in its name). A value holding a line break or starting
with ``{`` is text given instead of a file (a PDDL mapping), never a path.
"""

import os
from typing import List, Optional, Sequence

from armor_contract.catalogue import Command


def absolute(path: str, cwd: Optional[str] = None) -> str:
    """A path argument as it is sent: a relative one joined to ``cwd``.

    ``cwd`` is by default this process's working directory. ".." is left for the node to
    apply after following links, as the kernel does.

    Args:
        path: the path as the caller wrote it ('' stays '': "the file it was loaded from").
        cwd: the directory it is relative to.

    Returns:
        The absolute path, or the argument unchanged when it is empty, absolute or text.
    """
    text = path.strip()
    if not text or '\n' in text or text.startswith('{') or os.path.isabs(text):
        return path
    return os.path.join(cwd or os.getcwd(), text)


def absolute_args(command: Optional[Command], args: Sequence[str],
                  cwd: Optional[str] = None) -> List[str]:
    """A directive's arguments with its path arguments made absolute (others unchanged).

    Args:
        command: the catalogue entry of the directive (None: unknown here, sent unchanged).
        args: its arguments as text.
        cwd: the directory relative paths are relative to (default: the working directory).

    Returns:
        The arguments to send.
    """
    positions = command.path_positions if command is not None else ()
    return [absolute(arg, cwd) if i in positions else arg for i, arg in enumerate(args)]
