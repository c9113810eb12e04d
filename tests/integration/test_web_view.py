# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The live web view (issue 13) in a real browser: what a person sees, and how it follows changes.

A node runs with web_port set; each test loads robotics.owl over ROS under a reference of its
own, opens the page in Debian's chromium (Playwright) and reads what is on screen. Changes are
made by a ROS client while the page stays open: it must show them without being reloaded.
Every test leaves a screenshot in build/test-artifacts/web/.
"""

import base64
import json
import pathlib
import urllib.error
import urllib.request

from armor_client import ArmorTransport, directive
from conftest import ONTOLOGIES, REPO, start_node
from ontology_factory import write_abox
from playwright.sync_api import expect, sync_playwright
import pytest
from web_browser import free_port, launch

pytestmark = pytest.mark.runs_for_minutes(1)

ROBOTICS = str(ONTOLOGIES / 'robotics.owl')
NAMESPACE = '/web_view'
ARTIFACTS = REPO / 'build' / 'test-artifacts' / 'web'
# Generous: the 1 s target is measured by bench/web_view.py, not asserted by a timed test.
SHOWN_WITHIN_MS = 15_000
# Every other expectation of the page waits as long: Playwright's 5-s default was too short
# for a graph of 53 individuals drawn beside two other test workers (the note stayed empty).
expect.set_options(timeout=SHOWN_WITHIN_MS)


@pytest.fixture(scope='module')
def web_node(tmp_path_factory):
    scratch = tmp_path_factory.mktemp('web')
    port = free_port()
    node = start_node(scratch, '-p', f'web_port:={port}', namespace=NAMESPACE)
    transport = ArmorTransport(namespace=NAMESPACE, service_wait_s=90.0)
    assert transport.call(directive('t', '', 'GET', 'ALL', 'REFS'), timeout_s=120).success, \
        node.log()
    node.url = f'http://127.0.0.1:{port}/'
    node.armor = transport
    node.scratch = scratch
    yield node
    transport.close()
    node.stop()


@pytest.fixture(scope='module')
def browser():
    with sync_playwright() as playwright:
        chromium = launch(playwright)
        yield chromium
        chromium.close()


@pytest.fixture
def page(browser, request):
    """A fresh page; its screenshot is saved when the test ends, and script errors fail it."""
    context = browser.new_context(viewport={'width': 1400, 'height': 900})
    opened = context.new_page()
    script_errors = []
    opened.on('pageerror', lambda error: script_errors.append(str(error)))
    yield opened
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    opened.screenshot(path=str(ARTIFACTS / f'{request.node.name}.png'), full_page=True)
    context.close()
    assert script_errors == []


def call(node, reference, words, *args, client='web_test_client'):
    command, primary, secondary = (words.split() + ['', '', ''])[:3]
    return node.armor.call(directive(client, reference, command, primary, secondary, list(args)),
                           timeout_s=300)


def load(node, reference, path=ROBOTICS, reasoner='PELLET'):
    answer = call(node, reference, 'LOAD FILE', path, '', 'false', reasoner, 'false')
    assert answer.success, answer.error_description


def open_reference(page, node, reference, tab):
    page.goto(f'{node.url}#/{reference}/{tab}')
    expect(page.locator(f'.card[data-name="{reference}"]')).to_be_visible()
    # Marks this very document: a reload would lose it.
    page.evaluate('window.armorTestDocument = "the first load"')


def still_the_same_document(page):
    return page.evaluate('window.armorTestDocument') == 'the first load'


def test_the_page_shows_the_reference_its_classes_and_an_inferred_type(web_node, page):
    load(web_node, 'web_seen')
    open_reference(page, web_node, 'web_seen', 'classes')
    card = page.locator('.card[data-name="web_seen"]')
    expect(card).to_contain_text('consistent')
    expect(card).to_contain_text('PELLET')
    expect(page.locator('#summary')).to_contain_text('5 individuals')
    tree = page.locator('#class-tree')
    for name in ('Location', 'Room', 'Corridor', 'OccupiedRoom', 'Agent', 'Robot'):
        expect(tree.locator('span[data-iri]', has_text=name).first).to_be_visible()
    tree.locator('span[data-iri$="#OccupiedRoom"]').click()
    detail = page.locator('#class-detail')
    expect(detail).to_contain_text('Room and (contains some Agent)')
    expect(detail.locator('a.inferred', has_text='kitchen')).to_be_visible()

    page.get_by_role('tab', name='Individuals').click()
    kitchen = page.locator('tr[data-name="kitchen"] td.types')
    expect(kitchen.locator('a.inferred')).to_have_text('OccupiedRoom')
    expect(kitchen.locator('a.asserted')).to_have_text('Room')
    page.locator('tr[data-name="robot1"] td').first.click()
    robot = page.locator('#individual-detail')
    expect(robot.locator('a.inferred', has_text='RobotInRoom')).to_be_visible()
    expect(robot).to_contain_text('"80"^^xsd:integer')


def test_a_fact_added_over_ros_appears_without_a_reload_with_its_inferences(web_node, page):
    load(web_node, 'web_live')
    open_reference(page, web_node, 'web_live', 'individuals')
    bedroom = page.locator('tr[data-name="bedroom"] td.types')
    expect(bedroom).to_have_text('Room')

    assert call(web_node, 'web_live', 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom').success
    expect(bedroom.locator('a.inferred')).to_have_text('OccupiedRoom', timeout=SHOWN_WITHIN_MS)
    expect(page.locator('#summary')).to_contain_text('5 individuals')

    assert call(web_node, 'web_live', 'ADD IND CLASS', 'carol', 'Person').success
    expect(page.locator('tr[data-name="carol"]')).to_be_visible(timeout=SHOWN_WITHIN_MS)
    expect(page.locator('#summary')).to_contain_text('6 individuals', timeout=SHOWN_WITHIN_MS)
    assert still_the_same_document(page)

    # The graph colours individuals by their most specific type: bedroom is now occupied.
    page.get_by_role('tab', name='Graph').click()
    expect(page.locator('#graph-note')).to_contain_text('6 individuals')
    assert graph_label(page, 'bedroom') == 'bedroom\nOccupiedRoom'


def graph_label(page, name):
    return page.evaluate('(iri) => window.armorWeb.graph().getElementById(iri).data("label")',
                         f'http://www.example.org/robotics#{name}')


def test_the_graph_reads_as_a_map_and_follows_changes(web_node, page):
    load(web_node, 'web_map')
    open_reference(page, web_node, 'web_map', 'graph')
    form = page.locator('#graph-form')
    expect(form.locator('input[name=property]')).to_have_count(3)
    for box in form.locator('input[name=property]').all():
        if not box.get_attribute('value').endswith('#connectedTo'):
            box.uncheck()
    form.locator('input[name=class]').fill('Location')
    form.locator('button[type=submit]').click()
    note = page.locator('#graph-note')
    expect(note).to_contain_text('3 individuals, 2 links')
    legend = page.locator('#graph-legend')
    expect(legend).to_contain_text('Corridor')
    expect(legend).to_contain_text('OccupiedRoom')

    assert call(web_node, 'web_map', 'ADD IND CLASS', 'hall', 'Room').success
    assert call(web_node, 'web_map', 'ADD OBJECTPROP IND', 'connectedTo', 'hall',
                'corridor1').success
    expect(note).to_contain_text('4 individuals, 3 links', timeout=SHOWN_WITHIN_MS)
    assert still_the_same_document(page)


def write_floor(path: pathlib.Path, corridors: int, rooms_per_corridor: int) -> pathlib.Path:
    """A floor plan on the robotics TBox: corridors in a row, each with its rooms, linked by
    connectedTo (symmetric, so only one direction is stated); a robot in every third room."""
    ns = 'http://www.example.org/robotics#'
    individuals = []
    for c in range(corridors):
        link = f'<connectedTo rdf:resource="{ns}c{c - 1}"/>' if c else ''
        individuals.append(f'<owl:NamedIndividual rdf:about="{ns}c{c}"><rdf:type '
                           f'rdf:resource="{ns}Corridor"/>{link}</owl:NamedIndividual>')
        for r in range(rooms_per_corridor):
            individuals.append(f'<owl:NamedIndividual rdf:about="{ns}room_{c}_{r}"><rdf:type '
                               f'rdf:resource="{ns}Room"/><connectedTo rdf:resource="{ns}c{c}"/>'
                               '</owl:NamedIndividual>')
            if r % 3 == 0:
                individuals.append(f'<owl:NamedIndividual rdf:about="{ns}bot_{c}_{r}"><rdf:type '
                                   f'rdf:resource="{ns}Robot"/><isIn rdf:resource='
                                   f'"{ns}room_{c}_{r}"/></owl:NamedIndividual>')
    tbox = (ONTOLOGIES / 'robotics.owl').read_text()
    path.write_text(tbox.replace('</rdf:RDF>', '\n'.join(individuals) + '\n</rdf:RDF>'))
    return path


def test_a_floor_of_rooms_and_corridors_reads_as_a_map(web_node, page):
    floor = write_floor(web_node.scratch / 'floor.owl', corridors=4, rooms_per_corridor=8)
    load(web_node, 'web_floor', path=str(floor))
    open_reference(page, web_node, 'web_floor', 'graph')
    form = page.locator('#graph-form')
    for box in form.locator('input[name=property]').all():
        if box.get_attribute('value').endswith('#contains'):
            box.uncheck()
    form.locator('button[type=submit]').click()
    # The robotics example's own rooms and agents, the 4 corridors, 32 rooms and 12 robots.
    expect(page.locator('#graph-note')).to_contain_text('53 individuals')
    page.wait_for_function('() => window.armorWeb.settled()')
    positions = page.evaluate('''() => Object.fromEntries(window.armorWeb.graph().nodes()
        .map((n) => [n.data('label').split('\\n')[0], n.position()]))''')

    def distance(a, b):
        return ((positions[a]['x'] - positions[b]['x']) ** 2
                + (positions[a]['y'] - positions[b]['y']) ** 2) ** 0.5
    corridors = [f'c{c}' for c in range(4)]
    misplaced = [f'room_{c}_{r}' for c in range(4) for r in range(8)
                 if min(corridors, key=lambda k: distance(f'room_{c}_{r}', k)) != f'c{c}']
    # Read as a map: a room is drawn beside its own corridor, nearer to it than to any other.
    assert misplaced == []
    assert graph_label(page, 'room_2_3') == 'room_2_3\nOccupiedRoom'
    assert graph_label(page, 'room_2_4') == 'room_2_4\nRoom'


def test_one_link_whose_iri_the_naming_rules_refuse_leaves_the_rest_of_the_graph(web_node,
                                                                                 page):
    # An object property whose IRI holds a '|': RDF/XML takes it, ARMOR's naming rules do not.
    ns = 'http://www.example.org/robotics#'
    odd = 'http://www.example.org/odd|map#'
    extra = (f'<owl:ObjectProperty rdf:about="{odd}leadsTo"/>\n'
             f'<owl:NamedIndividual rdf:about="{ns}kitchen"><odd:leadsTo xmlns:odd="{odd}" '
             f'rdf:resource="{ns}bedroom"/></owl:NamedIndividual>\n')
    tbox = (ONTOLOGIES / 'robotics.owl').read_text()
    path = web_node.scratch / 'odd-link.owl'
    path.write_text(tbox.replace('</rdf:RDF>', extra + '</rdf:RDF>'))
    load(web_node, 'web_odd', path=str(path))
    open_reference(page, web_node, 'web_odd', 'graph')
    note = page.locator('#graph-note')
    # The robotics example's 5 individuals and their links, the odd one among them.
    expect(note).to_contain_text('5 individuals')
    expect(note.locator('.error')).to_have_count(0)
    assert graph_label(page, 'bedroom') == 'bedroom\nRoom'
    labels = page.evaluate('() => window.armorWeb.graph().edges().map((e) => e.data("label"))')
    assert 'leadsTo' in labels and 'connectedTo' in labels, labels


def test_an_inconsistent_reference_is_flagged_at_the_top_with_the_explanation(web_node, page):
    load(web_node, 'web_bad')
    open_reference(page, web_node, 'web_bad', 'individuals')
    banner = page.locator('#inconsistency')
    expect(banner).to_be_hidden()

    # kitchen is a Room; Room and Corridor are disjoint.
    assert call(web_node, 'web_bad', 'ADD IND CLASS', 'kitchen', 'Corridor').success
    expect(banner).to_be_visible(timeout=SHOWN_WITHIN_MS)
    expect(banner).to_contain_text('This reference is inconsistent')
    expect(page.locator('#explanation')).to_contain_text('DisjointWith', timeout=SHOWN_WITHIN_MS)
    expect(page.locator('.card[data-name="web_bad"]')).to_contain_text('INCONSISTENT')
    kitchen = page.locator('tr[data-name="kitchen"] td.types')
    expect(kitchen.locator('a.asserted', has_text='Corridor')).to_be_visible()
    assert still_the_same_document(page)
    page.screenshot(path=str(ARTIFACTS / 'inconsistent-warning.png'))

    assert call(web_node, 'web_bad', 'REMOVE IND CLASS', 'kitchen', 'Corridor').success
    expect(banner).to_be_hidden(timeout=SHOWN_WITHIN_MS)


def test_dl_and_sparql_boxes_answer_and_explain_their_errors(web_node, page):
    load(web_node, 'web_query')
    open_reference(page, web_node, 'web_query', 'query')
    page.fill('#dl-expression', 'Room and (contains some Agent)')
    page.click('#dl-form button')
    result = page.locator('#dl-result')
    expect(result.locator('a.entity', has_text='kitchen')).to_be_visible()

    page.fill('#dl-expression', 'Room and (contains some)')
    page.click('#dl-form button')
    expect(result).to_contain_text('exit code 208')

    page.fill('#sparql-query', 'SELECT ?who ?where WHERE { ?who :isIn ?where } ORDER BY ?who')
    page.click('#sparql-form button')
    table = page.locator('#sparql-result table')
    expect(table).to_be_visible(timeout=60_000)
    expect(table.locator('tbody tr')).to_have_count(2)
    expect(table.locator('tbody tr').first).to_contain_text('alice')
    expect(table.locator('tbody tr').first).to_contain_text('corridor1')


def test_recent_directives_name_the_client_and_the_outcome(web_node, page):
    load(web_node, 'web_recent')
    assert not call(web_node, 'web_recent', 'ADD IND CLASS', 'lonely',
                    client='sloppy_node').success
    open_reference(page, web_node, 'web_recent', 'query')
    page.fill('#dl-expression', 'Robot')
    page.click('#dl-form button')
    expect(page.locator('#dl-result a.entity', has_text='robot1')).to_be_visible()
    page.get_by_role('tab', name='Recent directives').click()
    newest = page.locator('#recent-table tbody tr').first
    expect(newest).to_contain_text('sloppy_node')
    expect(newest).to_contain_text('ADD IND CLASS')
    expect(newest.locator('td.fail')).to_have_text('207')
    # The page's own queries are left out unless asked for.
    expect(page.locator('#recent-table')).not_to_contain_text('armor_web')
    page.check('#recent-all')
    expect(page.locator('#recent-table')).to_contain_text('armor_web')


def test_recent_directives_follow_queries_live_without_a_click(web_node, page):
    """Issue 35 item 9: a query moves no revision, yet shows in the open list at once."""
    load(web_node, 'web_recent_live')
    open_reference(page, web_node, 'web_recent_live', 'recent')
    rows = page.locator('#recent-table tbody tr')
    expect(rows.first).to_contain_text('LOAD')
    assert call(web_node, 'web_recent_live', 'QUERY IND CLASS', 'Robot',
                client='live_reader').success
    expect(rows.first).to_contain_text('live_reader', timeout=SHOWN_WITHIN_MS)
    expect(rows.first).to_contain_text('QUERY IND CLASS')
    assert not call(web_node, 'web_recent_live', 'QUERY IND', client='sloppy_reader').success
    expect(rows.first).to_contain_text('sloppy_reader', timeout=SHOWN_WITHIN_MS)
    assert still_the_same_document(page)


def legend_colours(page):
    page.wait_for_function('() => document.querySelectorAll("#graph-legend .swatch").length > 0')
    return page.evaluate("""() => Object.fromEntries([...document.querySelectorAll(
        '#graph-legend > span')].map((item) => [item.textContent,
        getComputedStyle(item.querySelector('.swatch')).backgroundColor]))""")


def test_each_class_keeps_one_colour_and_edge_labels_stay_readable(web_node, browser, page):
    """Issue 35 item 9: a type's colour depends on its name only, not on the page's history;
    edge labels are level, on a background, and at least 11 px on screen."""
    load(web_node, 'web_colours')
    open_reference(page, web_node, 'web_colours', 'graph')
    expect(page.locator('#graph-legend')).to_contain_text('Room')
    assert call(web_node, 'web_colours', 'REPLACE OBJECTPROP IND', 'isIn', 'alice', 'bedroom',
                'corridor1').success
    expect(page.locator('#graph-note')).to_contain_text('individuals')
    page.wait_for_function('() => window.armorWeb.graph().getElementById('
                           '"http://www.example.org/robotics#bedroom").data("label")'
                           '.endsWith("OccupiedRoom")', timeout=SHOWN_WITHIN_MS)
    seen_first = legend_colours(page)
    other = browser.new_context(viewport={'width': 1400, 'height': 900}).new_page()
    open_reference(other, web_node, 'web_colours', 'graph')
    seen_later = legend_colours(other)
    assert seen_first == seen_later and len(set(seen_later.values())) == len(seen_later)
    other.context.close()

    page.wait_for_function('() => window.armorWeb.settled()')
    page.wait_for_function("""() => window.armorWeb.graph().edges().every((edge) =>
        parseFloat(edge.renderedStyle('font-size')) >= 11)""", timeout=SHOWN_WITHIN_MS)
    styles = page.evaluate("""() => window.armorWeb.graph().edges().map((edge) =>
        [edge.style('text-rotation'), Number(edge.style('text-background-opacity'))])""")
    assert styles and all(rotation == 'none' and opacity > 0.5 for rotation, opacity in styles)


def test_the_dl_box_names_a_word_the_reference_does_not_know(web_node, page):
    """Issue 35 item 2: a misspelt class answers nothing, and the page says why."""
    load(web_node, 'web_dl_typo')
    open_reference(page, web_node, 'web_dl_typo', 'query')
    page.fill('#dl-expression', 'Agent and (isIn some Rom)')
    page.click('#dl-form button')
    expect(page.locator('#dl-result .note').first).to_contain_text(
        "new to the reference: class 'Rom' (did you mean Room?)")


def test_ten_thousand_individuals_are_paged_and_found_by_name(web_node, page):
    abox = write_abox(web_node.scratch / 'ten_thousand.owl', rooms=2000, robots=8000)
    load(web_node, 'web_big', path=str(abox))
    open_reference(page, web_node, 'web_big', 'individuals')
    count = page.locator('#individual-count')
    expect(count).to_have_text('1–50 of 10,005', timeout=60_000)
    expect(page.locator('#individuals-table tbody tr')).to_have_count(50)
    page.click('#individual-next')
    expect(count).to_have_text('51–100 of 10,005')
    page.fill('#individual-search', 'bot7777')
    expect(count).to_have_text('1–1 of 1')
    expect(page.locator('tr[data-name="bot7777"] a.inferred')).to_have_text('RobotInRoom')
    page.screenshot(path=str(ARTIFACTS / 'ten-thousand-individuals.png'))

    # Dropped by a ROS client, the reference leaves the open page.
    assert call(web_node, 'web_big', 'DROP').success
    expect(page.locator('.card[data-name="web_big"]')).to_have_count(0, timeout=SHOWN_WITHIN_MS)
    expect(page.locator('#gone')).to_contain_text('"web_big" is no longer loaded')


def http(node, path, *, method='GET', body=None, headers=None):
    """(status, JSON answer) of a request to the node's web view."""
    request = urllib.request.Request(node.url.rstrip('/') + path, method=method, data=body,
                                     headers=headers or {})
    try:
        with urllib.request.urlopen(request, timeout=120) as answer:
            return answer.status, json.loads(answer.read() or b'null')
    except urllib.error.HTTPError as error:
        text = error.read()
        try:
            return error.code, json.loads(text)
        except ValueError:
            return error.code, text.decode()


def test_the_server_answers_only_its_own_origin_and_changes_nothing(web_node):
    load(web_node, 'web_http')
    status, answer = http(web_node, '/api/overview', headers={'Host': 'attacker.example:80'})
    assert status == 421 and 'attacker.example' in answer['error']['description']
    status, answer = http(web_node, '/api/references/nowhere/classes')
    assert status == 404 and answer['error']['exit_code'] == 206
    status, answer = http(web_node, '/api/references/web_http/graph?property=isOn')
    assert status == 404 and answer['error']['exit_code'] == 224
    status, _ = http(web_node, '/api/references/web_http/sparql', method='POST',
                     body=b'query=SELECT', headers={'Content-Type': 'text/plain'})
    assert status == 415
    status, answer = http(web_node, '/api/references/web_http/sparql', method='POST',
                          body=json.dumps({'query': 'INSERT DATA { :x a :Room }'}).encode(),
                          headers={'Content-Type': 'application/json'})
    assert status == 200 and not answer['success'] and answer['exit_code'] == 208
    assert call(web_node, 'web_http', 'QUERY IND CLASS', 'Room').queried_objects == [
        '<http://www.example.org/robotics#bedroom>', '<http://www.example.org/robotics#kitchen>']
    for path in ('/api/references/web_http', '/api/references/web_http/classes',
                 '/api/references/web_http/individuals'):
        status, _ = http(web_node, path, method='DELETE')
        assert status == 405
    status, _ = http(web_node, '/api/live', headers={
        'Connection': 'Upgrade', 'Upgrade': 'websocket', 'Sec-WebSocket-Version': '13',
        'Sec-WebSocket-Key': 'dGhlIHNhbXBsZSBub25jZQ==', 'Origin': 'http://attacker.example'})
    assert status == 403


def test_a_taken_port_leaves_the_robot_served_and_says_so(tmp_path, web_node):
    taken = int(web_node.url.rsplit(':', 1)[1].strip('/'))
    node = start_node(tmp_path, '-p', f'web_port:={taken}', namespace='/web_taken')
    transport = ArmorTransport(namespace='/web_taken', service_wait_s=90.0)
    try:
        answer = transport.call(directive('t', 'robotics', 'QUERY', 'IND', 'CLASS', ['Room']),
                                timeout_s=120)
        assert answer.success, node.log()
        log = node.log()
        assert f'the web view cannot listen on 127.0.0.1:{taken}' in log
        assert 'serves ROS without the web view' in log
        assert 'Web view:' not in log
    finally:
        transport.close()
        node.stop()


def test_a_bad_port_stops_the_node_with_the_reason(tmp_path):
    node = start_node(tmp_path, '-p', 'web_port:=70000', namespace='/web_bad_port')
    node.process.wait(timeout=120)
    node.stop()
    assert node.process.returncode != 0
    assert 'web_port must be 0 (off) or a TCP port from 1 to 65535, got 70000' in node.log()


def test_the_web_view_is_off_by_default(armor_node, armor):
    assert 'ARMOR ready' in armor_node.log()
    assert 'Web view' not in armor_node.log()


SCREENSHOT = REPO / 'docs' / 'images' / 'web-view.png'
# Parts of the page that look the same on every render of the README's scene (the rest shows
# times or a layout): the header, the summary's first line, the reference's card without its
# time, the tabs (Graph chosen), the graph's controls and its note (5 individuals, 8 links).
STEADY_PARTS = {'header': 'header', 'summary': '#summary', 'card': '.card[data-name="robotics"]',
                'tabs': '.tabs', 'controls': '#graph-form', 'note': '#graph-note'}
COMPARE = """
async ([stored, fresh, boxes, palette, canvas]) => {
  const pixels = async (source) => {
    const image = new Image();
    image.src = source;
    await image.decode();
    const drawn = document.createElement('canvas');
    drawn.width = image.width;
    drawn.height = image.height;
    const context = drawn.getContext('2d');
    context.drawImage(image, 0, 0);
    return {width: image.width, height: image.height,
            data: context.getImageData(0, 0, image.width, image.height).data};
  };
  const [a, b] = [await pixels(stored), await pixels(fresh)];
  // Per box: pixels that differ by more than a quarter of the range in some channel.
  const differing = {};
  for (const [name, box] of Object.entries(boxes)) {
    let count = 0;
    for (let y = box.y; y < box.y + box.height; y++) {
      for (let x = box.x; x < box.x + box.width; x++) {
        const i = 4 * (y * a.width + x);
        if ([0, 1, 2].some(c => Math.abs(a.data[i + c] - b.data[i + c]) > 64)) count++;
      }
    }
    differing[name] = count;
  }
  // In the graph: each node colour's share of the pixels painted in a node colour.
  const shares = (image) => {
    const counts = palette.map(() => 0);
    for (let y = canvas.y; y < canvas.y + canvas.height; y++) {
      for (let x = canvas.x; x < canvas.x + canvas.width; x++) {
        const i = 4 * (y * image.width + x);
        const k = palette.findIndex(([r, g, bl]) => Math.abs(image.data[i] - r) < 3
            && Math.abs(image.data[i + 1] - g) < 3 && Math.abs(image.data[i + 2] - bl) < 3);
        if (k >= 0) counts[k]++;
      }
    }
    const total = counts.reduce((x, y) => x + y, 0) || 1;
    return counts.map(n => n / total);
  };
  return {stored: [a.width, a.height], fresh: [b.width, b.height], differing,
          storedShares: shares(a), freshShares: shares(b)};
}
"""


def _data_url(png: bytes) -> str:
    return 'data:image/png;base64,' + base64.b64encode(png).decode('ascii')


def test_the_readme_screenshot_shows_the_page_it_claims(tmp_path, browser):
    """The README's picture is the web view's graph of the robotics example (Openllet) after
    alice moved into the bedroom: the same scene rendered afresh (the page open, then the move
    over ROS, as a user would see it) has its size, the same steady parts pixel for pixel, and
    its nodes in the same colours in the same shares (the layout itself varies)."""
    readme = (REPO / 'README.md').read_text()
    assert '](docs/images/web-view.png)' in readme
    assert 'after alice moved into the bedroom' in readme
    port = free_port()
    node = start_node(tmp_path, '-p', f'web_port:={port}', namespace='/web_readme')
    node.armor = ArmorTransport(namespace='/web_readme', service_wait_s=90.0)
    context = None
    try:
        assert call(node, 'robotics', 'DROP').success
        load(node, 'robotics')
        context = browser.new_context(viewport={'width': 1280, 'height': 800})
        page = context.new_page()
        page.goto(f'http://127.0.0.1:{port}/#/robotics/graph')
        expect(page.locator('#graph-note')).to_contain_text('5 individuals, 6 links')
        assert call(node, 'robotics', 'ADD OBJECTPROP IND', 'isIn', 'alice', 'bedroom').success
        expect(page.locator('#graph-note')).to_contain_text('5 individuals, 8 links',
                                                            timeout=SHOWN_WITHIN_MS)
        page.wait_for_function('() => window.armorWeb.settled()')
        # The page's own reads are not a directive: the card shows its counts, not "busy".
        expect(page.locator('.card[data-name="robotics"] .badge.busy')).to_have_count(
            0, timeout=SHOWN_WITHIN_MS)
        page.locator('#graph-canvas').hover(position={'x': 1, 'y': 1})  # no hover effect
        fresh = page.screenshot()
        ARTIFACTS.mkdir(parents=True, exist_ok=True)
        (ARTIFACTS / 'readme-scene-fresh.png').write_bytes(fresh)
        boxes = {}
        for name, selector in STEADY_PARTS.items():
            box = page.locator(selector).first.bounding_box()
            boxes[name] = {'x': round(box['x']), 'y': round(box['y']),
                           'width': round(box['width']), 'height': round(box['height'])}
        boxes['summary']['height'] = 20  # its first line: the second holds the reasoning time
        # The card down to its profile: the rows below show times (classification, reasoning).
        profile_bottom = page.evaluate(
            "() => [...document.querySelectorAll('.card[data-name=\"robotics\"] dt')]"
            ".find((dt) => dt.textContent === 'profile').nextElementSibling"
            ".getBoundingClientRect().bottom")
        boxes['card']['height'] = round(profile_bottom) - boxes['card']['y']
        canvas = {k: round(v) for k, v in page.locator('#graph-canvas').bounding_box().items()}
        canvas['height'] = 800 - canvas['y']
        palette = page.evaluate(
            'PALETTE.map(c => [1, 3, 5].map(i => parseInt(c.slice(i, i + 2), 16)))')
        seen = page.evaluate(COMPARE, [_data_url(SCREENSHOT.read_bytes()), _data_url(fresh),
                                       boxes, palette, canvas])
    finally:
        if context is not None:
            context.close()
        node.armor.close()
        node.stop()
    assert seen['stored'] == seen['fresh'] == [1280, 800]
    assert all(count <= 3 for count in seen['differing'].values()), seen['differing']
    for stored_share, fresh_share in zip(seen['storedShares'], seen['freshShares']):
        assert abs(stored_share - fresh_share) < 0.05, (seen['storedShares'], seen['freshShares'])
