# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The ROS packages pass the usual linters, and the typed client its type check.

As ament_lint's tests would: flake8 (99 columns, .flake8), pep257 docstrings with pydocstyle
(Google convention, the style the code is written in; a missing docstring is not an error),
the copyright line on every source file, package.xml files well-formed and valid by catkin_pkg
(the format 3 schema itself lives on a web server the build cannot reach), and mypy over
armor_client (it ships py.typed) and armor_contract. The tools are pinned in
tools/requirements-lint.txt and installed by tools/setup.sh.
"""

import pathlib
import subprocess
import sys
import xml.etree.ElementTree as ET

from catkin_pkg.package import parse_package
import pytest

REPO = pathlib.Path(__file__).resolve().parents[1]
PYTHON_PACKAGES = ('armor_contract', 'armor_service', 'armor_client', 'sit_armor_injected')
ROS_PACKAGES = ('armor_msgs', 'armor_cpp', 'sit_armor_injected_msgs', *PYTHON_PACKAGES)
COPYRIGHT = '# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.'


def _run(*command: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, '-m', *command], cwd=REPO, capture_output=True,
                          text=True, timeout=600)


def test_flake8():
    result = _run('flake8', *PYTHON_PACKAGES)
    assert result.returncode == 0, result.stdout + result.stderr


def test_pep257():
    result = _run('pydocstyle', '--convention=google',
                  '--add-ignore=D100,D101,D102,D103,D104,D105,D106,D107,D401', *PYTHON_PACKAGES)
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.parametrize('package', PYTHON_PACKAGES)
def test_copyright(package):
    missing = []
    for source in sorted((REPO / package).rglob('*.py')):
        lines = source.read_text().splitlines()[:2]
        if COPYRIGHT not in lines:
            missing.append(str(source.relative_to(REPO)))
    assert missing == []


@pytest.mark.parametrize('package', ROS_PACKAGES)
def test_package_xml(package):
    manifest = REPO / package / 'package.xml'
    assert ET.parse(manifest).getroot().get('format') == '3'
    warnings: list = []
    parsed = parse_package(str(manifest), warnings=warnings)
    assert parsed.name == package and warnings == []


def test_mypy_on_the_typed_client():
    result = _run('mypy', 'armor_client/armor_client', 'armor_contract/armor_contract')
    assert result.returncode == 0, result.stdout + result.stderr
