# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The sandbox, attacked over ROS 2 (issue 20), and imports that resolve or say why (issue 21).

Each test sends what an adversary (or an unlucky user) would send to a live node and checks
that the node answers with a clear code, reads nothing outside `allowed_dirs`, and opens no
network connection: a TCP listener started by the test must see no connection at all.

Most attacks go to the session's node (default parameters, as users run it); the SPARQL time
limit and the lenient import rule need a node of their own (`guarded`, in its own namespace).
"""

import concurrent.futures
import http.server
import json
import os
import pathlib
import re
import shlex
import shutil
import socket
import subprocess
import sys
import threading
import time
import zipfile

from armor_client import ArmorTransport, directive
from armor_contract.events import ANSWER_QOS, SUBSCRIBE_SERVICE, UNSUBSCRIBE_SERVICE
from armor_msgs.msg import ArmorAnswer
from armor_msgs.srv import ArmorSubscribe, ArmorUnsubscribe
from armor_service.node_harness import ArmorNodeProcess
from conftest import call_service, REPO, TEST_ONTOLOGIES, start_node
import pytest
from test_contract_support import answer, failure, succeeded, unique_name
from test_contract_support import load  # noqa: F401 (fixture)

pytestmark = pytest.mark.runs_for_minutes(1)

IMPORTS = TEST_ONTOLOGIES / 'imports'
SECRET_IRI = 'http://www.example.org/armor-test/secret'
SECRET_CLASS = f'<{SECRET_IRI}#TopSecret>'
MiB = 1 << 20

# Codes of this module's rules (core/.../api/ExitCode.java, docs/commands.md#exit-codes).
LOAD_FAILED, TIMEOUT, PATH_NOT_ALLOWED, WEB_LOADING_DISABLED = 209, 211, 213, 218
TOO_LARGE, IMPORTS_UNRESOLVED, FEDERATED_QUERY_DISABLED = 221, 222, 223

# Five unconstrained triple patterns: the cross join of a small ontology with itself five
# times (about 10^13 combinations); the filter needs all five, so nothing prunes it early.
CROSS_JOIN = ('SELECT (COUNT(*) AS ?n) WHERE { ?a ?b ?c . ?d ?e ?f . ?g ?h ?i . ?j ?k ?l . '
              '?m ?n2 ?o FILTER(STRLEN(CONCAT(STR(?a), STR(?d), STR(?g), STR(?j), STR(?m))) < 0) }')


class Listener:
    """A TCP server on 127.0.0.1 that records every connection it accepts (and closes it)."""

    def __init__(self):
        self._server = socket.create_server(('127.0.0.1', 0))
        self._server.settimeout(0.2)
        self.port = self._server.getsockname()[1]
        self.connections = []
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._accept, daemon=True, name='listener')
        self._thread.start()

    def _accept(self):
        while not self._stop.is_set():
            try:
                connection, peer = self._server.accept()
            except socket.timeout:
                continue
            connection.settimeout(0.5)
            try:
                first = connection.recv(200)
            except OSError:
                first = b''
            self.connections.append((peer, first))
            connection.close()

    def close(self):
        self._stop.set()
        self._thread.join()
        self._server.close()


@pytest.fixture(scope='module')
def listener():
    server = Listener()
    yield server
    server.close()


@pytest.fixture
def no_connection(listener):
    """The listener; at the end of the test it must have seen no connection."""
    seen = len(listener.connections)
    yield listener
    assert listener.connections[seen:] == [], 'the core opened a network connection'


@pytest.fixture(scope='module')
def outside(tmp_path_factory):
    """A directory outside every allowed directory, holding a secret in several forms."""
    directory = tmp_path_factory.mktemp('outside')
    secret = functional(SECRET_IRI, body=f'Declaration(Class({SECRET_CLASS}))\n'
                        f'ClassAssertion({SECRET_CLASS} <{SECRET_IRI}#launchCode>)')
    (directory / 'secret.owl').write_text(secret)
    with zipfile.ZipFile(directory / 'secret.jar', 'w') as jar:
        jar.writestr('secret.owl', secret)
    (directory / 'secret.txt').write_text('the launch code is 0000\n')
    return directory


def functional(ontology_iri, imports=(), body=''):
    """An ontology document in OWL functional syntax."""
    lines = [f'Ontology(<{ontology_iri}>']
    lines += [f'Import(<{imported}>)' for imported in imports]
    lines += [body, ')', '']
    return '\n'.join(lines)


def importer(folder: pathlib.Path, *imports: str) -> pathlib.Path:
    """A new ontology file in folder whose only content is the given imports."""
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f'{unique_name("importer")}.owl'
    path.write_text(functional(f'http://www.example.org/armor-test/{path.stem}', imports,
                               'Declaration(Class(<http://www.example.org/armor-test/A>))'))
    return path


def load_fails(call, path, code):
    name = unique_name('attack')
    response = failure(call, name, 'LOAD FILE', str(path), '', 'false', 'HERMIT', 'false',
                       code=code)
    assert name not in answer(call, '', 'GET ALL REFS'), 'a refused LOAD left a reference'
    return response


# --- issue 20.1: owl:imports stay inside allowed_dirs -----------------------------------------

@pytest.mark.parametrize('target', [
    'file://{outside}/secret.owl',
    'file:{outside}/secret.owl',
    'jar:file://{outside}/secret.jar!/secret.owl',
])
def test_an_import_of_a_file_outside_allowed_dirs_is_213(call, armor_node, outside, target):
    imported = target.format(outside=outside)
    response = load_fails(call, importer(armor_node.scratch, imported), PATH_NOT_ALLOWED)
    assert imported in response.error_description
    assert 'allowed_dirs' in response.error_description


def test_a_catalog_entry_outside_allowed_dirs_is_213(call, armor_node, outside):
    folder = armor_node.scratch / unique_name('catalogued')
    path = importer(folder, SECRET_IRI)
    relative = os.path.relpath(outside / 'secret.owl', folder)
    (folder / 'catalog-v001.xml').write_text(
        '<catalog xmlns="urn:oasis:names:tc:entity:xmlns:xml:catalog">'
        f'<uri name="{SECRET_IRI}" uri="{relative}"/></catalog>')
    response = load_fails(call, path, PATH_NOT_ALLOWED)
    assert SECRET_IRI in response.error_description


def test_a_symlink_beside_the_importing_file_is_never_read(call, armor_node, outside):
    folder = armor_node.scratch / unique_name('linked')
    path = importer(folder, SECRET_IRI)
    os.symlink(outside / 'secret.owl', folder / 'secret.owl')
    response = load_fails(call, path, IMPORTS_UNRESOLVED)
    assert SECRET_IRI in response.error_description


def test_a_refused_import_is_refused_by_the_lenient_rule_too(guarded_call, guarded, outside):
    path = importer(guarded.scratch, f'file://{outside}/secret.owl')
    load_fails(guarded_call, path, PATH_NOT_ALLOWED)


# --- issue 20.2: no network connection with web_loading off -----------------------------------

@pytest.mark.parametrize('template', [
    'http://127.0.0.1:{port}/tbox.owl',
    'https://127.0.0.1:{port}/tbox.owl',
    'ftp://127.0.0.1:{port}/tbox.owl',
    'jar:http://127.0.0.1:{port}/tbox.jar!/tbox.owl',
    'jar:https://127.0.0.1:{port}/tbox.jar!/tbox.owl',
])
def test_an_import_over_any_scheme_opens_no_connection(call, armor_node, no_connection,
                                                       template):
    imported = template.format(port=no_connection.port)
    response = load_fails(call, importer(armor_node.scratch, imported), IMPORTS_UNRESOLVED)
    assert imported in response.error_description
    assert 'web_loading' in response.error_description


def test_load_web_opens_no_connection(call, no_connection):
    load_fails_web = failure(call, unique_name('web'), 'LOAD WEB',
                             f'http://127.0.0.1:{no_connection.port}/robotics.owl', '', 'false',
                             'HERMIT', 'false', code=WEB_LOADING_DISABLED)
    assert 'web_loading' in load_fails_web.error_description


@pytest.mark.parametrize('query', [
    'SELECT * WHERE {{ SERVICE <http://127.0.0.1:{port}/sparql> {{ ?s ?p ?o }} }}',
    'SELECT * WHERE {{ SERVICE SILENT <http://127.0.0.1:{port}/sparql> {{ ?s ?p ?o }} }}',
    'SELECT * WHERE {{ ?s a ?t OPTIONAL {{ SERVICE SILENT <http://127.0.0.1:{port}/q> '
    '{{ ?s ?p ?o }} }} }}',
    'SELECT * WHERE {{ {{ SELECT ?s WHERE {{ SERVICE <http://127.0.0.1:{port}/q> {{ ?s ?p ?o }} '
    '}} }} }}',
    'ASK {{ ?s ?p ?o FILTER EXISTS {{ SERVICE SILENT <http://127.0.0.1:{port}/q> {{ ?s ?p ?o }} '
    '}} }}',
    'SELECT * WHERE {{ BIND(<http://127.0.0.1:{port}/q> AS ?endpoint) SERVICE ?endpoint '
    '{{ ?s ?p ?o }} }}',
])
def test_sparql_service_is_refused_without_a_connection(call, load, no_connection, query):
    reference = load()
    for words in ('QUERY SPARQL', 'QUERY SPARQL FORMATTED'):
        response = failure(call, reference, words, query.format(port=no_connection.port),
                           code=FEDERATED_QUERY_DISABLED)
        assert 'SERVICE' in response.error_description
        assert 'sparql_federated' in response.error_description


def test_an_import_inside_an_axiom_is_208_and_never_fetched(call, load, no_connection, outside):
    reference = load()
    response = failure(call, reference, 'ADD AXIOM',
                       f'Import(<http://127.0.0.1:{no_connection.port}/x.owl>) '
                       f'Import(<file://{outside}/secret.owl>) SubClassOf(:Robot :Agent)', code=208)
    assert 'Import' in response.error_description


def test_external_entities_are_never_fetched(call, armor_node, load, no_connection, outside):
    document = armor_node.scratch / f'{unique_name("xxe")}.owl'
    document.write_text(f'''<?xml version="1.0"?>
<!DOCTYPE rdf:RDF [
  <!ENTITY remote SYSTEM "http://127.0.0.1:{no_connection.port}/entity">
  <!ENTITY secret SYSTEM "file://{outside}/secret.txt">
]>
<rdf:RDF xmlns:owl="http://www.w3.org/2002/07/owl#"
     xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#"
     xmlns:rdfs="http://www.w3.org/2000/01/rdf-schema#">
  <owl:Ontology rdf:about="http://www.example.org/armor-test/xxe"/>
  <owl:Class rdf:about="http://www.example.org/armor-test/xxe#A">
    <rdfs:label>&remote;</rdfs:label>
    <rdfs:comment>&secret;</rdfs:comment>
  </owl:Class>
</rdf:RDF>
''')
    name = unique_name('xxe')
    response = call(name, 'LOAD FILE', str(document), '', 'false', 'HERMIT', 'false')
    if response.success:
        try:
            values = answer(call, name, 'QUERY SPARQL',
                            'SELECT ?v WHERE { ?s ?p ?v FILTER(isLiteral(?v)) }')
            assert not any('launch code' in value for value in values), values
        finally:
            call(name, 'DROP')


# --- issue 20.3 / 20.4: LOG FILE ON takes only a regular file, confined ------------------------

def test_log_file_on_a_fifo_is_refused_and_freezes_nothing(call, armor_node, load):
    reference = load()
    fifo = armor_node.scratch / f'{unique_name("log")}.fifo'
    os.mkfifo(fifo)
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=1)
    logging_on = pool.submit(call, '', 'LOG FILE ON', str(fifo), timeout_s=120)
    try:
        deadline = time.monotonic() + 3
        while not logging_on.done() and time.monotonic() < deadline:
            time.sleep(0.05)
        # With the old lock, this query waited until a reader opened the FIFO.
        assert answer(call, reference, 'QUERY IND CLASS', 'Robot', timeout_s=30) != []
        response = logging_on.result(timeout=30)
        assert not response.success and response.exit_code == LOAD_FAILED, response
        assert 'regular file' in response.error_description
    finally:
        # Releases a core stuck in open() (the bug), then leaves logging off.
        reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)
        try:
            logging_on.result(timeout=60)
        finally:
            os.close(reader)
            pool.shutdown()
            call('', 'LOG FILE OFF')


def test_log_file_on_a_directory_is_refused(call, armor_node):
    folder = armor_node.scratch / unique_name('folder')
    folder.mkdir()
    failure(call, '', 'LOG FILE ON', str(folder), code=LOAD_FAILED)


def test_log_file_on_a_dangling_symlink_to_outside_is_213(call, armor_node, outside):
    target = outside / f'{unique_name("created")}.log'
    link = armor_node.scratch / f'{unique_name("dangling")}.log'
    os.symlink(target, link)
    response = failure(call, '', 'LOG FILE ON', str(link), code=PATH_NOT_ALLOWED)
    assert 'write_dirs' in response.error_description
    chain = armor_node.scratch / f'{unique_name("chain")}.log'
    os.symlink(link, chain)
    failure(call, '', 'LOG FILE ON', str(chain), code=PATH_NOT_ALLOWED)
    directory_link = armor_node.scratch / unique_name('outside_dir')
    os.symlink(outside, directory_link)
    failure(call, '', 'LOG FILE ON', str(directory_link / 'x.log'), code=PATH_NOT_ALLOWED)
    assert not target.exists() and not (outside / 'x.log').exists()


def test_log_file_records_directives_and_stops(call, armor_node, load):
    reference = load()
    log = armor_node.scratch / f'{unique_name("directives")}.log'
    succeeded(call, '', 'LOG FILE ON', str(log))
    try:
        succeeded(call, reference, 'QUERY IND CLASS', 'Robot')
        deadline = time.monotonic() + 30
        while 'QUERY IND CLASS' not in (log.read_text() if log.exists() else ''):
            assert time.monotonic() < deadline, 'no line reached the log file'
            time.sleep(0.05)
    finally:
        succeeded(call, '', 'LOG FILE OFF')


# --- issue 20.5: SPARQL has a time limit and evaluates outside the reference lock --------------

@pytest.fixture(scope='module')
def guarded(tmp_path_factory):
    """A node of its own: a 3 s default SPARQL limit, lenient imports.

    Lock waits stay at their default: a query that held the reference would show as no change
    answered while it ran, and a short wait only made a write behind another write's
    reasoning on a loaded machine fail.
    """
    node = start_node(tmp_path_factory.mktemp('guarded'), '-p', 'sparql_timeout_ms:=3000',
                      '-p', 'ignore_missing_imports:=true', namespace='/guarded')
    yield node
    node.stop()


@pytest.fixture(scope='module')
def guarded_transport(guarded):
    transport = ArmorTransport(namespace='/guarded', service_wait_s=120.0)
    yield transport
    transport.close()


@pytest.fixture
def guarded_call(guarded_transport):
    def send(reference, words, *args, client='test', timeout_s=120):
        command, primary, secondary = (words.split() + ['', '', ''])[:3]
        return guarded_transport.call(directive(client, reference, command, primary, secondary,
                                                args), timeout_s=timeout_s)
    return send


def test_a_cross_join_stops_at_the_default_limit_and_locks_nothing(guarded_call):
    reference = 'robotics'
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=1)
    started = time.monotonic()
    query = pool.submit(guarded_call, reference, 'QUERY SPARQL', CROSS_JOIN, timeout_s=120)
    writes_during_query = 0
    try:
        while not query.done():
            individual = unique_name('visitor')
            response = guarded_call(reference, 'ADD IND CLASS', individual, 'Person',
                                    timeout_s=60)
            assert response.success, f'{response.exit_code} {response.error_description}'
            writes_during_query += not query.done()
            guarded_call(reference, 'REMOVE IND', individual)
        response = query.result()
    finally:
        pool.shutdown()
    assert response.success and response.timeout, (response.exit_code,
                                                    response.error_description)
    assert time.monotonic() - started < 60
    assert writes_during_query > 0, 'no change was answered while the query ran'


def test_rows_found_before_the_limit_are_answered(guarded_call):
    query = ('SELECT ?x WHERE { { ?x a <http://www.example.org/robotics#Robot> } UNION '
             + CROSS_JOIN.split('WHERE', 1)[1] + ' }')
    response = guarded_call('robotics', 'QUERY SPARQL', query, '1000')
    assert response.success and response.timeout, response.error_description
    assert '<http://www.example.org/robotics#robot1>' in list(response.queried_objects)


# --- issue 20.7: size limits, refused before any work -----------------------------------------

def _journal_bytes(node) -> int:
    return sum(path.stat().st_size for path in (node.scratch / 'state').rglob('*')
               if path.is_file())


def test_a_50_mb_name_is_221_and_never_journaled(call, armor_node, load):
    reference = load()
    before = _journal_bytes(armor_node)
    response = failure(call, reference, 'ADD IND CLASS', 'x' * (50 * MiB), 'Robot',
                       code=TOO_LARGE)
    assert 'argument 0' in response.error_description
    assert len(response.error_description) < 1000
    assert _journal_bytes(armor_node) - before < 4096
    assert answer(call, reference, 'QUERY IND CLASS', 'Robot') != []


def test_a_50_mb_query_text_is_221(call, load):
    reference = load()
    query = 'SELECT * WHERE { ?s ?p ?o } #' + 'x' * (50 * MiB)
    failure(call, reference, 'QUERY SPARQL', query, code=TOO_LARGE)


def test_limits_per_argument_directive_name_and_list(call, armor, load):
    reference = load()
    # Just inside the argument limit: an (unknown) class name of almost 1 MiB is answered.
    assert answer(call, reference, 'QUERY IND CLASS', 'C' * (MiB - 64)) == []
    failure(call, reference, 'QUERY IND CLASS', 'C' * (MiB + 1), code=TOO_LARGE)
    # Five arguments of 0.9 MiB each: every one is fine, the directive (4 MiB) is not.
    names = [f'{i}' + 'n' * (9 * MiB // 10) for i in range(5)]
    response = failure(call, reference, 'DISJOINT IND', *names, code=TOO_LARGE)
    assert 'directive' in response.error_description
    response = failure(call, reference, 'QUERY IND CLASS', 'Robot', code=TOO_LARGE,
                       client='c' * 2000)
    assert 'client_name' in response.error_description

    def refused_list(requests):
        result = armor.call_list(requests, timeout_s=300)
        assert not result.success
        assert len(result.armor_responses) == len(requests)
        assert {r.exit_code for r in result.armor_responses} == {TOO_LARGE}
        return result

    refused_list([directive('test', reference, 'QUERY', 'IND', 'CLASS', ['Robot'])] * 10_001)
    big = 'y' * (3 * MiB)
    refused_list([directive('test', reference, 'ADD', 'IND', 'CLASS', [big + str(i), 'Robot'])
                  for i in range(3)])
    assert answer(call, reference, 'QUERY IND CLASS', 'Robot') == [
        '<http://www.example.org/robotics#robot1>']


# --- issue 21.2 / 21.3: imports resolve beside the file or through a catalog, or say why -------

@pytest.mark.parametrize('document, question, individual', [
    # Functional syntax importing a functional-syntax neighbour (the SOMA.owl / DUL.owl case).
    ('functional/tasks.owl', 'upper#Event', 'tasks#goToKitchen'),
    # RDF/XML importing a neighbour that declares its IRI with rdf:about only (no xml:base).
    ('rdfxml/site.owl', 'map#Location', 'site#lab'),
    # Turtle whose import catalog-v001.xml maps to a document in a subfolder.
    ('catalog/robot-tasks.ttl', 'vendor#Gripper', 'robot-tasks#gripper1'),
])
def test_imports_resolve_beside_the_file_or_through_its_catalog(call, load, document, question,
                                                                  individual):
    reference = load(path=IMPORTS / document)
    assert answer(call, reference, 'QUERY IND CLASS',
                  f'<http://www.example.org/armor-test/{question}>') == [
        f'<http://www.example.org/armor-test/{individual}>']


def test_an_unresolved_web_import_is_222_naming_it_and_why(call):
    response = load_fails(call, IMPORTS / 'web-only' / 'students.owl', IMPORTS_UNRESOLVED)
    assert 'http://www.example.org/armor-test/university.owl' in response.error_description
    assert 'web_loading' in response.error_description
    assert 'ignore_missing_imports' in response.error_description


def test_the_lenient_rule_loads_and_lists_the_unresolved_imports(guarded_call):
    name = unique_name('students')
    response = guarded_call(name, 'LOAD FILE', str(IMPORTS / 'web-only' / 'students.owl'), '',
                            'false', 'HERMIT', 'false')
    try:
        assert response.success and response.exit_code == 0, response.error_description
        assert 'http://www.example.org/armor-test/university.owl' in response.error_description
    finally:
        guarded_call(name, 'DROP')


# --- issue 11.5: a file that is no ontology says so -------------------------------------------

def test_a_file_that_is_no_ontology_says_so_and_which_syntaxes_were_tried(call, armor_node):
    notes = armor_node.scratch / f'{unique_name("notes")}.owl'
    notes.write_text('shopping list: milk, bread\n')
    response = load_fails(call, notes, LOAD_FAILED)
    description = response.error_description
    assert 'not an ontology in any supported syntax' in description
    for syntax in ('RDF/XML', 'OWL/XML', 'Functional', 'Turtle', 'Manchester'):
        assert syntax in description, description
    for internal in ('HDT', 'RioParserImpl', 'org.eclipse', 'Exception'):
        assert internal not in description, description


# --- issue 27: what a client may write, on a node started as `make run` starts it --------------
#
# `exposed`: default parameters (no allowed_dirs, write_dirs or state_dir given), the checkout as
# its working directory, as `make run`, but a throwaway home: every attack below aims at that
# home's dotfiles, the checkout's code and virtual environment, and the node's own state.

EXPOSED = '/exposed'
ROBOTICS_FILE = REPO / 'ontologies' / 'robotics.owl'
ROBOTICS_MAPPING = REPO / 'examples' / 'pddl' / 'robotics-mapping.yaml'
# A literal whose lines a shell or Python would run, were it written where they look.
PAYLOAD = '\n$(touch {home}/pwned)\nimport sys\nssh-ed25519 AAAAC3NzaC1lZDI1NTE5AAAAIO attacker\n'


@pytest.fixture(scope='module')
def exposed(tmp_path_factory):
    home = tmp_path_factory.mktemp('home')
    environment = {**os.environ, 'HOME': str(home)}
    environment.pop('XDG_DATA_HOME', None)
    node = ArmorNodeProcess(tmp_path_factory.mktemp('exposed_log') / 'armor_service.log', [
        '-p', f'preload_file:={ROBOTICS_FILE}', '-p', 'preload_reference:=robotics',
        '-p', "state_dir:=''", '-r', f'__ns:={EXPOSED}'], cwd=REPO, env=environment)
    transport = ArmorTransport(namespace=EXPOSED, service_wait_s=120.0)
    node.home = home
    node.transport = transport
    try:
        assert transport.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=180).success, \
            node.log()
        yield node
    finally:
        transport.close()
        node.stop()


@pytest.fixture
def exposed_call(exposed):
    def send(reference, words, *args, client='attacker', timeout_s=120):
        command, primary, secondary = (words.split() + ['', '', ''])[:3]
        return exposed.transport.call(directive(client, reference, command, primary, secondary,
                                                args), timeout_s=timeout_s)
    return send


@pytest.fixture
def poisoned(exposed, exposed_call):
    """A reference whose one literal holds a shell command, a Python line and an SSH key."""
    name = unique_name('poisoned')
    succeeded(exposed_call, name, 'LOAD FILE', str(ROBOTICS_FILE), '', 'false', 'PELLET', 'false')
    succeeded(exposed_call, name, 'ADD DATAPROP IND', 'note', 'robot1', 'STRING',
              PAYLOAD.format(home=exposed.home))
    yield name
    exposed_call(name, 'DROP')


def state_dir_of(node) -> pathlib.Path:
    """The default state directory of the exposed node (one per domain and node name)."""
    return (node.home / '.local' / 'share' / 'armor_ros2' / f'domain{os.environ["ROS_DOMAIN_ID"]}'
            / 'exposed__armor_service')


def refused_write(call, reference, words, *args, target: pathlib.Path):
    """A write that must be 213 and leave no file (nor a folder it would have made)."""
    existed = target.exists()
    before = target.read_bytes() if existed and target.is_file() else None
    try:
        response = failure(call, reference, words, *args, code=PATH_NOT_ALLOWED)
    finally:
        if not existed and target.is_file():
            target.unlink()  # on a broken build: never leave a planted file behind
    assert 'write_dirs' in response.error_description, response.error_description
    if existed:
        assert target.is_file() and target.read_bytes() == before
    else:
        assert not target.exists()
    return response


@pytest.mark.parametrize('words, relative, file_format', [
    ('SAVE', '.bashrc', 'turtle'),
    ('SAVE', '.profile', 'turtle'),
    ('SAVE', '.ssh/authorized_keys', 'rdfxml'),
    ('SAVE INFERENCE', '.bashrc', 'turtle'),
    ('SAVE INFERENCE', '.config/autostart/armor.desktop', 'turtle'),
])
def test_save_into_the_users_dotfiles_is_213(exposed, exposed_call, poisoned, words, relative,
                                             file_format):
    target = exposed.home / relative
    refused_write(exposed_call, poisoned, words, str(target), file_format, target=target)
    assert not (exposed.home / '.ssh').exists() and not (exposed.home / '.config').exists()
    assert not (exposed.home / 'pwned').exists()


def test_save_pddl_problem_into_a_dotfile_is_213(exposed, exposed_call, poisoned):
    target = exposed.home / '.bashrc'
    refused_write(exposed_call, poisoned, 'SAVE PDDL PROBLEM', str(ROBOTICS_MAPPING), str(target),
                  target=target)


def test_log_file_on_a_dotfile_is_213(exposed, exposed_call):
    target = exposed.home / '.bashrc'
    refused_write(exposed_call, '', 'LOG FILE ON', str(target), target=target)


def code_and_state_targets(node) -> dict:
    venv = pathlib.Path(sys.prefix)
    site_packages = next(venv.glob('lib/python3*/site-packages'))
    plugin_dir = pathlib.Path(os.environ['ARMOR_PLUGIN_DIRS'].split(os.pathsep)[0])
    return {
        'a .pth file in the virtual environment': site_packages / f'{unique_name("armor")}.pth',
        'a module of the checkout': REPO / 'armor_service' / 'armor_service' / 'planted.py',
        'the core installation': pathlib.Path(os.environ['ARMOR_CORE_JAR']).parent / 'planted.owl',
        'a plugin directory': plugin_dir / 'planted.owl',
        'the home directory itself': node.home / 'planted.owl',
        'the working directory itself': REPO / 'planted.owl',
        'the temporary directory as a whole': pathlib.Path('/tmp') / f'{unique_name("planted")}.owl',
        'a new folder in the home directory': node.home / unique_name('made') / 'planted.owl',
        'the state directory': state_dir_of(node) / 'planted.owl',
    }


@pytest.mark.parametrize('what', ['a .pth file in the virtual environment', 'a module of the checkout',
                                  'the core installation', 'a plugin directory',
                                  'the home directory itself', 'the working directory itself',
                                  'the temporary directory as a whole',
                                  'a new folder in the home directory', 'the state directory'])
def test_code_the_installation_and_shared_folders_are_never_written(exposed, exposed_call,
                                                                     poisoned, what):
    target = code_and_state_targets(exposed)[what]
    refused_write(exposed_call, poisoned, 'SAVE', str(target), 'turtle', target=target)
    refused_write(exposed_call, '', 'LOG FILE ON', str(target), target=target)
    if what == 'a new folder in the home directory':
        made = target.parent.exists()
        if made:
            target.parent.rmdir()
        assert not made, 'SAVE made a folder outside the write folders'


def test_the_state_directory_is_neither_read_nor_written(exposed, exposed_call):
    state = state_dir_of(exposed)
    meta = next(state.rglob('meta.json'))
    checkpoint = next(path for path in state.rglob('*') if path.is_file()
                      and path.suffix in ('.ofn', '.owl'))
    refused_write(exposed_call, 'robotics', 'SAVE', str(meta), 'turtle', target=meta)
    refused_write(exposed_call, 'robotics', 'SAVE', str(checkpoint), target=checkpoint)
    failure(exposed_call, unique_name('stolen'), 'LOAD FILE', str(checkpoint), '', 'false',
            'HERMIT', 'false', code=PATH_NOT_ALLOWED)
    failure(exposed_call, 'robotics', 'QUERY PDDL PROBLEM', str(meta), code=PATH_NOT_ALLOWED)


def test_symbolic_links_in_the_write_folder_lead_nowhere_else(exposed, exposed_call, poisoned):
    folder = exposed.home / 'armor_files'
    succeeded(exposed_call, poisoned, 'SAVE', str(folder / 'first.owl'))
    links = {
        folder / 'to_bashrc': exposed.home / '.bashrc',
        folder / 'to_home': exposed.home,
        folder / 'to_code': REPO / 'armor_service',
    }
    for link, target in links.items():
        os.symlink(target, link)
    try:
        refused_write(exposed_call, poisoned, 'SAVE', str(folder / 'to_bashrc'),
                      target=exposed.home / '.bashrc')
        refused_write(exposed_call, poisoned, 'SAVE', str(folder / 'to_home' / 'x.owl'),
                      target=exposed.home / 'x.owl')
        refused_write(exposed_call, poisoned, 'SAVE', str(folder / 'to_code' / 'planted.py'),
                      target=REPO / 'armor_service' / 'planted.py')
    finally:
        for link in links:
            link.unlink()


def test_the_armor_folder_is_private_and_takes_the_documented_writes(exposed, exposed_call,
                                                                      poisoned):
    folder = exposed.home / 'armor_files'
    succeeded(exposed_call, poisoned, 'SAVE', str(folder / 'maps' / 'today' / 'robotics.ttl'),
              'turtle')
    assert (folder / 'maps' / 'today' / 'robotics.ttl').read_text().startswith('@')
    assert folder.stat().st_mode & 0o777 == 0o700


def test_a_log_line_is_one_line_whatever_the_directive_holds(exposed, exposed_call):
    log = exposed.home / 'armor_files' / f'{unique_name("directives")}.log'
    succeeded(exposed_call, '', 'LOG FILE ON', str(log))
    try:
        # Refused (no such reference), and logged all the same.
        exposed_call('nowhere', 'ADD IND CLASS', 'x\n$(touch /tmp/pwned)\r\x1b[2K', 'Robot')
        exposed_call('nowhere', 'QUERY IND CLASS', 'Robot', client='after\nclient')
    finally:
        succeeded(exposed_call, '', 'LOG FILE OFF')
    lines = log.read_text().splitlines()
    # LOG FILE ON and the two directives, one line each (LOG FILE OFF closed the file first).
    assert len(lines) == 3 and all(' -> ' in line for line in lines), lines
    assert '$(touch /tmp/pwned)' in lines[1] and '\\n' in lines[1] and '\x1b' not in lines[1]
    assert '[after\\nclient]' in lines[2], lines[2]


# --- issue 27.5: limits consistent from the core to the node ----------------------------------

FRAME_BYTES = 256 * MiB  # the node-core frame limit (armor_service/wire.py, CoreServer.java)


def test_a_list_whose_answers_outgrow_a_frame_is_221_and_the_core_stays(call, armor, armor_node,
                                                                        load):
    reference = load()
    succeeded(call, reference, 'ADD DATAPROP IND', 'note', 'robot1', 'STRING', 'x' * 1_000_000)
    # 30 rows of a 1 MB literal: each answer stays under its own 32 MiB limit...
    rows = ' '.join(str(i) for i in range(30))
    query = ('SELECT ?v ?n WHERE { ?s <http://www.example.org/robotics#note> ?v '
             f'VALUES ?n {{ {rows} }} }}')
    single = succeeded(call, reference, 'QUERY SPARQL', query)
    one_answer = sum(len(row) for row in single.queried_objects)
    assert 30_000_000 < one_answer < 32 * MiB
    # ... and ten of them in one list come to more than a frame carries.
    count = FRAME_BYTES // one_answer + 2
    core = armor_node.core_pid()
    result = armor.call_list([directive('test', reference, 'QUERY', 'SPARQL', '', [query])] * count,
                             timeout_s=600)
    codes = {r.exit_code for r in result.armor_responses}
    assert not result.success and codes == {TOO_LARGE}, codes
    assert any(f'{FRAME_BYTES:,}' in r.error_description for r in result.armor_responses), \
        result.armor_responses[0].error_description
    assert armor_node.core_pid() == core, 'the node dropped the core'
    assert answer(call, reference, 'QUERY IND CLASS', 'Robot') == [
        '<http://www.example.org/robotics#robot1>']


# --- issue 27.9: what one client may hold -----------------------------------------------------

CLIENT_LIMIT = 226
# The defaults of subscriptions_per_client and references_per_client (README's parameter table).
SUBSCRIPTIONS_PER_CLIENT = REFERENCES_PER_CLIENT = 100


class Subscriptions:
    """armor_subscribe / armor_unsubscribe with plain rclpy, keeping each answer topic read."""

    def __init__(self, node):
        self._node = node
        self._subscribe = node.create_client(ArmorSubscribe, SUBSCRIBE_SERVICE)
        self._unsubscribe = node.create_client(ArmorUnsubscribe, UNSUBSCRIBE_SERVICE)
        assert self._subscribe.wait_for_service(timeout_sec=60)
        self.live = []
        self._readers = []

    @staticmethod
    def _call(client, request, timeout_s=120.0):
        return call_service(client, request, timeout_s)

    def subscribe(self, client, reference, *words):
        command, primary, secondary, *args = words
        response = self._call(self._subscribe, ArmorSubscribe.Request(armor_request=directive(
            client, reference, command, primary, secondary, args)))
        if response.success:
            self.live.append(response.subscription_id)
            # A topic with a reader keeps its subscription alive (subscription_idle_s).
            self._readers.append(self._node.create_subscription(
                ArmorAnswer, response.topic, lambda message: None, ANSWER_QOS))
        return response

    def close(self):
        for subscription_id in self.live:
            self._call(self._unsubscribe, ArmorUnsubscribe.Request(subscription_id=subscription_id))
        for reader in self._readers:
            self._node.destroy_subscription(reader)


def test_one_client_holds_at_most_its_share_of_subscriptions(armor, load):
    reference = load()
    subscriptions = Subscriptions(armor.node)
    try:
        for _ in range(SUBSCRIPTIONS_PER_CLIENT):
            response = subscriptions.subscribe('flooder', reference, 'QUERY', 'IND', 'CLASS',
                                               'Robot')
            assert response.success, response.error_description
        refused = subscriptions.subscribe('flooder', reference, 'QUERY', 'IND', 'CLASS', 'Robot')
        assert not refused.success and refused.exit_code == CLIENT_LIMIT, refused
        assert 'subscriptions_per_client' in refused.error_description
        assert 'flooder' in refused.error_description
        other = subscriptions.subscribe('neighbour', reference, 'QUERY', 'IND', 'CLASS', 'Robot')
        assert other.success, other.error_description
    finally:
        subscriptions.close()


def test_one_client_holds_at_most_its_share_of_references(call):
    made = []
    try:
        for _ in range(REFERENCES_PER_CLIENT):
            name = unique_name('flood')
            succeeded(call, name, 'CREATE', '', 'false', 'HERMIT', 'false', client='flooder')
            made.append(name)
        response = failure(call, unique_name('flood'), 'CREATE', '', 'false', 'HERMIT', 'false',
                           client='flooder', code=CLIENT_LIMIT)
        assert 'references_per_client' in response.error_description
        failure(call, unique_name('flood'), 'LOAD FILE', str(ROBOTICS_FILE), '', 'false', 'HERMIT',
                'false', client='flooder', code=CLIENT_LIMIT)
        # Another client is not held back, and a DROP gives the flooder room again.
        other = unique_name('neighbour')
        succeeded(call, other, 'CREATE', '', 'false', 'HERMIT', 'false', client='neighbour')
        made.append(other)
        succeeded(call, made.pop(0), 'DROP', client='flooder')
        again = unique_name('flood')
        succeeded(call, again, 'CREATE', '', 'false', 'HERMIT', 'false', client='flooder')
        made.append(again)
    finally:
        for name in made:
            call(name, 'DROP')


def test_get_ref_changes_answers_a_bounded_page_and_where_to_go_on(call, load):
    reference = load()
    # Three changes of 600 KB each: more text than one answer carries.
    for i in range(3):
        succeeded(call, reference, 'ADD DATAPROP IND', 'note', 'robot1', 'STRING',
                  str(i) * 600_000)
    revisions, since = [], 0
    for _ in range(3):
        page = succeeded(call, reference, 'GET REF CHANGES', reference, str(since))
        assert 0 < len(page.queried_objects) < 3, len(page.queried_objects)
        revisions += [json.loads(text)['revision'] for text in page.queried_objects]
        if not page.error_description:
            break
        since = revisions[-1]
        assert f'more changes after revision {since}' in page.error_description, \
            page.error_description
    assert revisions == [1, 2, 3]


# --- issue 34.4: the rules of docs/security.md, attacked live -----------------------------------

@pytest.fixture(scope='module')
def web_loading(tmp_path_factory):
    """A node that loads from the web, and a local web server whose redirects try to leave it."""
    scratch = tmp_path_factory.mktemp('web_loading')
    node = start_node(scratch, '-p', 'web_loading:=true', namespace='/web_loading')
    transport = ArmorTransport(namespace='/web_loading', service_wait_s=120.0)
    yield scratch, transport
    transport.close()
    node.stop()


class Redirects(http.server.BaseHTTPRequestHandler):
    """/upper.owl: an ontology; /moved.owl: redirected to it; /steal.owl: redirected to a file."""

    secret = ''

    def do_GET(self):  # noqa: N802 (the standard library's name)
        base = f'http://127.0.0.1:{self.server.server_address[1]}'
        if self.path == '/upper.owl':
            body = functional(f'{base}/upper.owl', body=f'Declaration(Class(<{base}/upper#Task>))')
            self.send_response(200)
            self.send_header('Content-Type', 'text/owl-functional')
            self.end_headers()
            self.wfile.write(body.encode())
            return
        self.send_response(302)
        self.send_header('Location', f'{base}/upper.owl' if self.path == '/moved.owl'
                         else self.secret)
        self.end_headers()

    def log_message(self, *args):
        pass


def test_a_web_redirect_to_a_local_file_is_213_and_one_to_the_web_is_followed(web_loading,
                                                                             outside):
    scratch, transport = web_loading
    Redirects.secret = (outside / 'secret.owl').as_uri()
    server = http.server.ThreadingHTTPServer(('127.0.0.1', 0), Redirects)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    base = f'http://127.0.0.1:{server.server_address[1]}'

    def send(reference, words, *args):
        command, primary, secondary = (words.split() + ['', '', ''])[:3]
        return transport.call(directive('test', reference, command, primary, secondary, args),
                              timeout_s=120)
    try:
        moved = unique_name('moved')
        assert send(moved, 'LOAD WEB', f'{base}/moved.owl', '', 'false', 'HERMIT',
                    'false').success
        send(moved, 'DROP')
        stolen = send(unique_name('stolen'), 'LOAD WEB', f'{base}/steal.owl', '', 'false',
                      'HERMIT', 'false')
        assert stolen.exit_code == PATH_NOT_ALLOWED, stolen
        imported = send(unique_name('stolen'), 'LOAD FILE',
                        str(importer(scratch, f'{base}/steal.owl')), '', 'false', 'HERMIT', 'false')
        assert imported.exit_code == PATH_NOT_ALLOWED, imported
        assert SECRET_IRI not in send('', 'GET ALL REFS').queried_objects
    finally:
        server.shutdown()


ALIAS_BOMB = 'domain: d\na: &a ["x","x","x","x","x","x","x","x","x"]\n' + ''.join(
    f'{chr(98 + i)}: &{chr(98 + i)} [*{chr(97 + i)},*{chr(97 + i)},*{chr(97 + i)},*{chr(97 + i)},'
    f'*{chr(97 + i)},*{chr(97 + i)},*{chr(97 + i)},*{chr(97 + i)},*{chr(97 + i)}]\n'
    for i in range(8))


@pytest.mark.parametrize('mapping, code, says', [
    # A tag that would build a Java object.
    ('domain: d\ngoal: !!javax.script.ScriptEngineManager [!!java.net.URLClassLoader '
     '[[!!java.net.URL ["http://127.0.0.1:9/"]]]]\n', 208, 'tag'),
    # Nine times nine times ... aliases: a billion strings from a few hundred bytes.
    (ALIAS_BOMB, 208, 'aliases'),
    # Nesting far deeper than any mapping.
    ('domain: d\ngoal: ' + '[' * 200 + ']' * 200 + '\n', 208, 'nesting'),
])
def test_a_hostile_pddl_mapping_is_refused_before_it_is_built(call, no_connection, mapping, code,
                                                              says):
    started = time.monotonic()
    response = failure(call, 'robotics', 'QUERY PDDL PROBLEM', mapping, code=code)
    assert says in response.error_description.lower(), response.error_description
    assert time.monotonic() - started < 30


def test_a_pddl_mapping_file_over_its_size_limit_is_221(call, armor_node):
    mapping = armor_node.scratch / f'{unique_name("huge")}.yaml'
    mapping.write_text('domain: d\n' + ''.join(f'# {i:0>100}\n' for i in range(11_000)))
    assert mapping.stat().st_size > MiB
    response = failure(call, 'robotics', 'QUERY PDDL PROBLEM', str(mapping), code=TOO_LARGE)
    assert str(mapping) in response.error_description


# --- issue 27.7: the armor call relay and another local user -----------------------------------

ATTACKER = 'armor-relay-attacker'
# Run as the other user: makes the victim's relay folder (or a link to one of its own), waits for
# the victim's relay socket, puts its own in its place and answers every directive "applied".
FAKE_RELAY = r'''
import json, os, socket, sys, time
shared, victim, shape = sys.argv[1], sys.argv[2], sys.argv[3]
user_dir = os.path.join(shared, 'armor-' + victim)
if shape == 'link':
    own = os.path.join(shared, 'attacker-owned')
    os.makedirs(os.path.join(own, 'armor-call'), mode=0o777)
    os.symlink(own, user_dir)
    os.chmod(own, 0o777)
else:
    os.makedirs(os.path.join(user_dir, 'armor-call'))
    os.chmod(user_dir, 0o777)
folder = os.path.join(user_dir, 'armor-call')
os.chmod(folder, 0o777)
deadline = time.monotonic() + 90
while time.monotonic() < deadline:
    sockets = [name for name in os.listdir(folder) if name.endswith('.sock')]
    if sockets:
        break
    time.sleep(0.05)
else:
    sys.exit(0)
path = os.path.join(folder, sockets[0])
os.unlink(path)
server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
server.bind(path)
os.chmod(path, 0o777)
server.listen(8)
open(os.path.join(shared, 'replaced'), 'w').close()
server.settimeout(1.0)
while time.monotonic() < deadline:
    try:
        connection, _ = server.accept()
    except socket.timeout:
        continue
    request = connection.makefile('rb').readline()
    with open(os.path.join(shared, 'stolen'), 'ab') as stolen:
        stolen.write(request)
    connection.sendall(json.dumps({'response': {
        'success': True, 'timeout': False, 'exit_code': 0, 'error_description': '',
        'is_consistent': True, 'queried_objects': [], 'sparql_queried_objects': []}}).encode() + b'\n')
    connection.close()
'''


@pytest.fixture(scope='module')
def attacker_user():
    """A second, real local user (made for this module and removed after it, unless it existed)."""
    import pwd
    try:
        pwd.getpwnam(ATTACKER)
        made = False
    except KeyError:
        subprocess.run(['useradd', '--system', '--no-create-home', '--shell', '/usr/sbin/nologin',
                        ATTACKER], check=True)
        made = True
    yield pwd.getpwnam(ATTACKER)
    if made:
        subprocess.run(['userdel', ATTACKER], check=False)


@pytest.mark.parametrize('shape', ['folder', 'link'])
def test_armor_call_never_hands_a_directive_to_another_users_relay(call, load, attacker_user,
                                                                   shape):
    reference = load()
    shared = pathlib.Path('/tmp') / unique_name('armor-shared-tmp')
    shared.mkdir()
    shared.chmod(0o1777)  # what /tmp is: every user may create in it
    environment = {**os.environ, 'TMPDIR': str(shared), 'ARMOR_CALL_RELAY_IDLE_S': '20'}
    environment.pop('XDG_RUNTIME_DIR', None)
    fake = subprocess.Popen(['/usr/bin/python3', '-c', FAKE_RELAY, str(shared), str(os.getuid()),
                             shape], user=attacker_user.pw_uid, group=attacker_user.pw_gid,
                            extra_groups=[])

    def armor_call(*words):
        return subprocess.run([sys.executable, '-m', 'armor_client.cli', 'call', '--wait', '60',
                               reference, *words], capture_output=True, text=True, timeout=180,
                              env=environment)
    try:
        deadline = time.monotonic() + 10
        while not (shared / f'armor-{os.getuid()}').exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        first = armor_call('QUERY', 'IND', 'CLASS', '--', 'Robot')
        assert first.returncode == 0, first.stderr
        refused = 'relay' in first.stderr and str(attacker_user.pw_uid) in first.stderr \
            or 'symbolic link' in first.stderr
        deadline = time.monotonic() + 30
        while not refused and not (shared / 'replaced').exists() and time.monotonic() < deadline:
            time.sleep(0.1)
        second = armor_call('ADD', 'IND', 'CLASS', '--', 'relayed_check', 'Robot')
        assert second.returncode == 0, second.stderr
        assert not (shared / 'stolen').exists(), (shared / 'stolen').read_text()
        assert '<http://www.example.org/robotics#relayed_check>' in answer(
            call, reference, 'QUERY IND CLASS', 'Robot'), 'the change never reached ARMOR'
        assert 'relay' in second.stderr, second.stderr  # says why it calls without the relay
    finally:
        fake.kill()
        fake.wait()
        subprocess.run([sys.executable, '-c', 'from armor_client.cli import call_relay; '
                        'call_relay.stop()'], env=environment, capture_output=True, timeout=60)
        shutil.rmtree(shared, ignore_errors=True)


def documented_writes():
    """The `armor call` examples of the docs that write a file (SAVE, LOG FILE ON, ...)."""
    commands = []
    for page in ('commands.md', 'pddl.md'):
        for line in (REPO / 'docs' / page).read_text().splitlines():
            for command in re.findall(r'`?(armor call [^`|]*(?:SAVE|LOG FILE ON)[^`|]*)`?', line):
                commands.append(command.strip())
    return commands


def test_the_documented_writes_work_with_make_runs_defaults(exposed, exposed_call):
    commands = documented_writes()
    assert len(commands) >= 4, commands
    if 'surveillance' not in exposed_call('', 'GET ALL REFS').queried_objects:
        succeeded(exposed_call, 'surveillance', 'LOAD FILE',
                  str(REPO / 'ontologies' / 'surveillance.owl'), '', 'false', 'PELLET', 'false')
    environment = {**os.environ, 'HOME': str(exposed.home)}
    for command in commands:
        # As a shell would: ~ expanded to the user's home.
        words = shlex.split(command.replace('~/', f'{exposed.home}/'))
        done = subprocess.run([sys.executable, '-m', 'armor_client.cli', 'call', '--namespace',
                               EXPOSED, '--wait', '120', *words[2:]], capture_output=True,
                              text=True, timeout=300, env=environment, cwd=REPO)
        assert done.returncode == 0, (command, done.stderr)
        written = [pathlib.Path(word) for word in words if word.startswith(str(exposed.home))]
        assert written and all(path.is_file() for path in written), (command, written)
    exposed_call('', 'LOG FILE OFF')
