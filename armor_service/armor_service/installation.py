# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Where the code the node runs lives: folders no directive may ever write into.

A file written there becomes code: a ``.pth`` file in site-packages runs at every start of that
Python, a module in a package directory is imported. The core knows its own jar, the Java
runtime, plugin_dirs and state_dir; only the node knows its Python side, which it hands over
as protected_dirs (docs/security.md).
"""

import os
import pathlib
import site
import sys
from typing import List

# The packages of this repository the node imports (armor_msgs: the generated messages).
_PACKAGES = ('armor_service', 'armor_client', 'armor_contract', 'armor_msgs')


def code_dirs() -> List[str]:
    """The node's Python environment, its packages' folders and the checkout they come from.

    Folders that hold the user's own files as well as code (the home directory, the root, a
    temporary directory) are left out: they are never written directly already, and protecting
    them whole would leave nothing writable.
    """
    found = [sys.prefix, sys.base_prefix, *site.getsitepackages()]
    found += [entry for entry in sys.path if entry]
    found += [p for p in os.environ.get('AMENT_PREFIX_PATH', '').split(os.pathsep) if p]
    for name in _PACKAGES:
        module = sys.modules.get(name)
        location = getattr(module, '__file__', None) if module else None
        if location:
            package = pathlib.Path(location).resolve().parent
            found += [str(package.parent), *_checkout_of(package)]
    too_wide = {pathlib.Path('/'), pathlib.Path.home().resolve(), pathlib.Path('/tmp'),
                pathlib.Path.home().resolve().parent}
    kept = []
    for entry in found:
        path = pathlib.Path(entry).resolve()
        if path.is_dir() and path not in too_wide and str(path) not in kept:
            kept.append(str(path))
    return kept


def _checkout_of(package: pathlib.Path) -> List[str]:
    """The git checkout a package's folder lies in (a development install), if any."""
    for folder in package.parents:
        if (folder / '.git').exists():
            return [str(folder)]
    return []
