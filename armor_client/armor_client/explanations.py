# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Why a reference believes something: the EXPLAIN commands (docs/explanations.md).

Mixed into every reference class like the contract's commands. Each method answers an
``Explanation``: the justifications of a fact (the minimal sets of the reference's axioms that
entail it), each a list of ``ExplainedAxiom`` in Manchester syntax, and a rendering a person can
read aloud:

>>> with Armor('robot') as armor:                                          # doctest: +SKIP
...     ref = armor.reference('map')
...     why = ref.explain_instance('bedroom', 'OccupiedRoom')
...     why.read_aloud(ref.labels(*why.names()))
'bedroom is an OccupiedRoom because alice isIn bedroom, contains is the inverse of isIn, ...'
"""

from typing import Any, Callable, Dict, List, Sequence, Tuple

from armor_client.values import short_name, typed_argument
from armor_contract.explanations import ExplainedAxiom, Explanation, parse

__all__ = ['Explanations', 'Explanation', 'ExplainedAxiom', 'parse']


class Explanations:
    """Why a fact holds: its justifications, computed by the node's reasoner on a module."""

    answers: Any

    def _execute(self, words: Tuple[str, str, str], args: Sequence[Any],
                 parse: Callable[[Any], Any]) -> Any:
        raise NotImplementedError

    def _explain(self, words: Tuple[str, str, str], args: List[Any], fact: str,
                 justifications: int) -> Explanation:
        iris = self.answers.iris

        def explanation(response: Any) -> Explanation:
            asserted = response.error_description.startswith('asserted')
            return parse(response.queried_objects, fact, asserted, iris)
        return self._execute(words, args + [str(justifications)], explanation)

    def explain_instance(self, individual: str, cls: str, justifications: int = 1) -> Explanation:
        """Why the individual is an instance of the class (EXPLAIN IND CLASS).

        Args:
            individual: the individual.
            cls: the class.
            justifications: how many justifications at most (1 to 20).

        Returns:
            The justifications. Raises ArmorNotEntailedError (227) when the fact does not
            hold, ArmorTimeLimitError (211) when the reasoner time limit ran out first (its
            ``response.queried_objects`` holds the justifications found by then: ``parse``
            reads them).
        """
        return self._explain(('EXPLAIN', 'IND', 'CLASS'), [individual, cls],
                             f'{short_name(individual)} Type {short_name(cls)}', justifications)

    def explain_object_property(self, prop: str, subject: str, value: str,
                                justifications: int = 1) -> Explanation:
        """Why the subject has the object property value (EXPLAIN OBJECTPROP IND).

        Args:
            prop: the object property.
            subject: the individual that has the value.
            value: the individual it is related to.
            justifications: how many justifications at most (1 to 20).
        """
        return self._explain(('EXPLAIN', 'OBJECTPROP', 'IND'), [prop, subject, value],
                             f'{short_name(subject)} {short_name(prop)} {short_name(value)}',
                             justifications)

    def explain_data_property(self, prop: str, individual: str, value: Any, datatype: str = '',
                              justifications: int = 1) -> Explanation:
        """Why the individual has the data property value (EXPLAIN DATAPROP IND).

        Args:
            prop: the data property.
            individual: the individual.
            value: the value (int, float, bool, str: its type follows, as in add_data_value).
            datatype: ARMOR's type name (INTEGER, LONG...) to override the value's own.
            justifications: how many justifications at most (1 to 20).
        """
        kind, text = typed_argument(value, datatype)
        return self._explain(('EXPLAIN', 'DATAPROP', 'IND'), [prop, individual, kind, text],
                             f'{short_name(individual)} {short_name(prop)} {text}', justifications)

    def explain_subclass(self, sub: str, sup: str, justifications: int = 1) -> Explanation:
        """Why the first class is a subclass of the second (EXPLAIN CLASS CLASS)."""
        return self._explain(('EXPLAIN', 'CLASS', 'CLASS'), [sub, sup],
                             f'{short_name(sub)} SubClassOf {short_name(sup)}', justifications)

    def explain_inconsistency(self, justifications: int = 1) -> Explanation:
        """The sets of axioms that make the reference inconsistent (EXPLAIN INCONSISTENCY)."""
        return self._explain(('EXPLAIN', 'INCONSISTENCY', ''), [],
                             'Thing SubClassOf Nothing', justifications)

    def labels(self, *names: str) -> Dict[str, str]:
        """The rdfs:label of each named entity that has one (the smallest, when several)."""
        if not names:
            return self._execute(('QUERY', 'SPARQL', 'FORMATTED'),
                                 ['ASK { FILTER(false) }'], lambda response: {})
        values = ' '.join(f':{n}' if ':' not in n else f'<{n}>' for n in names)
        query = ('SELECT ?e ?l WHERE { VALUES ?e { ' + values + ' } ?e rdfs:label ?l } '
                 'ORDER BY ?e ?l')

        def labels(response: Any) -> Dict[str, str]:
            found: Dict[str, str] = {}
            for row in self.answers.rows(response):
                if row.get('e') is not None and row.get('l') is not None:
                    found.setdefault(short_name(str(row['e'])), str(row['l']))
            return found
        return self._execute(('QUERY', 'SPARQL', 'FORMATTED'), [query], labels)
