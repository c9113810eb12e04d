# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The scene service of the ARMOR node: ``sit_armor_injected`` (docs/scenes.md).

ROS 1 SIT's service, as an extension of the node: each request becomes the directive
``SIT SCENE`` of the core's SIT plugin, sent by the node's own path (size limits, mount check,
the reference's lock, the journal, exit codes), with the node's thresholds
``sit_position_threshold`` and ``sit_axis_threshold`` written into it, so that a restart replays
it exactly. The answer's classes are short names (SCENE-3), as ROS 1 SIT answered them.
"""

from armor_contract import scenes
from armor_contract.services import SERVICE_QOS
from sit_armor_injected_msgs.msg import Recognition
from sit_armor_injected_msgs.srv import ArmorSITScene

POSITION_PARAMETER = 'sit_position_threshold'
AXIS_PARAMETER = 'sit_axis_threshold'


class SceneService:
    """Started by the node with its ExtensionContext (armor_service.extensions)."""

    def __init__(self, context):
        """Serve sit_armor_injected on the node."""
        self.context = context
        context.create_service(ArmorSITScene, scenes.SCENE_SERVICE, self.scene,
                               qos_profile=SERVICE_QOS)
        context.logger.info(
            f'serving {context.node.resolve_service_name(scenes.SCENE_SERVICE)} '
            '(sit_armor_injected_msgs/srv/ArmorSITScene)')

    def scene(self, request, response):
        """Recognise the request's scene, learning it if new; ARMOR's code and reason if not."""
        node = self.context.node
        arguments = scenes.scene_arguments(
            request.scene_elements, request.learning_treshold,
            node.get_parameter(POSITION_PARAMETER).value, node.get_parameter(AXIS_PARAMETER).value)
        answer = self.context.call(request.onto_reference, *scenes.SCENE_WORDS, arguments,
                                   client_name=request.client_name or None)
        response.success = answer.success
        response.exit_code = answer.exit_code
        response.error_description = answer.error_description
        if answer.success:
            outcome = scenes.read_answer(answer.queried_objects, scenes.short_name)
            response.learned_scene_name = outcome.learned_scene_name
            response.recognitions = [
                Recognition(class_name=r.class_name, similarity=r.similarity)
                for r in outcome.recognitions]
        return response
