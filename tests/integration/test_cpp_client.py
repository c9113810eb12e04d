# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The C++ client (armor_cpp) against the live node, and the program of docs/cpp-client.md.

The GoogleTest program build/armor_cpp/armor_cpp_live_test (built by make test) runs once
against the session's node, in its own process over real ROS 2; each of its cases is one test
here, so a failure names the case and shows GoogleTest's message. The docs' C++ program is
built as a user builds it (its CMakeLists.txt, find_package(armor_cpp) from install/) and must
answer a query as the Python client does at the same moment.
"""

import os
import re
import subprocess
import xml.etree.ElementTree as ET

from armor_client import Armor
from conftest import cmake_built, ONTOLOGIES, REPO
import pytest

BUILD = REPO / 'build' / 'armor_cpp'
LIVE_TEST = BUILD / 'armor_cpp_live_test'
DOC = REPO / 'docs' / 'cpp-client.md'
EXAMPLES = REPO / 'armor_cpp' / 'examples'


def live_cases():
    """The GoogleTest cases of the live test (Suite.Case), listed by the program itself."""
    if not LIVE_TEST.exists():
        return ['build/armor_cpp/armor_cpp_live_test is missing: run make test (tools/setup.sh test builds it)']
    listed = subprocess.run([str(LIVE_TEST), '--gtest_list_tests'], capture_output=True,
                            text=True, timeout=60, check=True).stdout
    cases, suite = [], ''
    for line in listed.splitlines():
        if not line.startswith(' '):
            suite = line.strip()
        else:
            cases.append(suite + line.split('#')[0].strip())
    return cases


@pytest.fixture(scope='module')
def live_results(armor, armor_node, tmp_path_factory):
    """Run the live test once: case -> its failure messages ('' when it passed).

    A case that skipped itself (GTEST_SKIP) did not pass: its message says it was skipped.
    """
    report = tmp_path_factory.mktemp('gtest') / 'live.xml'
    env = {**os.environ, 'ARMOR_TEST_ONTOLOGY': str(ONTOLOGIES / 'robotics.owl'),
           'ARMOR_TEST_SCRATCH': str(armor_node.scratch),
           'ARMOR_TEST_PDDL_MAPPING': str(REPO / 'examples' / 'pddl' / 'robotics-mapping.yaml')}
    done = subprocess.run([str(LIVE_TEST), f'--gtest_output=xml:{report}'], env=env,
                          capture_output=True, text=True, timeout=600)
    assert report.exists(), done.stdout[-3000:] + done.stderr[-3000:]
    results = {}
    for case in ET.parse(report).getroot().iter('testcase'):
        failures = [failure.get('message', '') for failure in case.iter('failure')]
        failures += [f'skipped: {skip.get("message", "")}' for skip in case.iter('skipped')]
        if case.get('result') == 'skipped' and not failures:
            failures.append('skipped')
        results[f'{case.get("classname")}.{case.get("name")}'] = '\n'.join(failures)
    return results


@pytest.mark.parametrize('case', live_cases())
def test_cpp_client_against_the_live_node(live_results, case):
    assert case in live_results, f'{case} did not run'
    assert live_results[case] == '', live_results[case]


def code_block(text: str, language: str, after: str) -> str:
    """The first ```language block of the docs after the line `after`."""
    start = text.index(after)
    return re.search(rf'```{language}\n(.*?)```', text[start:], re.DOTALL).group(1)


def test_the_docs_program_is_the_example_and_builds_with_the_projects_cmake(armor, tmp_path):
    doc = DOC.read_text()
    program = code_block(doc, 'cpp', '<!-- example: query_rooms.cpp -->')
    cmake = code_block(doc, 'cmake', '<!-- example: CMakeLists.txt -->')
    assert program == (EXAMPLES / 'query_rooms.cpp').read_text()
    (tmp_path / 'query_rooms.cpp').write_text(program)
    (tmp_path / 'CMakeLists.txt').write_text(cmake)
    ran = subprocess.run([str(cmake_built(tmp_path, 'query_rooms'))], capture_output=True,
                         text=True, timeout=120)
    assert ran.returncode == 0, ran.stderr
    occupied = Armor('cpp_docs_check', transport=armor).reference('robotics').instances(
        'OccupiedRoom')
    printed = ran.stdout.splitlines()
    assert occupied and [line.split(' ', 1)[0] for line in printed[:-1]] == occupied, printed
    assert printed[-1] == 'consistent: yes'


def test_the_docs_show_the_rclcpp_example_as_it_is_in_the_package():
    doc = DOC.read_text()
    assert code_block(doc, 'cpp', '<!-- example: rclcpp_planner.cpp -->') == (
        EXAMPLES / 'rclcpp_planner.cpp').read_text()
    assert 'not compiled' in doc
