# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Scene identification and tagging (docs/scenes.md): what the scene service and clients share.

A scene goes to the core as the directive ``SIT SCENE`` with four arguments: the learning
threshold, the position threshold (metres), the axis threshold, and the elements as a JSON array
of ``{"type": ..., "features": [...]}``. Its answer holds ``learned <class>`` (when a class was
learned) and one ``recognised <class> <similarity>`` per recognised class, most similar first.
"""

import json
import math
from dataclasses import dataclass, field
from typing import Any, Iterable, List, Mapping, Sequence, Tuple, Union

# The ROS service (relative to the node's namespace): sit_armor_injected_msgs/srv/ArmorSITScene.
SCENE_SERVICE = 'sit_armor_injected'
SCENE_WORDS = ('SIT', 'SCENE', '')
# The thresholds of ROS 1 SIT: the node's sit_position_threshold and sit_axis_threshold default
# to them, and clients of the directive send them unless told otherwise.
POSITION_THRESHOLD = 0.03
AXIS_THRESHOLD = 0.05
TYPES = ('SPHERE', 'PLANE', 'CONE', 'CYLINDER')

# An element: a SceneElement message, a mapping {'type': ..., 'features': [...]}, or a pair
# (type, features).
ElementLike = Union[Any, Mapping[str, Any], Tuple[str, Sequence[float]]]


@dataclass(frozen=True)
class Recognition:
    """A scene class the scene was recognised as.

    Attributes:
        class_name: the class (a short name such as SCENE-3, or its IRI if asked for).
        similarity: card(class) / card(scene), in [0, 1].
    """

    class_name: str
    similarity: float


@dataclass(frozen=True)
class SceneAnswer:
    """What SIT SCENE answered.

    Attributes:
        learned_scene_name: the class learned from the scene ('' when none was).
        recognitions: every class it was recognised as, most similar first.
    """

    learned_scene_name: str = ''
    recognitions: List[Recognition] = field(default_factory=list)


def element_fields(element: ElementLike) -> Tuple[str, List[float]]:
    """The type and features of an element given in any of the accepted forms."""
    if isinstance(element, Mapping):
        return str(element['type']), [float(v) for v in element['features']]
    if isinstance(element, tuple):
        kind, features = element
        return str(kind), [float(v) for v in features]
    return str(element.type), [float(v) for v in element.features]


def elements_argument(elements: Iterable[ElementLike]) -> str:
    """The elements as SIT SCENE's fourth argument.

    JSON: no type can smuggle in another element; NaN and infinities go as such, for the core
    to refuse with a clear reason.
    """
    sent = []
    for element in elements:
        kind, features = element_fields(element)
        sent.append({'type': kind, 'features': features})
    return json.dumps(sent, allow_nan=True)


def number_argument(value: float) -> str:
    """A threshold as an argument.

    repr keeps every digit; NaN and infinities go as the core reads them, to be refused with a
    clear reason.
    """
    value = float(value)
    if math.isnan(value):
        return 'NaN'
    if math.isinf(value):
        return 'Infinity' if value > 0 else '-Infinity'
    return repr(value)


def scene_arguments(elements: Iterable[ElementLike], learning_threshold: float,
                    position_threshold: float = POSITION_THRESHOLD,
                    axis_threshold: float = AXIS_THRESHOLD) -> List[str]:
    """SIT SCENE's four arguments."""
    return [number_argument(learning_threshold), number_argument(position_threshold),
            number_argument(axis_threshold), elements_argument(elements)]


def read_answer(queried_objects: Sequence[str], name=lambda entity: entity) -> SceneAnswer:
    """SIT SCENE's answer; ``name`` turns each answered class into the name wanted."""
    learned = ''
    recognitions = []
    for line in queried_objects:
        word, _, rest = line.partition(' ')
        if word == 'learned':
            learned = name(rest)
        elif word == 'recognised':
            entity, _, similarity = rest.rpartition(' ')
            recognitions.append(Recognition(name(entity), float(similarity)))
    return SceneAnswer(learned, recognitions)


def short_name(entity: str) -> str:
    """SCENE-3 of ``<http://www.emarolab.it/sit/simple#SCENE-3>`` (a short name stays as it is)."""
    iri = entity[1:-1] if entity.startswith('<') and entity.endswith('>') else entity
    for separator in ('#', '/'):
        if separator in iri:
            return iri.rsplit(separator, 1)[1]
    return iri
