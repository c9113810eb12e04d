# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A tiny extension of the ARMOR node: one service and one topic of its own.

- service ``armor_hello/references`` (std_srvs/Trigger): the loaded references, as
  ``GET ALL REFS`` answers them;
- topic ``armor_hello/directives`` (armor_msgs/ArmorDirectiveReq): directives sent without
  waiting for an answer (a sensor that only reports), each answered on ``armor_hello/answers``
  (armor_msgs/ArmorDirectiveRes).

Both go to the core through the node's own path, so mount checks, locks, the journal and exit
codes apply to them exactly as to armor_interface_srv.
"""

from armor_msgs.msg import ArmorDirectiveReq, ArmorDirectiveRes
from std_srvs.srv import Trigger


class HelloExtension:
    """Started by the node with its ExtensionContext (armor_service.extensions)."""

    def __init__(self, context):
        """Create the service, the subscription and the publisher on the node."""
        self.context = context
        context.create_service(Trigger, 'armor_hello/references', self.references)
        self.answers = context.create_publisher(ArmorDirectiveRes, 'armor_hello/answers', 10)
        context.create_subscription(ArmorDirectiveReq, 'armor_hello/directives', self.directive,
                                    10)
        context.logger.info('serving armor_hello/references and armor_hello/directives')

    def references(self, request, response):
        """Answer the loaded references, space-separated in the Trigger's message."""
        answer = self.context.call('', 'GET', 'ALL', 'REFS')
        response.success = answer.success
        response.message = (' '.join(answer.queried_objects) if answer.success
                            else f'{answer.exit_code} {answer.error_description}')
        return response

    def directive(self, request):
        """Send a directive that came over the topic and publish ARMOR's answer."""
        self.answers.publish(self.context.directive(request))

    def close(self):
        """Called by the node at shutdown."""
        self.context.logger.info('stopped')
