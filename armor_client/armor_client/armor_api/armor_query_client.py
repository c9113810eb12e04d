# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""``ArmorClient.query`` of ROS 1 armor_api: questions, answered as ARMOR's strings.

Answers are what ARMOR sends (``<http://...#kitchen>``, ``"80"^^xsd:integer``), as armor_api
returned them; armor_client.Reference answers Python values instead.
"""

from typing import Any, List

from armor_client.values import entity_iri, short_name

OWL_THING = '<http://www.w3.org/2002/07/owl#Thing>'


class ArmorQueryClient:
    """The query helper of an ArmorClient.

    Args:
        client: the ArmorClient whose reference and client id are used.
    """

    def __init__(self, client: Any):
        self._client = client

    def ind_b2_class(self, class_name: str) -> List[str]:
        """The individuals that belong to a class, asserted and inferred (QUERY IND CLASS).

        Args:
            class_name: the class.

        Returns:
            The individuals as ARMOR writes them.

        Raises:
            ArmorServiceInternalError: ARMOR refused the query.
        """
        return list(self._client.call_checked('QUERY', 'IND', 'CLASS',
                                              [class_name]).queried_objects)

    def dataprop_b2_ind(self, dataprop_name: str, ind_name: str) -> List[str]:
        """An individual's values of a data property (QUERY DATAPROP IND).

        Args:
            dataprop_name: the data property.
            ind_name: the individual.

        Returns:
            The literals as ARMOR writes them (``"80"^^xsd:integer``).

        Raises:
            ArmorServiceInternalError: ARMOR refused the query.
        """
        return list(self._client.call_checked('QUERY', 'DATAPROP', 'IND',
                                              [dataprop_name, ind_name]).queried_objects)

    def objectprop_b2_ind(self, objectprop_name: str, ind_name: str) -> List[str]:
        """The individuals related to one by an object property (QUERY OBJECTPROP IND).

        Args:
            objectprop_name: the object property.
            ind_name: the subject.

        Returns:
            The related individuals as ARMOR writes them.

        Raises:
            ArmorServiceInternalError: ARMOR refused the query.
        """
        return list(self._client.call_checked('QUERY', 'OBJECTPROP', 'IND',
                                              [objectprop_name, ind_name]).queried_objects)

    def check_ind_exists(self, ind_name: str) -> bool:
        """Whether the ontology has an individual of that name.

        Args:
            ind_name: a plain or prefixed name, or a full IRI (``<...>`` or bare).

        Returns:
            True when an individual of that name exists (whatever its classes).

        Raises:
            ArmorServiceInternalError: ARMOR refused the query.
        """
        individuals = self.ind_b2_class(OWL_THING)
        wanted = entity_iri(ind_name)
        if '#' in wanted or '/' in wanted:
            return any(entity_iri(individual) == wanted for individual in individuals)
        # A plain or prefixed name (dev:robot1): compare the part after the prefix.
        local = wanted.rpartition(':')[2]
        return any(short_name(individual) == local for individual in individuals)
