# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A client of ``sit_armor_injected`` for any rclpy program, as ROS 1 SIT clients called it.

>>> client = SceneServiceClient(node)                                     # doctest: +SKIP
>>> response = client.call('table', [('SPHERE', [0, 0, 0]), ('CONE', [0.3, 0, 0, 0, 0, 1])], 0.9)
>>> response.learned_scene_name, [(r.class_name, r.similarity) for r in response.recognitions]
('SCENE-1', [])

The node must be spun elsewhere (an executor on another thread, as armor_client's transport
does): calls wait for their answer on a threading event.
"""

import threading
import time
from typing import Iterable

from armor_contract.scenes import element_fields, ElementLike, SCENE_SERVICE
from armor_contract.services import SERVICE_QOS
from sit_armor_injected_msgs.msg import SceneElement
from sit_armor_injected_msgs.srv import ArmorSITScene


class SceneServiceClient:
    """Calls sit_armor_injected of the ARMOR node in ``namespace`` ('' for the caller's own).

    The first call waits (at most ``wait_s``) until the service has answered once: Fast DDS drops
    a response sent before the server has matched the client's reader.
    """

    def __init__(self, node, namespace: str = '', wait_s: float = 60.0):
        self._node = node
        self.name = f'{namespace.rstrip("/")}/{SCENE_SERVICE}' if namespace else SCENE_SERVICE
        self._client = node.create_client(ArmorSITScene, self.name, qos_profile=SERVICE_QOS)
        self._wait_s = wait_s
        self._ready = False

    def call(self, reference: str, elements: Iterable[ElementLike], threshold: float,
             client_name: str = '', timeout_s: float = 120.0) -> ArmorSITScene.Response:
        """Send one scene; the response (success, exit_code, error_description included)."""
        if not self._ready:
            self._wait_until_answered()
        request = ArmorSITScene.Request(
            onto_reference=reference, learning_treshold=float(threshold), client_name=client_name,
            scene_elements=[SceneElement(type=kind, features=features)
                            for kind, features in map(element_fields, elements)])
        return self._send(request, timeout_s)

    def close(self) -> None:
        self._node.destroy_client(self._client)

    def _wait_until_answered(self) -> None:
        deadline = time.monotonic() + self._wait_s
        while True:
            left = deadline - time.monotonic()
            if left <= 0 or not self._client.wait_for_service(timeout_sec=left):
                raise TimeoutError(f'{self.name} did not answer within {self._wait_s:.0f} s: '
                                   'is the ARMOR node running with its sit extension?')
            try:
                # A request with no reference is answered at once (201) and changes nothing.
                self._send(ArmorSITScene.Request(), min(5.0, max(0.5, left)))
                self._ready = True
                return
            except TimeoutError:
                continue

    def _send(self, request, timeout_s: float):
        done = threading.Event()
        future = self._client.call_async(request)
        future.add_done_callback(lambda _: done.set())
        if not done.wait(timeout_s):
            self._client.remove_pending_request(future)
            raise TimeoutError(f'no answer from {self.name} within {timeout_s} s')
        return future.result()
