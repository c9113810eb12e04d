# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""ArmorClient of ROS 1 armor_api: a client id and a reference name, with three helpers.

``client.manipulation`` changes the ontology, ``client.query`` asks it, ``client.utils``
loads, saves, mounts and syncs; ``client.call()`` sends any directive and returns the raw
response.
"""

from typing import Any, Optional, Sequence, Tuple

from armor_client.armor_api.armor_manipulation_client import ArmorManipulationClient
from armor_client.armor_api.armor_query_client import ArmorQueryClient
from armor_client.armor_api.armor_utils_client import ArmorUtilsClient
from armor_client.batch import list_error
from armor_client.errors import error_for
from armor_client.transport import ArmorTransport, directive, DIRECTIVE_SERVICE, LIST_SERVICE
from armor_msgs.msg import ArmorDirectiveRes
from rclpy.node import Node


class ArmorClient:
    """One client of one reference, as in ROS 1 armor_api.

    Args:
        client_id: the client name sent with every directive (the mount holder's name).
        reference_name: the reference the directives address.
        service_name: the one-directive service; its namespace is where the node is.
        serial_service_name: the list service, in the same namespace.
        timeout: seconds to wait for the service to answer the first time (ROS 1 waited for
            the service only, 5 s by default; ROS 2 discovery needs longer on a busy machine).
        node: a node this program already spins; None to create and spin one (ROS 2 has no
            process-wide node like rospy's).
        call_timeout: longest wait for each answer (None: as long as it takes; ROS 1 had no
            limit).

    Raises:
        ValueError: the service names do not end in ARMOR's service names.
    """

    def __init__(self, client_id: str, reference_name: str,
                 service_name: str = '/' + DIRECTIVE_SERVICE,
                 serial_service_name: str = '/' + LIST_SERVICE, timeout: float = 30,
                 node: Optional[Node] = None, call_timeout: Optional[float] = None):
        namespace, _, base = service_name.rpartition('/')
        serial_namespace, _, serial_base = serial_service_name.rpartition('/')
        names_ok = (base, serial_base) == (DIRECTIVE_SERVICE, LIST_SERVICE)
        if not names_ok or namespace != serial_namespace:
            raise ValueError(f'service names must be <namespace>/{DIRECTIVE_SERVICE} and '
                             f'<namespace>/{LIST_SERVICE}, got {service_name!r} and '
                             f'{serial_service_name!r}')
        self.client_id = client_id
        self.reference_name = reference_name
        self.timeout = timeout
        self.call_timeout = call_timeout
        # An absolute name keeps its leading '/', as ROS 1 resolved it.
        if not namespace and service_name.startswith('/'):
            namespace = '/'
        self.transport = ArmorTransport(node=node, namespace=namespace, service_wait_s=timeout)
        self.manipulation = ArmorManipulationClient(self)
        self.query = ArmorQueryClient(self)
        self.utils = ArmorUtilsClient(self)

    def call(self, command: str, first_spec: str, second_spec: str,
             args_list: Sequence[Any]) -> ArmorDirectiveRes:
        """Send one directive on this client's reference and return ARMOR's raw response.

        Args:
            command: the command word.
            first_spec: the primary spec ('' for none).
            second_spec: the secondary spec ('' for none).
            args_list: the arguments.

        Returns:
            The response, whatever its exit code.

        Raises:
            ArmorServiceCallError: the service could not be called or did not answer in time.
        """
        return self.transport.call(
            directive(self.client_id, self.reference_name, command, first_spec, second_spec,
                      args_list), timeout_s=self.call_timeout)

    def call_checked(self, command: str, first_spec: str, second_spec: str,
                     args_list: Sequence[Any]) -> ArmorDirectiveRes:
        """Like call(), raising when the directive failed.

        Args:
            command: the command word.
            first_spec: the primary spec.
            second_spec: the secondary spec.
            args_list: the arguments.

        Returns:
            The successful response.

        Raises:
            ArmorServiceInternalError: ARMOR answered with an error (its code in ``.code``).
            ArmorServiceCallError: the service could not be called.
        """
        response = self.call(command, first_spec, second_spec, args_list)
        if not response.success:
            raise error_for(response)
        return response

    def call_list_checked(self,
                          directives: Sequence[Tuple[str, str, str, Sequence[Any]]]) -> bool:
        """Send directives on this client's reference as one atomic list.

        Args:
            directives: (command, first_spec, second_spec, args_list) for each directive.

        Returns:
            Whether the ontology is consistent after the list.

        Raises:
            ArmorServiceInternalError: a directive failed, so none of them changed anything.
            ArmorServiceCallError: the service could not be called.
        """
        answer = self.transport.call_list(
            [directive(self.client_id, self.reference_name, *words) for words in directives],
            timeout_s=self.call_timeout)
        if not answer.success:
            raise list_error(answer.armor_responses)
        return answer.is_consistent

    def close(self) -> None:
        """Release the service clients (and the node, if this object created it)."""
        self.transport.close()
