# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""``ArmorClient.utils`` of ROS 1 armor_api: loading, saving, mounting, buffers and logs."""

from typing import Any

from armor_client.errors import ArmorServiceCallError


class ArmorUtilsClient:
    """The utility helper of an ArmorClient.

    Args:
        client: the ArmorClient whose reference and client id are used.
    """

    def __init__(self, client: Any):
        self._client = client

    def apply_buffered_changes(self) -> bool:
        """Apply the buffered manipulations of a buffered reference (APPLY).

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused (e.g. 102, mounted by another client).
        """
        return self._client.call_checked('APPLY', '', '', []).is_consistent

    def sync_buffered_reasoner(self) -> bool:
        """Apply the buffer and bring a buffered reasoner up to date (REASON).

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused.
        """
        return self._client.call_checked('REASON', '', '', []).is_consistent

    def save_ref_with_inferences(self, filepath: str) -> None:
        """Save the ontology with its inferences (SAVE INFERENCE); the live one is unchanged.

        Args:
            filepath: the file on the node's machine (a relative path is the caller's).

        Raises:
            ArmorServiceInternalError: the file could not be written (209, 213).
        """
        self.save(filepath, inference=True)

    def save(self, filepath: str, inference: bool = False) -> None:
        """Save the ontology (SAVE, or SAVE INFERENCE with inference=True).

        Args:
            filepath: the file on the node's machine ('' = the file it was loaded from; a
                relative path is the caller's).
            inference: also write the inferred knowledge.

        Raises:
            ArmorServiceInternalError: the file could not be written (209, 213).
        """
        self._client.call_checked('SAVE', 'INFERENCE' if inference else '', '', [filepath])

    def load_ref_from_file(self, owl_file_path: str, iri: str, buffered_manipulation: bool = False,
                           reasoner: str = 'PELLET', buffered_reasoner: bool = False,
                           mounted: bool = False) -> None:
        """Load an ontology file as this client's reference (LOAD FILE [MOUNTED]).

        Args:
            owl_file_path: the file on the node's machine (a relative path is the caller's).
            iri: the ontology IRI plain names resolve against ('' = the file's own).
            buffered_manipulation: queue changes until apply_buffered_changes().
            reasoner: PELLET (the default, as in armor_api), HERMIT, JFACT or ELK.
            buffered_reasoner: the reasoner sees changes only at sync_buffered_reasoner().
            mounted: also mount this client on the reference.

        Raises:
            ArmorServiceInternalError: the file could not be loaded (209, 213, 214) or the
                reasoner is unknown (210).
        """
        self._client.call_checked('LOAD', 'FILE', 'MOUNTED' if mounted else '',
                                  [owl_file_path, iri, str(bool(buffered_manipulation)).lower(),
                                   reasoner, str(bool(buffered_reasoner)).lower()])

    def mount_on_ref(self) -> None:
        """Mount this client on the reference (MOUNT).

        Raises:
            ArmorServiceInternalError: another client holds the mount (203).
        """
        self._client.call_checked('MOUNT', '', '', [])

    def unmount_from_ref(self) -> None:
        """Release this client's mount (UNMOUNT).

        Raises:
            ArmorServiceInternalError: this client does not hold the mount (203).
        """
        self._client.call_checked('UNMOUNT', '', '', [])

    def set_log_to_terminal(self, switch: bool) -> None:
        """Turn the node's logging of directives to its screen on or off (LOG SCREEN).

        Args:
            switch: True to log.

        Raises:
            ArmorServiceInternalError: ARMOR refused.
        """
        self._client.call_checked('LOG', 'SCREEN', 'ON' if switch else 'OFF', [])

    def set_log_to_file(self, switch: bool, filepath: str = '') -> None:
        """Turn logging of directives to a file on or off (LOG FILE).

        Args:
            switch: True to log.
            filepath: the log file on the node's machine (needed to switch on; a relative
                path is the caller's).

        Raises:
            ArmorServiceCallError: switching on without a file path (nothing is sent).
            ArmorServiceInternalError: ARMOR refused (213 for a path outside allowed_dirs).
        """
        if switch and not filepath:
            raise ArmorServiceCallError('set_log_to_file(True) needs the path of the log file')
        if switch:
            self._client.call_checked('LOG', 'FILE', 'ON', [filepath])
        else:
            self._client.call_checked('LOG', 'FILE', 'OFF', [])
