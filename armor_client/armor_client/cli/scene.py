# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Show a reference a scene: recognise it, and learn it as a new scene class if it is new.

  armor scene REF FILE [--threshold 0.9] [--json]
  armor scene REF --classes            # the learned scene classes, in words

FILE is YAML or JSON ('-' reads stdin): a list of elements, or a mapping with ``elements``
(ROS 1's ``sceneElements`` and ``scene_elements`` too) and optionally ``threshold``
(``learningTreshold``, ``learning_treshold``). Each element has ``type`` (SPHERE, PLANE, CONE,
CYLINDER) and ``features`` (centre x y z, then for PLANE, CONE and CYLINDER optionally the axis):

  threshold: 0.9
  elements:
    - {type: SPHERE, features: [0.0, 0.0, 0.0]}
    - {type: CONE, features: [-0.8, -0.8, 0.0, 0, 0, 1]}

The scene goes as the directive SIT SCENE (docs/scenes.md). Exit status: 0 answered, 1
refused (code and reason on stderr), 2 no service.
"""

import argparse
import json
import sys
from typing import Any, Dict, List, Tuple

from armor_client.cli.common import (add_connection_arguments, connect, print_table,
                                     reporting_errors)
from armor_contract.scenes import AXIS_THRESHOLD, POSITION_THRESHOLD

_ELEMENT_KEYS = ('elements', 'scene_elements', 'sceneElements')
_THRESHOLD_KEYS = ('threshold', 'learning_treshold', 'learningTreshold')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the options of armor scene.

    Args:
        parser: the verb's parser.
    """
    parser.add_argument('reference', metavar='REF', help='reference name')
    parser.add_argument('file', metavar='FILE', nargs='?',
                        help="the scene, YAML or JSON ('-': standard input)")
    parser.add_argument('--threshold', type=float, default=None,
                        help="learn unless a recognised class is more similar than this "
                             "(default: the file's, else 0.9)")
    parser.add_argument('--position-threshold', type=float, default=POSITION_THRESHOLD,
                        help='metres, for right/behind/above and along '
                             f'(default {POSITION_THRESHOLD})')
    parser.add_argument('--axis-threshold', type=float, default=AXIS_THRESHOLD,
                        help=f'for parallel, perpendicular, coaxial (default {AXIS_THRESHOLD})')
    parser.add_argument('--classes', action='store_true',
                        help='list the learned scene classes instead, each defined in words')
    parser.add_argument('--json', action='store_true', help='print the answer as JSON')
    add_connection_arguments(parser)


def read_scene(text: str) -> Tuple[List[Dict[str, Any]], Any]:
    """The elements and the threshold (None if not given) a scene file holds.

    Raises:
        ValueError: the file does not hold a scene.
    """
    import yaml
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as error:
        raise ValueError(f'not YAML or JSON: {error}') from error
    threshold = None
    if isinstance(data, dict):
        threshold = next((data[k] for k in _THRESHOLD_KEYS if k in data), None)
        data = next((data[k] for k in _ELEMENT_KEYS if k in data), None)
        if data is None:
            raise ValueError(f'no elements: give one of the keys {", ".join(_ELEMENT_KEYS)}')
    if not isinstance(data, list) or not all(
            isinstance(e, dict) and 'type' in e and isinstance(e.get('features'), list)
            for e in data):
        raise ValueError('the elements must be a list of {type: ..., features: [numbers]}')
    return data, threshold


@reporting_errors('scene')
def run(args: argparse.Namespace) -> int:
    """Send the scene (or ask for the classes) and print the answer.

    Args:
        args: the parsed command line.

    Returns:
        The exit status.
    """
    if args.classes:
        return _classes(args)
    if args.file is None:
        print('armor scene: give a scene FILE (or --classes)', file=sys.stderr)
        return 1
    try:
        text = sys.stdin.read() if args.file == '-' else open(args.file, encoding='utf-8').read()
        elements, threshold = read_scene(text)
        threshold = float(args.threshold if args.threshold is not None
                          else threshold if threshold is not None else 0.9)
    except (OSError, ValueError, TypeError) as error:
        print(f'armor scene: {args.file}: {error}', file=sys.stderr)
        return 1
    with connect(args) as armor:
        answer = armor.reference(args.reference).learn_scene(
            elements, threshold, position_threshold=args.position_threshold,
            axis_threshold=args.axis_threshold)
    if args.json:
        print(json.dumps({'learned_scene_name': answer.learned_scene_name,
                          'recognitions': [{'class_name': r.class_name,
                                            'similarity': r.similarity}
                                           for r in answer.recognitions]}))
        return 0
    print(f'learned {answer.learned_scene_name}' if answer.learned_scene_name
          else 'nothing learned')
    if answer.recognitions:
        print_table(['recognised as', 'similarity'],
                    [[r.class_name, f'{r.similarity:.3f}'] for r in answer.recognitions])
    return 0


def _classes(args: argparse.Namespace) -> int:
    with connect(args) as armor:
        classes = armor.reference(args.reference).scene_classes()
    if args.json:
        print(json.dumps([vars(c) for c in classes]))
        return 0
    print_table(['scene class', 'cardinality', 'contains', 'definition'],
                [[c.name, c.cardinality, ', '.join(c.superscenes) or '-', c.definition]
                 for c in classes])
    return 0
