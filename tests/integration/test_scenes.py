# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Teaching scenes by demonstration (issue 32, docs/scenes.md) over real ROS 2.

The node loads the SIT plugin and the sit extension by default, so the session's node serves
``sit_armor_injected``; these tests call it from this process with sit_armor_injected_msgs, as
a ported ROS 1 client would: the checks of the specification, refused input, mounts, one change
event per scene, restarts of the core and of the node, a randomised test of the two properties
on generated scenes, and the Python client's and the CLI's way to the same directive.
"""

import itertools
import json
import os
import random
import signal
import subprocess
import sys
import time

from armor_client import Armor, ArmorArgumentError, ArmorTransport, directive
from change_listener import ChangeListener
from conftest import REPO, start_node
import pytest
from sit_armor_injected.client import SceneServiceClient
from sit_armor_injected_msgs.msg import SceneElement

SIT = 'http://www.emarolab.it/sit/simple'
TWO_SPHERES = [('SPHERE', [0, 0, 0]), ('SPHERE', [0.8, 0, 0.8])]
SPHERE_AND_CONE = [('SPHERE', [0, 0, 0]), ('CONE', [-0.8, -0.8, 0, 0, 0, 1])]
ALL_THREE = [('SPHERE', [0, 0, 0]), ('CONE', [-0.8, -0.8, 0, 0, 0, 1]), ('SPHERE', [0.8, 0, 0.8])]
TWO_CONES = [('CONE', [0, 0, 0, 0, 0, 1]), ('CONE', [1, 0, 0, 0.5, 0.5, 0])]


class SceneClient(SceneServiceClient):
    """The package's client, with the test's shorthands."""

    def send(self, reference, elements, threshold, client_name='', timeout_s=120):
        return self.call(reference, elements, threshold, client_name, timeout_s)

    def ok(self, reference, elements, threshold=0.9, client_name=''):
        response = self.send(reference, elements, threshold, client_name)
        assert response.success, (response.exit_code, response.error_description)
        return response


def recognised(response):
    return {r.class_name: r.similarity for r in response.recognitions}


@pytest.fixture(scope='module')
def scenes(armor):
    client = SceneClient(armor.node)
    yield client
    client.close()


@pytest.fixture
def fresh(armor, request):
    """A new empty reference of the test's own, dropped afterwards; the call helper with it."""
    name = 'sit_' + request.node.name.replace('[', '_').replace(']', '')[:40]
    armor.call(directive('t', name, 'DROP'))
    reasoner = getattr(request, 'param', 'PELLET')
    created = armor.call(directive('t', name, 'CREATE', '', '', [SIT, 'false', reasoner, 'false']))
    assert created.success, created.error_description
    yield name
    armor.call(directive('t', name, 'DROP'))


def query(armor, reference, words, *args, client='t'):
    command, primary, secondary = (words.split() + ['', '', ''])[:3]
    answer = armor.call(directive(client, reference, command, primary, secondary, args),
                        timeout_s=120)
    assert answer.success, (words, answer.exit_code, answer.error_description)
    return list(answer.queried_objects)


def scene_classes(armor, reference):
    return {json.loads(t)['name']: json.loads(t) for t in query(armor, reference,
                                                                'QUERY SIT SCENES')}


def iri(name):
    return f'<{SIT}#{name}>'


@pytest.mark.parametrize('fresh', ['PELLET', 'HERMIT'], indirect=True)
def test_the_checks_of_the_specification(armor, scenes, fresh):
    first = scenes.ok(fresh, TWO_SPHERES)
    assert first.learned_scene_name == 'SCENE-1' and recognised(first) == {}
    again = scenes.ok(fresh, TWO_SPHERES)
    assert again.learned_scene_name == '' and recognised(again) == {'SCENE-1': 1.0}

    second = scenes.ok(fresh, SPHERE_AND_CONE)
    assert second.learned_scene_name == 'SCENE-2'
    restrictions = query(armor, fresh, 'QUERY CLASS RESTRICTIONS', 'SCENE-2')
    assert any('CONE' in r for r in restrictions), restrictions
    assert not any('PLANE' in r for r in restrictions), restrictions

    third = scenes.ok(fresh, ALL_THREE)
    assert third.learned_scene_name == 'SCENE-3'
    cardinality = {name: c['cardinality'] for name, c in scene_classes(armor, fresh).items()}
    assert cardinality == {'SCENE-1': 4, 'SCENE-2': 4, 'SCENE-3': 12}
    assert recognised(third) == pytest.approx({'SCENE-1': 4 / 12, 'SCENE-2': 4 / 12})
    assert all(0 < s < 1 for s in recognised(third).values())
    repeated = scenes.ok(fresh, ALL_THREE)
    assert repeated.learned_scene_name == ''
    assert recognised(repeated)['SCENE-3'] == 1.0
    supers = query(armor, fresh, 'QUERY CLASS SUPER', 'SCENE-3')
    assert {iri('SCENE-1'), iri('SCENE-2')} <= set(supers), supers

    cones = scenes.ok(fresh, TWO_CONES)
    assert cones.learned_scene_name == 'SCENE-4'
    cone_class = scene_classes(armor, fresh)['SCENE-4']
    assert cone_class['cardinality'] == 6
    assert {f'{r["property"]} min {r["min"]} {r["type"]}' for r in cone_class['restrictions']} == {
        'alongXCONE min 2 CONE', 'perpendicularCONE min 2 CONE', 'behindCONE min 1 CONE',
        'frontCONE min 1 CONE'}
    assert iri('SCENE') in query(armor, fresh, 'QUERY CLASS SUPER', 'SCENE-4')
    # The scenes' individuals are gone: the reference has none.
    assert query(armor, fresh, 'QUERY IND CLASS', 'owl:Thing') == []


def test_bad_input_gets_a_clear_error_and_leaves_nothing(armor, scenes, fresh):
    scenes.ok(fresh, TWO_SPHERES)
    revision = query(armor, fresh, 'GET REF REVISION', fresh)
    refused = {
        'unknown type': ([('CUBE', [0, 0, 0]), ('SPHERE', [1, 1, 1])], 207),
        'a sphere with an axis': ([('SPHERE', [0, 0, 0, 0, 0, 1]), ('SPHERE', [1, 1, 1])], 207),
        'too few features': ([('CONE', [0, 0]), ('SPHERE', [1, 1, 1])], 207),
        'NaN': ([('SPHERE', [0, float('nan'), 0]), ('SPHERE', [1, 1, 1])], 101),
        'infinity': ([('SPHERE', [0, 0, 0]), ('PLANE', [1, 1, float('inf'), 0, 0, 1])], 101),
        'empty scene': ([], 207),
        '1,000 elements': ([('SPHERE', [i, 0, 0]) for i in range(1000)], 221),
    }
    for what, (elements, code) in refused.items():
        started = time.monotonic()
        response = scenes.send(fresh, elements, 0.9)
        assert not response.success and response.exit_code == code, (
            what, response.exit_code, response.error_description)
        assert response.error_description and response.learned_scene_name == '', what
        assert time.monotonic() - started < 30, f'{what}: refused only after minutes of work'
    nowhere = scenes.send('no_such_reference', TWO_SPHERES, 0.9)
    assert (nowhere.success, nowhere.exit_code) == (False, 206), nowhere.error_description
    assert 'no_such_reference' in nowhere.error_description
    # Nothing acknowledged, nothing left: the same revision, one class, no individual.
    assert query(armor, fresh, 'GET REF REVISION', fresh) == revision
    assert list(scene_classes(armor, fresh)) == ['SCENE-1']
    assert query(armor, fresh, 'QUERY IND CLASS', 'owl:Thing') == []


def test_a_mount_of_another_client_refuses_the_scene(armor, scenes, fresh):
    query(armor, fresh, 'MOUNT', client='holder')
    try:
        refused = scenes.send(fresh, TWO_SPHERES, 0.9)
        assert (refused.success, refused.exit_code) == (False, 102), refused.error_description
        assert scene_classes(armor, fresh) == {}
        # The holder may send it, naming itself in the appended client_name field.
        assert scenes.ok(fresh, TWO_SPHERES, client_name='holder').learned_scene_name == 'SCENE-1'
    finally:
        query(armor, fresh, 'UNMOUNT', client='holder')


def test_each_scene_is_one_change_event(armor, scenes, fresh):
    listener = ChangeListener(armor.node)
    try:
        listener.wait_until_live(lambda: armor.call(directive(
            't', fresh, 'ADD', 'IND', 'CLASS', ['probe', 'Probe'])))
        start = int(query(armor, fresh, 'GET REF REVISION', fresh)[0])
        scenes.ok(fresh, ALL_THREE)
        scenes.ok(fresh, ALL_THREE)

        def after():
            return [m for m in listener.of(fresh) if m.revision > start]
        listener.wait_for(lambda: len(after()) >= 2)
        time.sleep(0.5)  # anything wrongly published would arrive meanwhile
        events = after()
        assert [[(d.command, d.primary_command_spec) for d in e.directives] for e in events] == [
            [('SIT', 'SCENE')], [('SIT', 'SCENE')]]
        assert [e.revision for e in events] == [start + 1, start + 2]
        assert events[0].client_name == 'extension:sit'
    finally:
        listener.close()


# ---------------------------------------------------------------- the two properties, randomised

def relations(elements, near=0.03, axis_near=0.05):
    """The distinct (property, element) assertions of a scene: the specification's table,
    written again here independently of the plugin."""
    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def dot(a, b):
        return sum(x * y for x, y in zip(a, b))

    facts = set()
    for (d, (kind_d, f_d)), (r, (kind_r, f_r)) in itertools.permutations(enumerate(elements), 2):
        dx, dy, dz = (f_d[i] - f_r[i] for i in range(3))
        found = []
        if dy >= near:
            found += [('right', d, r), ('left', r, d)]
        if dx >= near:
            found += [('behind', d, r), ('front', r, d)]
        if dz >= near:
            found += [('above', d, r), ('below', r, d)]
        for name, (u, v) in (('alongX', (dy, dz)), ('alongY', (dx, dz)), ('alongZ', (dx, dy))):
            if abs(u) <= near and abs(v) <= near:
                found += [(name, d, r), (name, r, d)]
        if len(f_d) == 6 and len(f_r) == 6:
            if all(abs(c) <= axis_near for c in cross(f_d[3:], f_r[3:])):
                found += [('parallel', d, r), ('parallel', r, d)]
            if abs(dot(f_d[3:], f_r[3:])) <= axis_near:
                found += [('perpendicular', d, r), ('perpendicular', r, d)]
        if len(f_d) == 6:
            offset = [f_r[i] - f_d[i] for i in range(3)]
            across = cross(offset, f_d[3:])
            if dot(across, across) / dot(f_d[3:], f_d[3:]) <= axis_near:
                found += [('coaxial', d, r), ('coaxial', r, d)]
        facts.update(found)
    return {(name + elements[subject][0], obj) for name, subject, obj in facts}


def generated_scene(rng, size):
    """A table top: primitives at random, some orientable ones with a random axis."""
    kinds = ('SPHERE', 'PLANE', 'CONE', 'CYLINDER')
    scene = []
    for _ in range(size):
        kind = rng.choice(kinds)
        centre = [round(rng.uniform(-0.5, 0.5), 3), round(rng.uniform(-0.5, 0.5), 3),
                  round(rng.choice([0.0, rng.uniform(0, 0.3)]), 3)]
        if kind != 'SPHERE' and rng.random() < 0.7:
            centre += rng.choice([[0, 0, 1], [1, 0, 0], [0, 1, 0],
                                  [round(rng.uniform(-1, 1), 2) or 0.5, 0.5, 0]])
        scene.append((kind, centre))
    return scene


def test_randomised_learned_scenes_are_recognised_and_recognise_their_extensions(
        armor, scenes, fresh):
    seed = int(os.environ.get('ARMOR_SCENE_SEED', '32'))
    rng = random.Random(seed)
    for round_number in range(6):
        example = generated_scene(rng, rng.randint(3, 5))
        example_cardinality = len(relations(example))
        learned = scenes.ok(fresh, example, threshold=1.0).learned_scene_name
        assert learned, f'seed {seed} round {round_number}: threshold 1 always learns'
        assert scene_classes(armor, fresh)[learned]['cardinality'] == example_cardinality

        # Property 1: sent again, it is recognised by its class with 1.0 and nothing is learned.
        again = scenes.ok(fresh, example, threshold=0.9)
        assert again.learned_scene_name == '', (seed, round_number, example)
        assert recognised(again)[learned] == 1.0

        # Property 2: a scene whose relations include the example's (the example plus more
        # elements) is recognised by the class, with similarity card(class) / card(scene).
        larger = example + generated_scene(rng, rng.randint(1, 3))
        assert {(p, o) for p, o in relations(larger) if o < len(example)} >= relations(example)
        answer = scenes.ok(fresh, larger, threshold=1.0)
        assert recognised(answer)[learned] == pytest.approx(
            example_cardinality / len(relations(larger)), abs=1e-12), (seed, round_number, larger)
    assert query(armor, fresh, 'QUERY IND CLASS', 'owl:Thing') == []


# ---------------------------------------------------------------- restarts

@pytest.fixture(scope='module')
def own_node(tmp_path_factory):
    """A node of its own (its state directory, its namespace), to restart and kill."""
    scratch = tmp_path_factory.mktemp('scenes_node')
    nodes = [start_node(scratch, namespace='/scenes')]
    transport = ArmorTransport(namespace='/scenes', service_wait_s=120)
    yield scratch, nodes, transport
    transport.close()
    nodes[-1].stop()


def test_learned_classes_the_counter_and_recognitions_survive_restarts(own_node):
    scratch, nodes, transport = own_node
    assert transport.call(directive('t', 'memory', 'CREATE', '', '',
                                    [SIT, 'false', 'PELLET', 'false']), timeout_s=120).success
    client = SceneClient(transport.node, '/scenes')
    assert client.ok('memory', TWO_SPHERES).learned_scene_name == 'SCENE-1'
    assert client.ok('memory', SPHERE_AND_CONE).learned_scene_name == 'SCENE-2'

    # The core dies: the node starts another from the journal.
    os.kill(nodes[-1].core_pid(), signal.SIGKILL)
    deadline = time.monotonic() + 180
    while True:
        response = client.send('memory', TWO_SPHERES, 0.9)
        if response.success or time.monotonic() > deadline:
            break
        assert response.exit_code == 216, response.error_description
        time.sleep(0.5)
    assert (response.learned_scene_name, recognised(response)) == ('', {'SCENE-1': 1.0})
    assert client.ok('memory', TWO_CONES).learned_scene_name == 'SCENE-3'
    client.close()

    # The whole node stops and starts again on its state directory.
    nodes[-1].stop()
    nodes.append(start_node(scratch, namespace='/scenes'))
    client = SceneClient(transport.node, '/scenes')
    assert recognised(client.ok('memory', SPHERE_AND_CONE)) == {'SCENE-2': 1.0}
    assert recognised(client.ok('memory', TWO_CONES)) == {'SCENE-3': 1.0}
    assert client.ok('memory', ALL_THREE).learned_scene_name == 'SCENE-4'
    client.close()


# ---------------------------------------------------------------- the Python client and the CLI

def test_the_python_client_learns_and_lists_scenes(armor, fresh):
    client = Armor('scene_teacher', transport=armor, timeout_s=120)
    table = client.reference(fresh)
    answer = table.learn_scene([{'type': 'SPHERE', 'features': [0, 0, 0]},
                                SceneElement(type='CONE', features=[-0.8, -0.8, 0.0, 0, 0, 1])],
                               0.9)
    assert (answer.learned_scene_name, answer.recognitions) == ('SCENE-1', [])
    again = table.learn_scene(SPHERE_AND_CONE, 0.9)
    assert again.learned_scene_name == '' and again.recognitions[0].class_name == 'SCENE-1'
    assert again.recognitions[0].similarity == 1.0
    with pytest.raises(ArmorArgumentError) as refused:
        table.learn_scene([('SPHERE', [0, 0])], 0.9)
    assert refused.value.exit_code == 207
    [learned] = table.scene_classes()
    assert learned.name == 'SCENE-1' and learned.cardinality == 4
    assert 'CONE' in learned.definition and learned.superscenes == []
    [latest, _] = table.recent_scenes()[:2]
    assert latest['recognitions'][0]['name'] == 'SCENE-1'


def test_the_cli_sends_a_scene_from_a_yaml_file(armor, armor_node, fresh):
    scene = armor_node.scratch / 'scene.yaml'
    scene.write_text('learningTreshold: 0.9\nsceneElements:\n'
                     '  - {type: CONE, features: [0, 0, 0, 0, 0, 1]}\n'
                     '  - {type: CONE, features: [1, 0, 0, 0.5, 0.5, 0]}\n')
    command = [sys.executable, '-m', 'armor_client.cli', 'scene', fresh, str(scene), '--json',
               '--wait', '90']
    first = subprocess.run(command, capture_output=True, text=True, timeout=180)
    assert first.returncode == 0, first.stderr
    assert json.loads(first.stdout) == {'learned_scene_name': 'SCENE-1', 'recognitions': []}
    second = subprocess.run(command[:-3], capture_output=True, text=True, timeout=180)
    assert second.returncode == 0, second.stderr
    assert 'nothing learned' in second.stdout and 'SCENE-1' in second.stdout
    listed = subprocess.run([sys.executable, '-m', 'armor_client.cli', 'scene', fresh,
                             '--classes'], capture_output=True, text=True, timeout=180)
    assert 'at least 2 CONE along X' in listed.stdout, listed.stdout
    scene.write_text('[{type: CUBE, features: [0, 0, 0]}, {type: SPHERE, features: [1, 1, 1]}]')
    refused = subprocess.run(command, capture_output=True, text=True, timeout=180)
    assert refused.returncode == 1 and 'error 207' in refused.stderr, refused.stderr


def test_the_demo_teaches_recognises_and_learns(armor):
    done = subprocess.run([sys.executable, str(REPO / 'examples' / 'scenes_demo.py'),
                           '--pause', '0', '--reference', 'scenes_demo_test'],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    lines = done.stdout.splitlines()
    # Each arrangement: learned from its first example, recognised in the others.
    assert [line.strip() for line in lines if line.strip().startswith('example 1:')] == [
        f'example 1: learned SCENE-{n}; nothing matched' for n in (1, 2, 3)]
    assert sum('recognised SCENE-' in line and '(1.00); nothing learned' in line
               for line in lines if 'example' in line) == 6
    assert '  row of cones: recognised SCENE-2 (1.00); nothing learned' in lines
    partial = next(line for line in lines if line.startswith('  plate scene and a cone:'))
    assert 'recognised SCENE-3 (0.' in partial and 'nothing learned' in partial
    assert next(line for line in lines if line.startswith('  stack and row:')).startswith(
        '  stack and row: learned SCENE-4; recognised SCENE-1')
    assert any(line.startswith('  SCENE-4 (new arrangement')
               and 'contains SCENE-1, SCENE-2' in line for line in lines), lines
    armor.call(directive('t', 'scenes_demo_test', 'DROP'))


def test_the_thresholds_are_node_parameters(own_node):
    """Set on the running node, sit_position_threshold changes which relations a scene has."""
    from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
    from rcl_interfaces.srv import SetParameters
    _, _, transport = own_node
    setter = transport.node.create_client(SetParameters, '/scenes/armor_service/set_parameters')
    assert setter.wait_for_service(timeout_sec=60)

    def position_threshold(value):
        done = setter.call_async(SetParameters.Request(parameters=[Parameter(
            name='sit_position_threshold', value=ParameterValue(
                type=ParameterType.PARAMETER_DOUBLE, double_value=value))]))
        deadline = time.monotonic() + 60
        while not done.done() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert done.result().results[0].successful
    assert transport.call(directive('t', 'wide', 'CREATE', '', '',
                                    [SIT, 'false', 'PELLET', 'false']), timeout_s=120).success
    client = SceneClient(transport.node, '/scenes')
    try:
        position_threshold(1.0)
        # 0.8 apart on X and Z: within 1 m, so along X, Y and Z of each other, neither behind
        # nor above (with 0.03 they are behind and above, and along nothing).
        assert client.ok('wide', TWO_SPHERES).learned_scene_name == 'SCENE-1'
    finally:
        position_threshold(0.03)
        client.close()
        transport.node.destroy_client(setter)
    [learned] = [json.loads(line) for line in query(transport, 'wide', 'QUERY SIT SCENES')]
    assert {r['relation'] for r in learned['restrictions']} == {'alongX', 'alongY', 'alongZ'}
