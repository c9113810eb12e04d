# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Reading the EXPLAIN commands' answers (docs/explanations.md).

What the clients and the web view share.

An answer holds one line per axiom, ``<n> <kind> <axiom>``: ``n`` numbers the justification
(the lines of one justification share it), ``kind`` is ``asserted``, ``axiom`` or ``rule``. A
rule reads ``<label>: <rule> | ?x=a, ?y=b``. ``parse`` makes an ``Explanation`` of it and
``read_aloud`` a sentence a person can say.
"""

import re
from dataclasses import dataclass, field
from typing import Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple

from armor_contract.scenes import short_name

# An answer line: "<justification number> <kind> <axiom>" (docs/explanations.md).
_LINE = re.compile(r'^(\d+) (asserted|axiom|rule) (.*)$', re.DOTALL)
_BRACKETED_IRI = re.compile(r'<([^<>\s]+)>')
_RULE = re.compile(r'^(?P<label>.*?): (?P<rule>.*?)(?: \| (?P<bindings>.*))?$', re.DOTALL)
_NAME = re.compile(r'\??[A-Za-z_][\w.\-]*')
_KEYWORDS = frozenset({'and', 'or', 'not', 'some', 'only', 'value', 'min', 'max', 'exactly',
                       'Self', 'that', 'inverse', 'Type', 'SubClassOf', 'EquivalentTo',
                       'DisjointWith', 'InverseOf', 'Domain', 'Range', 'SubPropertyOf',
                       'Characteristics', 'SameAs', 'DifferentFrom', 'Functional', 'Symmetric',
                       'Transitive', 'InverseFunctional', 'Reflexive', 'Irreflexive',
                       'Asymmetric', 'DisjointClasses', 'EquivalentClasses', 'Thing', 'Nothing'})


@dataclass(frozen=True)
class ExplainedAxiom:
    """One axiom of a justification.

    Attributes:
        kind: ``asserted`` (a fact of the ABox), ``axiom`` (the schema) or ``rule``.
        text: the axiom in Manchester syntax (a rule: ``label: body -> head``).
        rule: a rule's label ('' otherwise; ``-`` for a rule without one).
        bindings: a rule's variables as they fired it, ``{'?r': 'robot1'}``.
    """

    kind: str
    text: str
    rule: str = ''
    bindings: Dict[str, str] = field(default_factory=dict)

    @property
    def asserted(self) -> bool:
        """Whether the axiom is a fact asserted in the ABox."""
        return self.kind == 'asserted'


class Explanation(list):
    """The justifications of a fact: a list of lists of ExplainedAxiom, one per justification.

    Attributes:
        fact: the fact explained, in Manchester syntax (``bedroom Type OccupiedRoom``).
        asserted: whether the fact is itself asserted (its one justification is the fact).
    """

    def __init__(self, justifications: Iterable[List[ExplainedAxiom]], fact: str, asserted: bool):
        super().__init__(justifications)
        self.fact = fact
        self.asserted = asserted

    def names(self) -> List[str]:
        """Every entity name the explanation mentions, sorted (to ask for their labels)."""
        found = set(_names(self.fact))
        for justification in self:
            for axiom in justification:
                found.update(_names(axiom.text))
                found.update(v for v in axiom.bindings.values())
        return sorted(found)

    def read_aloud(self, labels: Optional[Mapping[str, str]] = None) -> str:
        """The explanation as a sentence a person can read aloud, the same every time.

        Args:
            labels: entity name -> rdfs:label (``ref.labels(*explanation.names())``); names
                without a label are said as they are.
        """
        return read_aloud(self.fact, list(self), labels or {})


def parse(lines: Sequence[str], fact: str, asserted: bool, iris: bool) -> Explanation:
    """An EXPLAIN answer's lines as an Explanation (entities as short names unless ``iris``)."""
    grouped: Dict[str, List[ExplainedAxiom]] = {}
    for line in lines:
        match = _LINE.match(line)
        if match is None:
            raise ValueError(f'not an explanation line: {line!r}')
        number, kind, text = match.groups()
        text = text if iris else _BRACKETED_IRI.sub(lambda m: short_name(m.group(1)), text)
        grouped.setdefault(number, []).append(_axiom(kind, text))
    return Explanation((grouped[n] for n in sorted(grouped, key=int)), fact, asserted)


def _axiom(kind: str, text: str) -> ExplainedAxiom:
    if kind != 'rule':
        return ExplainedAxiom(kind, text)
    match = _RULE.match(text)
    assert match is not None  # the pattern matches any text
    bindings = {}
    for pair in (match.group('bindings') or '').split(', '):
        if '=' in pair:
            variable, value = pair.split('=', 1)
            bindings[variable] = value
    return ExplainedAxiom(kind, match.group('rule'), match.group('label'), bindings)


def _names(text: str) -> List[str]:
    return [w for w in _NAME.findall(text) if not w.startswith('?') and w not in _KEYWORDS
            and not w.isdigit()]


# Read-aloud: each axiom shape says what it means in words.
_SENTENCES: List[Tuple[re.Pattern, str]] = [
    (re.compile(r'^(\S+) Type (\S+)$'), '{0} is {a1}'),
    (re.compile(r'^(\S+) SubClassOf (.+)$'), '{A0} is {a1}'),
    (re.compile(r'^(\S+) EquivalentTo (.+)$'), '{A0} is exactly {a1}'),
    (re.compile(r'^(\S+) DisjointWith (\S+)$'), 'nothing is both {a0} and {a1}'),
    (re.compile(r'^(\S+) InverseOf (\S+)$'), '{0} is the inverse of {1}'),
    (re.compile(r'^(\S+) SubPropertyOf (\S+)$'), '{0} implies {1}'),
    (re.compile(r'^(\S+) Domain (.+)$'), 'whatever {0} something is {a1}'),
    (re.compile(r'^(\S+) Range (.+)$'), 'whatever something {0} is {a1}'),
    (re.compile(r'^(\S+) SameAs (\S+)$'), '{0} is the same as {1}'),
    (re.compile(r'^(\S+) DifferentFrom (\S+)$'), '{0} is not {1}'),
    (re.compile(r'^(\S+) Characteristics: (\S+)$'), '{0} is {lower1}'),
    (re.compile(r'^(Functional|InverseFunctional|Symmetric|Asymmetric|Transitive|Reflexive|'
                r'Irreflexive): (\S+)$'), '{1} is {lower0}'),
    (re.compile(r'^(\S+) (\S+) (\S+)$'), '{0} {1} {2}'),
]


def _article(phrase: str) -> str:
    return ('an ' if phrase[:1].lower() in 'aeiou' else 'a ') + phrase


def _say_axiom(axiom: ExplainedAxiom, say: Callable[[str], str]) -> str:
    if axiom.kind == 'rule':
        label = say(axiom.rule) if axiom.rule != '-' else 'a rule'
        bound = ', '.join(f'{v} is {say(x)}' for v, x in sorted(axiom.bindings.items()))
        return f'the rule {label} applies' + (f' where {bound}' if bound else '')
    for pattern, template in _SENTENCES:
        match = pattern.match(axiom.text)
        if match:
            parts = [say(p) for p in match.groups()]
            words = {f'a{i}': _article(p) for i, p in enumerate(parts)}
            words.update({f'A{i}': _article(p) for i, p in enumerate(parts)})
            words['A0'] = 'every ' + parts[0] if template.startswith('{A0} is {a1}') else \
                _article(parts[0])
            words.update({f'lower{i}': p.lower() for i, p in enumerate(parts)})
            return template.format(*parts, **words)
    return say(axiom.text)


def read_aloud(fact: str, justifications: List[List[ExplainedAxiom]],
               labels: Mapping[str, str]) -> str:
    """The sentence of ``Explanation.read_aloud``: the fact, 'because', each justification."""
    def say(text: str) -> str:
        return _NAME.sub(lambda m: labels.get(m.group(0), m.group(0)), text)

    said_fact = _say_axiom(ExplainedAxiom('asserted', fact), say)
    if not justifications:
        return said_fact + '.'
    reasons = []
    for justification in justifications:
        clauses = [_say_axiom(a, say) for a in justification]
        if len(clauses) == 1 and clauses[0] == said_fact:
            reasons.append('it was asserted')
            continue
        reasons.append(clauses[0] if len(clauses) == 1
                       else ', '.join(clauses[:-1]) + ' and ' + clauses[-1])
    return said_fact + ' because ' + '; or because '.join(reasons) + '.'
