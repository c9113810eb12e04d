# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""What a release carries agrees with itself (issue 11 item 12): one version everywhere, and a
launch file that starts the installed executable with the installed sample parameters.

launch and launch_ros are not installable from PyPI here, so the launch file is evaluated
against stand-ins that record what it asks for; the parameters file itself is loaded by a
real node in tests/integration/test_params_file.py.
"""

import ast
import importlib.util
import pathlib
import re
import subprocess
import sys
import types
import xml.etree.ElementTree as ET

REPO = pathlib.Path(__file__).resolve().parents[1]


POM = '{http://maven.apache.org/POM/4.0.0}'


def _versions() -> dict:
    """Every place a version of this repository is written, found without a list to forget:
    each package.xml and setup.py, each pom.xml (and a dependency on the core), CMake projects."""
    found = {}
    for manifest in sorted(REPO.glob('*/package.xml')):
        found[str(manifest.relative_to(REPO))] = ET.parse(manifest).findtext('version')
    for setup in sorted([*REPO.glob('*/setup.py'), *REPO.glob('examples/plugins/*/setup.py')]):
        tree = ast.parse(setup.read_text())
        found[str(setup.relative_to(REPO))] = next(
            keyword.value.value for node in ast.walk(tree) if isinstance(node, ast.Call)
            for keyword in node.keywords if keyword.arg == 'version')
    for pom_file in sorted([REPO / 'core' / 'pom.xml', *REPO.glob('plugins/*/pom.xml')]):
        pom = ET.parse(pom_file).getroot()
        name = str(pom_file.relative_to(REPO))
        found[name] = pom.findtext(f'{POM}version')
        for dependency in pom.iter(f'{POM}dependency'):
            if dependency.findtext(f'{POM}artifactId') == 'armor-core':
                found[f'{name} (armor-core dependency)'] = dependency.findtext(f'{POM}version')
    for cmake in sorted(REPO.glob('*/CMakeLists.txt')):
        project = re.search(r'^project\(\S+ VERSION (\S+)', cmake.read_text(), re.MULTILINE)
        if project:
            found[str(cmake.relative_to(REPO))] = project.group(1)
    found['CHANGELOG.md'] = re.search(r'^## (\S+)', (REPO / 'CHANGELOG.md').read_text(),
                                      re.MULTILINE).group(1)
    return found


def test_every_package_the_core_and_the_changelog_carry_one_version():
    versions = _versions()
    for written in ('armor_cpp/package.xml', 'armor_cpp/CMakeLists.txt', 'armor_msgs/package.xml',
                    'plugins/pddl/pom.xml', 'plugins/pddl/pom.xml (armor-core dependency)'):
        assert written in versions, sorted(versions)
    assert len(set(versions.values())) == 1, versions
    assert re.fullmatch(r'\d+\.\d+\.\d+', versions['core/pom.xml']), versions


def test_armor_version_prints_it():
    printed = subprocess.run([sys.executable, '-m', 'armor_client.cli', '--version'],
                             capture_output=True, text=True, timeout=60)
    assert printed.returncode == 0, printed.stderr
    assert printed.stdout.strip() == f'armor {_versions()["core/pom.xml"]}'


def test_the_licence_is_the_apache_2_0_text_the_packages_declare():
    text = (REPO / 'LICENSE').read_text()
    assert 'Apache License' in text and 'Version 2.0, January 2004' in text
    assert 'TERMS AND CONDITIONS FOR USE, REPRODUCTION, AND DISTRIBUTION' in text
    for package in ('armor_msgs', 'armor_contract', 'armor_service', 'armor_client',
                    'sit_armor_injected_msgs', 'sit_armor_injected'):
        assert ET.parse(REPO / package / 'package.xml').findtext('license') == 'Apache-2.0'


class _Recorded:
    """Stands in for a launch class: keeps its arguments."""

    def __init__(self, *args, **kwargs):
        self.args, self.kwargs = args, kwargs


def _stub_launch(monkeypatch):
    modules = {name: types.ModuleType(name) for name in (
        'launch', 'launch.actions', 'launch.substitutions', 'launch_ros', 'launch_ros.actions')}
    modules['launch'].LaunchDescription = lambda actions: actions
    modules['launch.actions'].DeclareLaunchArgument = type('DeclareLaunchArgument', (_Recorded,), {})
    modules['launch.substitutions'].LaunchConfiguration = lambda name: ('configuration', name)
    modules['launch_ros.actions'].Node = type('Node', (_Recorded,), {})
    for name, module in modules.items():
        monkeypatch.setitem(sys.modules, name, module)


def test_the_launch_file_starts_the_installed_executable_with_the_sample_parameters(monkeypatch):
    _stub_launch(monkeypatch)
    spec = importlib.util.spec_from_file_location(
        'armor_launch', REPO / 'armor_service' / 'launch' / 'armor.launch.py')
    launch_file = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(launch_file)
    actions = launch_file.generate_launch_description()
    arguments = {a.args[0]: a.kwargs['default_value'] for a in actions
                 if type(a).__name__ == 'DeclareLaunchArgument'}
    node = next(a for a in actions if type(a).__name__ == 'Node')
    # The executable is a console script armor_service's setup.py installs.
    setup = (REPO / 'armor_service' / 'setup.py').read_text()
    assert f"'{node.kwargs['executable']} = armor_service.node:main'" in setup
    assert node.kwargs['package'] == 'armor_service'
    assert node.kwargs['parameters'] == [('configuration', 'params_file')]
    assert node.kwargs['namespace'] == ('configuration', 'namespace')
    # The default parameters file is the sample, installed in the package's share folder.
    sample = pathlib.Path(arguments['params_file'])
    assert sample.is_file() and sample.name == 'armor.params.yaml', sample
    assert sample.read_text() == (REPO / 'armor_service' / 'config' / 'armor.params.yaml').read_text()
