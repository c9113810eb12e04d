#!/usr/bin/env python3
# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Teaching the robot table-top arrangements by demonstration (docs/scenes.md).

A perception system would report primitives (spheres, planes, cones, cylinders with centres
and axes); here they are generated, each position and axis with centimetre noise, and sent to
the node's scene service ``sit_armor_injected`` as a ROS 1 SIT client would. The demo:

1. teaches three arrangements (a stack of cylinders, a row of cones, a ball on a plate beside a
   cup) from a few noisy examples each: the first example of each is learned as a new scene
   class, the others are recognised as it (the noise moves nothing past the 3 cm threshold);
2. shows a new example of the row of cones, elsewhere on the table: recognised, nothing learned;
3. shows the plate, ball and cup with a cone beside them, at threshold 0 (learn only what
   matches nothing): recognised as the plate scene with its similarity, card(class)/card(scene);
4. shows a new arrangement, the stack of cylinders beside the row of cones: neither is similar
   enough (each is only part of it), so it is learned, and the reasoner places the new class
   under both (a scene is a subclass of the scenes it contains);
and prints the learned classes in words, with the scenes each contains.

Run it against a running service (``make run`` in another terminal, then ``make demo-scenes``)
with the web view open on the Scenes tab of reference "table":
    python examples/scenes_demo.py [--reference table] [--examples 3] [--pause 1.5]
"""

import argparse
import random
import sys
import time
from typing import List, Sequence, Tuple

from armor_client import Armor, ArmorError
from sit_armor_injected.client import SceneServiceClient

SIT_IRI = 'http://www.emarolab.it/sit/simple'
NOISE_M = 0.01
THRESHOLD = 0.9
UP = (0.0, 0.0, 1.0)

Element = Tuple[str, Sequence[float]]

# Each arrangement as the robot would see it on a table (metres; x away from the robot, y to
# its left, z up), placed at an offset on the table.
ARRANGEMENTS = {
    'stack of cylinders': lambda x, y: [
        ('CYLINDER', (x, y, 0.00, *UP)), ('CYLINDER', (x, y, 0.10, *UP)),
        ('CYLINDER', (x, y, 0.20, *UP))],
    'row of cones': lambda x, y: [
        ('CONE', (x, y, 0.0, *UP)), ('CONE', (x + 0.3, y, 0.0, *UP)),
        ('CONE', (x + 0.6, y, 0.0, *UP))],
    'ball on a plate beside a cup': lambda x, y: [
        ('PLANE', (x, y, 0.0, *UP)), ('SPHERE', (x, y, 0.08)),
        ('CYLINDER', (x, y + 0.3, 0.08, *UP))],
}


def noisy(elements: List[Element], rng: random.Random) -> List[Element]:
    """The same primitives as a sensor reports them: every number off by up to a centimetre."""
    return [(kind, [round(v + rng.uniform(-NOISE_M, NOISE_M), 4) for v in features])
            for kind, features in elements]


def outcome(response) -> str:
    recognised = ', '.join(f'{r.class_name} ({r.similarity:.2f})' for r in response.recognitions)
    if response.learned_scene_name:
        return f'learned {response.learned_scene_name}' + (
            f'; recognised {recognised}, not similar enough' if recognised
            else '; nothing matched')
    return f'recognised {recognised}; nothing learned'


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--reference', default='table', help='reference to teach (made afresh)')
    parser.add_argument('--examples', type=int, default=3, help='noisy examples per arrangement')
    parser.add_argument('--pause', type=float, default=1.5,
                        help='seconds between scenes, to watch the web view')
    parser.add_argument('--seed', type=int, default=32, help='seed of the noise')
    parser.add_argument('--namespace', default='', help='namespace of the ARMOR node')
    args = parser.parse_args(argv)
    rng = random.Random(args.seed)

    with Armor('scene_demo', namespace=args.namespace) as armor:
        if args.reference in armor.references():
            armor.reference(args.reference).drop()
        table = armor.create(args.reference, SIT_IRI)
        service = SceneServiceClient(armor.transport.node, args.namespace)
        print(f'Teaching reference "{args.reference}" '
              f'(web view: the Scenes tab of "{args.reference}")')

        def show(title: str, elements: List[Element], threshold: float = THRESHOLD):
            response = service.call(args.reference, elements, threshold)
            if not response.success:
                raise SystemExit(f'{service.name} refused the scene: {response.exit_code} '
                                 f'{response.error_description}')
            print(f'  {title}: {outcome(response)}')
            sys.stdout.flush()
            time.sleep(args.pause)
            return response

        taught = {}
        for name, place in ARRANGEMENTS.items():
            print(f'{name}: {args.examples} examples with up to {NOISE_M * 100:.0f} cm of noise')
            for example in range(1, args.examples + 1):
                response = show(f'example {example}', noisy(place(0.0, 0.0), rng))
                taught.setdefault(name, response.learned_scene_name)

        print('A new row of cones, further along the table:')
        show('row of cones', noisy(ARRANGEMENTS['row of cones'](0.3, -0.4), rng))

        print('The plate, ball and cup with a cone beside them (threshold 0: learn only what '
              'matches nothing):')
        larger = noisy(ARRANGEMENTS['ball on a plate beside a cup'](0.0, 0.0)
                       + [('CONE', (0.5, 0.6, 0.0, *UP))], rng)
        show('plate scene and a cone', larger, threshold=0.0)

        print('Something never shown before: the stack of cylinders beside the row of cones:')
        show('stack and row', noisy(ARRANGEMENTS['stack of cylinders'](0.0, 0.0)
                                    + ARRANGEMENTS['row of cones'](0.0, 0.5), rng))

        print('What the robot has learned (and which learned scenes each contains):')
        for scene in table.scene_classes():
            taught_as = next((n for n, c in taught.items() if c == scene.name), 'new arrangement')
            contains = f', contains {", ".join(scene.superscenes)}' if scene.superscenes else ''
            print(f'  {scene.name} ({taught_as}, cardinality {scene.cardinality}{contains}): '
                  f'{scene.definition}')
    return 0


if __name__ == '__main__':
    try:
        sys.exit(main())
    except (ArmorError, TimeoutError) as error:
        print(f'scenes_demo: {error}', file=sys.stderr)
        sys.exit(1)
