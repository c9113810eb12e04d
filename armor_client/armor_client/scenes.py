# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Teaching a reference scenes by demonstration: the SIT plugin's commands (docs/scenes.md).

Mixed into every reference class (Reference, AsyncReference) like the contract's commands: each
method builds a directive and says how to read the answer; ``_execute`` sends it. A scene goes
as the directive SIT SCENE through armor_interface_srv, so it is this client's own change (its
mount applies, it is journaled and announced like any other).

>>> with Armor('teacher') as armor:                                       # doctest: +SKIP
...     table = armor.reference('table')
...     answer = table.learn_scene([('SPHERE', [0, 0, 0]), ('CONE', [0.3, 0, 0, 0, 0, 1])], 0.9)
...     answer.learned_scene_name, answer.recognitions
('SCENE-1', [])
"""

import json
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, Iterable, List, Sequence, Tuple

from armor_client.plugin_faces import written_for
from armor_contract.scenes import (AXIS_THRESHOLD, ElementLike, POSITION_THRESHOLD,
                                   read_answer, Recognition, SCENE_WORDS, scene_arguments,
                                   SceneAnswer)


@dataclass(frozen=True)
class SceneClass:
    """A learned scene class as QUERY SIT SCENES describes it.

    Attributes:
        name: its name (SCENE-3; its IRI if the reference answers IRIs).
        cardinality: card(class), the sum of its restrictions' minimums.
        definition: its definition in words ("at least 2 CONE along X; ...").
        restrictions: each restriction: property, relation, subject, type, min, words.
        superscenes: the nearest learned classes it is a subclass of (the scenes it contains).
        equivalent: learned classes the reasoner finds equivalent to it.
    """

    name: str
    cardinality: int
    definition: str
    restrictions: List[Dict[str, Any]] = field(default_factory=list)
    superscenes: List[str] = field(default_factory=list)
    equivalent: List[str] = field(default_factory=list)


class Scenes:
    """Scene identification and tagging: recognise a scene, learn it when it is new."""

    answers: Any

    def _execute(self, words: Tuple[str, str, str], args: Sequence[Any],
                 parse: Callable[[Any], Any]) -> Any:
        raise NotImplementedError

    def learn_scene(self, elements: Iterable[ElementLike], threshold: float, *,
                    position_threshold: float = POSITION_THRESHOLD,
                    axis_threshold: float = AXIS_THRESHOLD) -> SceneAnswer:
        """Recognise a scene; learn it if no learned class is similar enough (SIT SCENE).

        Args:
            elements: each a (type, features) pair, a {'type', 'features'} mapping or a
                sit_armor_injected_msgs SceneElement: type SPHERE, PLANE, CONE or CYLINDER,
                features the centre [x, y, z], for the last three optionally followed by the axis.
            threshold: in [0, 1]: the scene is learned unless a recognised class has a
                similarity above it (ROS 1's learningTreshold).
            position_threshold: metres, for right/behind/above and along an axis (the node's
                scene service uses its parameter sit_position_threshold instead).
            axis_threshold: for parallel, perpendicular and coaxial.

        Returns:
            SceneAnswer: learned_scene_name ('' when nothing was learned) and recognitions
            (class_name, similarity), most similar first.
        """
        return self._execute(
            SCENE_WORDS, scene_arguments(elements, threshold, position_threshold, axis_threshold),
            lambda response: read_answer(response.queried_objects, self.answers.entity))

    @written_for('QUERY SIT SCENES')
    def scene_classes(self) -> List[SceneClass]:
        """The learned scene classes, in the order they were learned (QUERY SIT SCENES)."""
        return self._execute(('QUERY', 'SIT', 'SCENES'), [], self._scene_classes)

    @written_for('QUERY SIT RECENT')
    def recent_scenes(self) -> List[Dict[str, Any]]:
        """The last scenes of this reference since the core started (QUERY SIT RECENT).

        Newest first. Each is a dict: elements, cardinality, learned, and recognitions, each
        with its similarity and an explanation (per restriction: the relations that meet it).
        """
        return self._execute(('QUERY', 'SIT', 'RECENT'), [],
                             lambda response: [json.loads(t) for t in response.queried_objects])

    def _scene_classes(self, response: Any) -> List[SceneClass]:
        classes = []
        for text in response.queried_objects:
            item = json.loads(text)
            classes.append(SceneClass(
                self.answers.entity(item['class']), item['cardinality'], item['definition'],
                item['restrictions'], [self.answers.entity(c) for c in item['superscenes']],
                [self.answers.entity(c) for c in item['equivalent']]))
        return classes


__all__ = ['Recognition', 'SceneAnswer', 'SceneClass', 'Scenes']
