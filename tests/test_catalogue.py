# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The core owns the catalogue; nothing else may disagree with it.

The installed core is asked for its catalogue (``java -jar armor-core.jar --catalogue``); the
generated catalogue.json the Python side reads, the exit-code enums and the tables of
docs/commands.md must all say the same. A command added on one side only fails here.
"""

import importlib.util
import json
import pathlib

from armor_contract import catalogue
from armor_contract.exit_codes import ExitCode
from armor_client import commands
import pytest

REPO = pathlib.Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location('catalogue_tool', REPO / 'tools' / 'catalogue.py')
tool = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(tool)


@pytest.fixture(scope='module')
def core_text():
    return tool.core_catalogue_text(tool.core_jar())


def test_the_python_catalogue_docs_and_exit_codes_agree_with_the_core(core_text):
    found = tool.differences(core_text, tool.installed_plugins_catalogue(tool.core_jar()))
    assert not found, '\n'.join(found)


def test_every_core_command_is_parsed_and_completed_by_the_cli(core_text):
    core = catalogue.parse(json.loads(core_text))
    for command in core.commands:
        assert commands.split_directive([*command.name.split(), 'x'])[0] == command
        typed = command.name.split()
        assert typed[-1] in commands.next_words(typed[:-1])


def test_the_exit_code_enum_is_the_cores(core_text):
    core = catalogue.parse(json.loads(core_text))
    assert {(e.name, e.code) for e in core.exit_codes} == {(e.name, e.value) for e in ExitCode}


def test_the_docs_table_shorthand_is_read_as_written():
    assert sorted(tool._alternatives('ADD/REMOVE OBJECTPROP DOMAIN / RANGE')) == [
        'ADD OBJECTPROP DOMAIN', 'ADD OBJECTPROP RANGE', 'REMOVE OBJECTPROP DOMAIN',
        'REMOVE OBJECTPROP RANGE']
    assert tool._alternatives('LOAD FILE [MOUNTED]') == ['LOAD FILE', 'LOAD FILE MOUNTED']
    assert tool._alternatives('ADD CARDINALITY MIN (or ADD MIN CARDINALITY)') == [
        'ADD MIN CARDINALITY', 'ADD CARDINALITY MIN']
    assert tool._alternatives('MOUNT / UNMOUNT') == ['MOUNT', 'UNMOUNT']


def test_make_catalogue_gives_a_new_command_its_first_docs_row(core_text):
    core = json.loads(core_text)
    core['commands'].append({'key': 'QUERY IND COUNT', 'words': ['QUERY', 'IND', 'COUNT'],
                             'aliases': [], 'kind': 'query', 'changes_ontology': False,
                             'args': {'required': ['class'], 'optional': [], 'variadic': False},
                             'summary': 'how many instances'})
    doc = tool.COMMANDS_DOC.read_text()
    written = tool.docs_with_new_commands(doc, core)
    assert tool.documented_commands(written) - tool.documented_commands(doc) == {
        'QUERY IND COUNT'}
    queries = tool._section(written, '## Queries')
    assert ('| QUERY IND COUNT | class | how many instances | '
            '`armor call robotics QUERY IND COUNT -- class` |') in queries
    assert tool.docs_with_new_commands(doc, json.loads(core_text)) == doc


def test_a_command_added_to_the_core_changes_the_cpp_contract_header(core_text):
    core = json.loads(core_text)
    assert tool.cpp_contract_header(core_text) == tool.CPP_CONTRACT.read_text()
    core['commands'].append({'key': 'QUERY IND COUNT', 'words': ['QUERY', 'IND', 'COUNT'],
                             'aliases': [], 'kind': 'query', 'changes_ontology': False,
                             'args': {'required': ['class'], 'optional': [], 'variadic': False},
                             'summary': 'how many instances'})
    header = tool.cpp_contract_header(json.dumps(core))
    assert ('inline constexpr Command QUERY_IND_COUNT{"QUERY", "IND", "COUNT", Kind::Query, '
            '1, 0, false, false};') in header
    assert '  &QUERY_IND_COUNT,\n};' in header


def test_a_plugins_catalogue_gives_a_cpp_header_of_its_faced_commands(core_text):
    """tools/faces.py --cpp-plugins: a method per plugin face, none for a name already taken."""
    spec = importlib.util.spec_from_file_location('faces_tool', REPO / 'tools' / 'faces.py')
    faces = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(faces)
    core = json.loads(core_text)

    def plugin(key, kind, required, method, answer, *parameters):
        return {'key': key, 'words': key.split(), 'aliases': [], 'kind': kind,
                'origin': 'shop.jar', 'changes_ontology': kind == 'manipulation',
                'summary': f'does {key.lower()}',
                'args': {'required': required, 'optional': [], 'variadic': False},
                'face': {'method': method, 'answer': answer, 'parameters': [
                    {'name': n, 'type': t} for n, t in parameters]}}

    core['commands'] += [
        plugin('ADD STOCK ITEM', 'manipulation', ['ind', 'n'], 'stock', 'none',
               ('item', 'string'), ('count', 'int')),
        plugin('QUERY SHOP PLAN', 'query', ['plan path'], 'shop_plan', 'values',
               ('plan', 'string')),
        plugin('QUERY SHOP CLASH', 'query', ['class'], 'instances', 'entities', ('cls', 'string')),
        plugin('QUERY SHOP SAVE', 'query', [], 'batch', 'entities')]
    header = faces.cpp_plugin_header(core, 'shop', 'a test')
    assert ('inline constexpr Command ADD_STOCK_ITEM{\n  "ADD", "STOCK", "ITEM", '
            'Kind::Manipulation, 2, 0, false, true};') in header
    assert ('  decltype(auto) stock(const std::string & item, int count)\n'
            '  {return this->template change<contract::ADD_STOCK_ITEM>('
            'item, std::to_string(count));}'
            ) in header
    # An argument named a path is sent absolute, as by every client.
    assert ' '.join(header.split()).count(
        '.values( contract::QUERY_SHOP_PLAN, {armor::path_argument(plan)});') == 1
    # instances (a built-in face) and batch (hand-written) are the client's already.
    assert 'QUERY_SHOP_CLASH' not in header and 'QUERY_SHOP_SAVE' not in header
    assert 'namespace shop\n{' in header and 'class Reference : public armor::Reference' in header
    # The installed plugins' header is the one make catalogue wrote.
    installed = tool.installed_plugins_catalogue(tool.core_jar())
    assert faces.installed_plugins_header(installed) == faces.CPP_PLUGINS.read_text()
    assert 'pddl_problem(const std::string & mapping)' in faces.CPP_PLUGINS.read_text()
    with pytest.raises(ValueError, match='not a C.. namespace of its own'):
        faces.cpp_plugin_header(core, 'armor', 'a test')
