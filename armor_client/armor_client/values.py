# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Between ARMOR's strings and Python values.

ARMOR answers entities as ``<http://example.org/onto#Robot>`` (or ``Robot`` when the node runs
with ``full_entity_iri:=false``) and literals as ``"80"^^xsd:integer`` or ``"text"@en``. These
functions turn answers into short names, IRIs, ``int``, ``float``, ``bool`` and ``str``, and
turn Python values into the (type, lexical value) pair that ADD DATAPROP IND takes.
"""

import math
from typing import Tuple, Union

Value = Union[int, float, bool, str]

_INTEGER_TYPES = frozenset((
    'integer', 'int', 'long', 'short', 'byte', 'nonNegativeInteger', 'positiveInteger',
    'nonPositiveInteger', 'negativeInteger', 'unsignedLong', 'unsignedInt', 'unsignedShort',
    'unsignedByte'))
_REAL_TYPES = frozenset(('float', 'double', 'decimal'))
_XSD = 'http://www.w3.org/2001/XMLSchema#'


def short_name(entity: str) -> str:
    """The name of an entity without its namespace.

    Args:
        entity: ``<http://x.org/o#Robot>``, ``http://x.org/o/Robot`` or already ``Robot``.

    Returns:
        ``Robot``: what follows the last ``#`` (else the last ``/``) of the IRI.
    """
    iri = entity_iri(entity)
    for separator in ('#', '/'):
        if separator in iri:
            return iri.rsplit(separator, 1)[1]
    return iri


def entity_iri(entity: str) -> str:
    """The IRI of an answered entity without its angle brackets.

    Args:
        entity: ``<http://x.org/o#Robot>`` (a short name comes back unchanged).

    Returns:
        ``http://x.org/o#Robot``.
    """
    if entity.startswith('<') and entity.endswith('>'):
        return entity[1:-1]
    return entity


def is_literal(answer: str) -> bool:
    """Whether an answer string is a literal (``"..."^^type`` or ``"..."@lang``)."""
    return answer.startswith('"') and ('"^^' in answer or '"@' in answer or answer.endswith('"'))


def split_literal(answer: str) -> Tuple[str, str]:
    """Split a literal answer into its lexical form and its datatype.

    Args:
        answer: ``"80"^^xsd:integer``, ``"hi"@en`` or ``"hi"``.

    Returns:
        (lexical form, datatype): ``('80', 'xsd:integer')``; the datatype of a language-tagged
        string is ``rdf:langString``, of a plain quoted string ``xsd:string``.

    Raises:
        ValueError: the answer is not a literal.
    """
    if not answer.startswith('"'):
        raise ValueError(f'not a literal: {answer!r}')
    # The lexical form may itself contain quotes, so split at the last closing quote.
    typed = answer.rfind('"^^')
    if typed > 0:
        datatype = answer[typed + 3:]
        if datatype.startswith('<' + _XSD):
            datatype = 'xsd:' + datatype[len(_XSD) + 1:-1]
        return answer[1:typed], datatype
    tagged = answer.rfind('"@')
    if tagged > 0:
        return answer[1:tagged], 'rdf:langString'
    if len(answer) >= 2 and answer.endswith('"'):
        return answer[1:-1], 'xsd:string'
    raise ValueError(f'not a literal: {answer!r}')


def literal_value(answer: str) -> Value:
    """The Python value of a literal answer.

    Args:
        answer: ``"80"^^xsd:integer`` and the like.

    Returns:
        ``int`` for the xsd integer types, ``float`` for float/double/decimal, ``bool`` for
        xsd:boolean, and the lexical form as ``str`` for everything else (strings, dates, ...).

    Raises:
        ValueError: the answer is not a literal, or its lexical form does not fit its type.
    """
    lexical, datatype = split_literal(answer)
    local = datatype[4:] if datatype.startswith('xsd:') else ''
    if local in _INTEGER_TYPES:
        return int(lexical)
    if local in _REAL_TYPES:
        return _xsd_real(lexical)
    if local == 'boolean':
        if lexical not in ('true', 'false', '1', '0'):
            raise ValueError(f'not an xsd:boolean: {lexical!r}')
        return lexical in ('true', '1')
    return lexical


def answer_value(answer: str, iris: bool = False) -> Value:
    """One answer as a Python value: literals converted, entities named.

    Args:
        answer: an entity or a literal as ARMOR writes it.
        iris: give entities as full IRIs instead of short names.

    Returns:
        The literal's value, or the entity's short name (its IRI when iris is True).
    """
    if answer.startswith('"'):
        return literal_value(answer)
    return entity_iri(answer) if iris else short_name(answer)


def typed_argument(value: Value, datatype: str = '') -> Tuple[str, str]:
    """The (type, value) arguments of ADD/REMOVE/REPLACE DATAPROP IND for a Python value.

    Args:
        value: the value; bool, int, float and str pick their type when datatype is empty.
        datatype: ARMOR's type name (STRING, INTEGER, LONG, DOUBLE, FLOAT, BOOLEAN) or an
            ``xsd:`` datatype, to override the choice (for example LONG for a timestamp).

    Returns:
        (type, lexical value), for example ``('INTEGER', '80')`` or ``('BOOLEAN', 'true')``.

    Raises:
        ValueError: a float that is not finite without an explicit datatype.
    """
    if isinstance(value, bool):
        return datatype or 'BOOLEAN', 'true' if value else 'false'
    if isinstance(value, int):
        return datatype or 'INTEGER', str(value)
    if isinstance(value, float):
        if not datatype and not math.isfinite(value):
            raise ValueError(f'{value} has no xsd:double lexical form ARMOR accepts')
        return datatype or 'DOUBLE', repr(value)
    return datatype or 'STRING', str(value)


def _xsd_real(lexical: str) -> float:
    special = {'INF': math.inf, '+INF': math.inf, '-INF': -math.inf, 'NaN': math.nan}
    return special[lexical] if lexical in special else float(lexical)
