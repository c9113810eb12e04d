# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Changes collected and sent as one atomic armor_interface_serialized_srv call.

The service runs the list in order; when one directive fails, the earlier ones are undone and
the later ones are not run (their responses say 212), so a batch happens entirely or not at
all.
"""

from typing import Any, List, Optional, Sequence

from armor_client.answers import Words
from armor_client.errors import ArmorRolledBackError, ArmorServiceInternalError, error_for
from armor_client.operations import Manipulations
from armor_client.transport import ArmorTransport, directive
from armor_contract.exit_codes import ExitCode
from armor_msgs.msg import ArmorDirectiveReq


class BatchBase(Manipulations):
    """The queue shared by Batch and AsyncBatch: every manipulation method appends to it.

    Args:
        client_name: the client the directives speak for.
        reference: the reference they change.
    """

    def __init__(self, client_name: str, reference: str):
        self.client_name = client_name
        self.reference = reference
        self.requests: List[ArmorDirectiveReq] = []
        self.consistent: Optional[bool] = None

    def __len__(self) -> int:
        return len(self.requests)

    def _execute(self, words: Words, args: Sequence[Any], parse: Any) -> None:
        self.requests.append(directive(self.client_name, self.reference, *words, args))

    def _finish(self, answer: Any) -> bool:
        """Check a list answer: the consistency after it, or the failing directive's error."""
        if not answer.success:
            raise list_error(answer.armor_responses)
        self.requests = []
        self.consistent = answer.is_consistent
        return answer.is_consistent


def list_error(responses: Sequence[Any]) -> ArmorServiceInternalError:
    """The error of a failed list: the one directive that failed, with its position.

    Args:
        responses: the list's armor_responses.

    Returns:
        The failing directive's error, with ``index`` (its position in the list) and
        ``responses`` (all of them) added.
    """
    for index, response in enumerate(responses):
        if not response.success and response.exit_code != ExitCode.ROLLED_BACK:
            error = error_for(response)
            error.index = index
            break
    else:
        error = ArmorRolledBackError('the list was rolled back', ExitCode.ROLLED_BACK)
        error.index = None
    error.responses = list(responses)
    return error


class Batch(BatchBase):
    """Manipulations of one reference, sent together as one atomic list.

    Every manipulation method of Reference is here too; it queues the directive instead of
    sending it. ``send()`` (or the end of a with block) sends the list.

    Args:
        transport: the transport that sends the list.
        client_name: the client the directives speak for.
        reference: the reference they change.
        timeout_s: longest wait for the answer.
    """

    def __init__(self, transport: ArmorTransport, client_name: str, reference: str,
                 timeout_s: Optional[float] = None):
        super().__init__(client_name, reference)
        self._transport = transport
        self._timeout_s = timeout_s

    def send(self) -> bool:
        """Send the queued directives as one atomic list and empty the queue.

        Returns:
            Whether the ontology is consistent after the list.

        Raises:
            ArmorServiceInternalError: a directive failed (the subclass of its exit code), so
                nothing changed; ``index`` says which one, ``responses`` has every response.
            ArmorServiceCallError: the service could not be called.
        """
        return self._finish(self._transport.call_list(self.requests, timeout_s=self._timeout_s))

    def __enter__(self) -> 'Batch':
        return self

    def __exit__(self, exc_type: Any, *exc: Any) -> None:
        if exc_type is None and self.requests:
            self.send()
