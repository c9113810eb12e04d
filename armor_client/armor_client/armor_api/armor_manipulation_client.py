# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""``ArmorClient.manipulation`` of ROS 1 armor_api: changes to the ontology.

Every method returns the ontology's consistency as ARMOR reports it (with a buffered reasoner,
as of the last sync), raises ArmorServiceInternalError when ARMOR refuses the change and
ArmorServiceCallError when the service cannot be called.
"""

from typing import Any, Sequence

from armor_client.errors import ArmorServiceInternalError
from armor_client.values import split_literal


class ArmorManipulationClient:
    """The manipulation helper of an ArmorClient.

    Args:
        client: the ArmorClient whose reference and client id are used.
    """

    def __init__(self, client: Any):
        self._client = client

    def _change(self, command: str, first_spec: str, second_spec: str,
                args: Sequence[Any]) -> bool:
        return self._client.call_checked(command, first_spec, second_spec, args).is_consistent

    def add_ind_to_class(self, ind_name: str, class_name: str) -> bool:
        """Add an individual to a class (ADD IND CLASS); both are created if needed.

        Args:
            ind_name: the individual.
            class_name: the class.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change.
        """
        return self._change('ADD', 'IND', 'CLASS', [ind_name, class_name])

    def remove_ind_from_class(self, ind_name: str, class_name: str) -> bool:
        """Remove an individual from a class (REMOVE IND CLASS).

        Args:
            ind_name: the individual.
            class_name: the class.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change.
        """
        return self._change('REMOVE', 'IND', 'CLASS', [ind_name, class_name])

    def disj_inds_of_class(self, class_name: str) -> bool:
        """Make all individuals of a class pairwise different (DISJOINT IND CLASS).

        Args:
            class_name: the class.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change.
        """
        return self._change('DISJOINT', 'IND', 'CLASS', [class_name])

    def disj_inds(self, inds: Sequence[str]) -> bool:
        """Make the given individuals pairwise different (DISJOINT IND).

        Not in armor_api itself: the widely copied addition of the ARMOR course material.

        Args:
            inds: two or more individuals.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change.
        """
        return self._change('DISJOINT', 'IND', '', list(inds))

    def add_objectprop_to_ind(self, objectprop_name: str, ind_name: str,
                              value_obj_name: str) -> bool:
        """Relate an individual to another (ADD OBJECTPROP IND).

        Args:
            objectprop_name: the object property.
            ind_name: the subject.
            value_obj_name: the related individual.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change.
        """
        return self._change('ADD', 'OBJECTPROP', 'IND',
                            [objectprop_name, ind_name, value_obj_name])

    def add_dataprop_to_ind(self, dataprop_name: str, ind_name: str, value_type: str,
                            value: Any) -> bool:
        """Give an individual a data property value (ADD DATAPROP IND).

        Args:
            dataprop_name: the data property.
            ind_name: the individual.
            value_type: INTEGER, INT, FLOAT, LONG, DOUBLE, STRING, BOOLEAN, BOOL or xsd:...
            value: the value (sent as str).

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change (101 for a value the type
                cannot hold).
        """
        return self._change('ADD', 'DATAPROP', 'IND', [dataprop_name, ind_name, value_type, value])

    def add_batch_dataprop_to_ind(self, ind_name: str,
                                  dataprops: Sequence[Sequence[Any]]) -> bool:
        """Give an individual several data property values, all or none (one atomic list).

        Args:
            ind_name: the individual.
            dataprops: [prop_name, value_type, value] for each value.

        Returns:
            Whether the ontology is consistent afterwards.

        Raises:
            ArmorServiceInternalError: one value was refused, so none was added.
        """
        return self._client.call_list_checked(
            [('ADD', 'DATAPROP', 'IND', [prop, ind_name, value_type, value])
             for prop, value_type, value in dataprops])

    def remove_batch_dataprop_to_ind(self, ind_name: str,
                                     dataprops: Sequence[Sequence[Any]]) -> bool:
        """Remove several data property values of an individual, all or none.

        Args:
            ind_name: the individual.
            dataprops: [prop_name, value_type, value] for each value.

        Returns:
            Whether the ontology is consistent afterwards.

        Raises:
            ArmorServiceInternalError: one removal was refused, so none happened.
        """
        return self._client.call_list_checked(
            [('REMOVE', 'DATAPROP', 'IND', [prop, ind_name, value_type, value])
             for prop, value_type, value in dataprops])

    def remove_dataprop_from_ind(self, dataprop_name: str, ind_name: str, value_type: str,
                                 value: Any) -> bool:
        """Remove a data property value (REMOVE DATAPROP IND).

        Args:
            dataprop_name: the data property.
            ind_name: the individual.
            value_type: the type it was added with.
            value: the value.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change.
        """
        return self._change('REMOVE', 'DATAPROP', 'IND',
                            [dataprop_name, ind_name, value_type, value])

    def remove_objectprop_from_ind(self, objectprop_name: str, ind_name: str,
                                   value: str) -> bool:
        """Remove a relation between two individuals (REMOVE OBJECTPROP IND).

        Args:
            objectprop_name: the object property.
            ind_name: the subject.
            value: the related individual.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change.
        """
        return self._change('REMOVE', 'OBJECTPROP', 'IND', [objectprop_name, ind_name, value])

    def replace_objectprop_b2_ind(self, objectprop_name: str, ind_name: str, new_value: str,
                                  old_value: str) -> bool:
        """Replace the individual related by an object property (REPLACE OBJECTPROP IND).

        Args:
            objectprop_name: the object property.
            ind_name: the subject.
            new_value: the individual it becomes related to.
            old_value: the individual it stops being related to.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change.
        """
        return self._change('REPLACE', 'OBJECTPROP', 'IND',
                            [objectprop_name, ind_name, new_value, old_value])

    def replace_dataprop_b2_ind(self, dataprop_name: str, ind_name: str, value_type: str,
                                new_value: Any, old_value: Any) -> bool:
        """Replace a data property value (REPLACE DATAPROP IND).

        Args:
            dataprop_name: the data property.
            ind_name: the individual.
            value_type: the type of both values.
            new_value: the value it gets.
            old_value: the value it loses.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: ARMOR refused the change.
        """
        return self._change('REPLACE', 'DATAPROP', 'IND',
                            [dataprop_name, ind_name, value_type, new_value, old_value])

    def replace_one_dataprop_b2_ind(self, dataprop_name: str, ind_name: str, value_type: str,
                                    new_value: Any) -> bool:
        """Set the only value of a single-valued data property, whatever it was.

        Adds the value when there was none. The old value is removed with its own datatype
        and the new one added in one atomic list.

        Args:
            dataprop_name: the data property.
            ind_name: the individual.
            value_type: the type of the new value.
            new_value: the new value.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: the individual has several values (exit_code None: a
                check of this client), or ARMOR refused the change.
        """
        values = self._client.query.dataprop_b2_ind(dataprop_name, ind_name)
        self._require_single(values, dataprop_name, ind_name)
        add = ('ADD', 'DATAPROP', 'IND', [dataprop_name, ind_name, value_type, new_value])
        if not values:
            return self._client.call_list_checked([add])
        old_lexical, old_type = split_literal(values[0])
        remove = ('REMOVE', 'DATAPROP', 'IND', [dataprop_name, ind_name, old_type, old_lexical])
        return self._client.call_list_checked([remove, add])

    def replace_one_objectprop_b2_ind(self, objectprop_name: str, ind_name: str,
                                      new_value: str) -> bool:
        """Set the only individual related by a single-valued object property.

        Adds the relation when there was none.

        Args:
            objectprop_name: the object property.
            ind_name: the subject.
            new_value: the individual it becomes related to.

        Returns:
            Whether the ontology is consistent.

        Raises:
            ArmorServiceInternalError: the individual has several values (exit_code None), or
                ARMOR refused the change.
        """
        values = self._client.query.objectprop_b2_ind(objectprop_name, ind_name)
        self._require_single(values, objectprop_name, ind_name)
        if not values:
            return self.add_objectprop_to_ind(objectprop_name, ind_name, new_value)
        # The answer names the old value as the service accepts it back (<IRI> or short name).
        return self.replace_objectprop_b2_ind(objectprop_name, ind_name, new_value, values[0])

    @staticmethod
    def _require_single(values: Sequence[str], prop: str, ind_name: str) -> None:
        if len(values) > 1:
            raise ArmorServiceInternalError(
                f'{ind_name} has {len(values)} values of {prop} ({", ".join(values)}); '
                'replace_one_* is for properties with at most one value')
