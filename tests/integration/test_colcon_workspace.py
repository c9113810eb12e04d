# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""colcon builds the repository as a ROS 2 workspace, and that install space alone serves.

The working tree is copied into src/ of a scratch workspace and built there by colcon
(tools/requirements-colcon.txt) on top of install/underlay.sh, the ROS 2 of the wheels in
.venv (what /opt/ros/<distro>/setup.bash is on a machine with ROS 2 installed). Every folder
of the repository with a package.xml must be built: a new package is covered by adding it,
nothing here. Then, in an environment made of the underlay and the workspace's
install/setup.bash only, `armor serve` starts and `armor call` answers a directive.
"""

import os
import pathlib
import re
import shutil
import signal
import subprocess
import time

import pytest

from conftest import ONTOLOGIES

pytestmark = pytest.mark.runs_for_minutes(3)

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD_TIMEOUT_S = 3600  # an idle 2-core machine needs a few minutes; one shared by 8 builds took 25+


def repository_files():
    listed = subprocess.run(['git', 'ls-files', '-z', '--cached', '--others', '--exclude-standard'],
                            cwd=REPO, capture_output=True, check=True).stdout
    return [name for name in listed.decode().split('\0') if name and (REPO / name).is_file()]


def package_names(files):
    """The name in each package.xml of the repository (not under a COLCON_IGNOREd folder)."""
    ignored = [pathlib.PurePath(f).parent for f in files if pathlib.PurePath(f).name == 'COLCON_IGNORE']
    names = set()
    for name in files:
        path = pathlib.PurePath(name)
        if path.name == 'package.xml' and not any(d in path.parents for d in ignored):
            names.add(re.search(r'<name>\s*([^<\s]+)\s*</name>', (REPO / name).read_text()).group(1))
    return names


def in_workspace(workspace, command):
    """bash -c command with the underlay and the workspace's install space, nothing else."""
    setup = workspace / 'install' / 'setup.bash'
    script = (f'source {REPO / "install" / "underlay.sh"} && '
              + (f'source {setup} && ' if setup.exists() else '') + command)
    env = {'HOME': os.environ.get('HOME', '/root'), 'PATH': '/usr/local/bin:/usr/bin:/bin',
           'LANG': 'C.UTF-8', 'ROS_DOMAIN_ID': os.environ['ROS_DOMAIN_ID'],
           'ARMOR_CALL_RELAY_IDLE_S': '60',
           # colcon's make otherwise adds -l<cores>, and under the suite's other workers the
           # load stays above 2: the build would go one job at a time.
           'MAKEFLAGS': f'-j{os.cpu_count()}',
           # Lines reach the log file as they are said, not when a buffer fills.
           'RCUTILS_LOGGING_BUFFERED_STREAM': '0', 'PYTHONUNBUFFERED': '1'}
    return {'args': ['bash', '-c', script], 'cwd': workspace, 'env': env}


def run(workspace, command, timeout=120, **options):
    options.setdefault('capture_output', True)
    return subprocess.run(**in_workspace(workspace, command), text=True, timeout=timeout,
                          **options)


@pytest.mark.timeout(BUILD_TIMEOUT_S + 300)
def test_colcon_builds_every_package_and_its_install_space_serves(tmp_path):
    workspace = tmp_path / 'ws'
    source = workspace / 'src' / 'armor_ros2'
    files = repository_files()
    for name in files:
        (source / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(REPO / name, source / name)
    expected = package_names(files)
    assert {'armor_msgs', 'armor_core', 'armor_service', 'armor_client', 'armor_cpp'} <= expected

    listed = run(workspace, 'colcon list --names-only')
    assert listed.returncode == 0, listed.stderr
    assert set(listed.stdout.split()) == expected, listed.stdout
    log = tmp_path / 'colcon-build.log'
    with open(log, 'w') as out:
        built = run(workspace, 'colcon build --event-handlers console_direct- '
                    '--cmake-args -DBUILD_TESTING=OFF', timeout=BUILD_TIMEOUT_S,
                    capture_output=False, stdout=out, stderr=subprocess.STDOUT)
    assert built.returncode == 0, log.read_text()[-4000:]
    for package in expected:
        assert (workspace / 'install' / package / 'share' / package / 'package.xml').is_file(), package

    # What the sourced install space provides comes from the workspace, not from this checkout.
    where = run(workspace, 'command -v armor; echo "$ARMOR_CORE_JAR"; echo "$ARMOR_PLUGIN_DIRS"; '
                'python -c "import armor_client, armor_service, armor_contract, armor_msgs; '
                'print(armor_client.__file__, armor_service.__file__, armor_contract.__file__, '
                'armor_msgs.__file__)"')
    assert where.returncode == 0, where.stderr
    armor, core_jar, plugin_dirs, modules = where.stdout.splitlines()
    assert armor == str(workspace / 'install' / 'armor_client' / 'bin' / 'armor'), where.stdout
    assert os.path.isfile(core_jar), where.stdout
    for path in (core_jar, plugin_dirs, *modules.split()):
        assert path.startswith(str(workspace / 'install')), where.stdout

    serve_log = tmp_path / 'armor_serve.log'
    with open(serve_log, 'w') as out:
        node = subprocess.Popen(**in_workspace(
            workspace, f'exec armor serve --ros-args -p preload_file:={ONTOLOGIES / "robotics.owl"} '
            f'-p preload_reference:=robotics -p allowed_dirs:={ONTOLOGIES} '
            f'-p state_dir:={tmp_path / "state"} -p web_port:=0'), stdout=out, stderr=subprocess.STDOUT)
    try:
        answer = run(workspace, 'armor call --wait 120 robotics QUERY IND CLASS -- Room', timeout=300)
        assert answer.returncode == 0, answer.stderr + serve_log.read_text()
        assert '<http://www.example.org/robotics#kitchen>' in answer.stdout.splitlines(), answer.stdout
        # The plugin package's commands are in the catalogue: its hook set ARMOR_PLUGIN_DIRS.
        catalogue = run(workspace, 'armor call - GET CATALOGUE')
        assert catalogue.returncode == 0, catalogue.stderr
        assert 'PDDL' in catalogue.stdout, catalogue.stdout
        deadline = time.monotonic() + 60
        while 'ARMOR ready' not in serve_log.read_text() and time.monotonic() < deadline:
            time.sleep(0.5)
    finally:
        run(workspace, 'python -c "from armor_client.cli import call_relay; call_relay.stop()"')
        node.send_signal(signal.SIGINT)
        try:
            node.wait(timeout=60)
        except subprocess.TimeoutExpired:
            node.kill()
            node.wait()
    assert 'ARMOR ready' in serve_log.read_text()
