# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Issue 21 item 5: an EL reasoner on an ontology outside OWL 2 EL, over ROS 2.

LOAD says the profile and the count and kinds of axioms the reasoner will not use; every
successful query of that reference says its answer may be incomplete, and it is: ELK misses
what only those axioms entail, where Openllet finds it.
"""

import re

import pytest

NS = 'http://www.example.org/coverage#'
# An EL definition (Placed) beside one axiom of each kind ELK skips, each defining a class only
# it can fill: a universal restriction, a cardinality with an inverse, a negation, a SWRL rule.
ONTOLOGY = f"""Prefix(:=<{NS}>)
Ontology(<http://www.example.org/coverage>
Declaration(Class(:Robot)) Declaration(Class(:Location)) Declaration(Class(:Room))
Declaration(Class(:Corridor)) Declaration(Class(:SafeRobot)) Declaration(Class(:Crowded))
Declaration(Class(:NotRoom)) Declaration(Class(:Visited)) Declaration(Class(:Placed))
Declaration(ObjectProperty(:isIn)) Declaration(ObjectProperty(:contains))
SubClassOf(:Room :Location) SubClassOf(:Corridor :Location) DisjointClasses(:Room :Corridor)
InverseObjectProperties(:contains :isIn)
EquivalentClasses(:SafeRobot ObjectIntersectionOf(:Robot ObjectAllValuesFrom(:isIn :Room)))
EquivalentClasses(:Crowded ObjectIntersectionOf(:Room ObjectMinCardinality(2 :contains :Robot)))
EquivalentClasses(:NotRoom ObjectIntersectionOf(:Location ObjectComplementOf(:Room)))
EquivalentClasses(:Placed ObjectIntersectionOf(:Robot ObjectSomeValuesFrom(:isIn :Location)))
DLSafeRule(Body(ClassAtom(:Robot Variable(<urn:swrl:var#r>))
    ObjectPropertyAtom(:isIn Variable(<urn:swrl:var#r>) Variable(<urn:swrl:var#l>)))
    Head(ClassAtom(:Visited Variable(<urn:swrl:var#l>))))
ClassAssertion(:Robot :r1) ClassAssertion(:Room :kitchen) ClassAssertion(:Corridor :hall)
ObjectPropertyAssertion(:isIn :r1 :kitchen)
)
"""


@pytest.fixture
def coverage_file(armor_node):
    path = armor_node.scratch / 'coverage.ofn'
    path.write_text(ONTOLOGY)
    return str(path)


def _load(call, reference, path, reasoner):
    loaded = call(reference, 'LOAD FILE', path, 'http://www.example.org/coverage', 'false',
                  reasoner, 'false')
    assert loaded.success, loaded.error_description
    return loaded


def test_elk_on_an_ontology_outside_el(call, coverage_file):
    try:
        loaded = _load(call, 'coverage_elk', coverage_file, 'ELK')
        report = loaded.error_description
        assert report.startswith('profile: outside OWL 2 EL; ELK does not use 5 axioms outside '
                                 'OWL 2 EL: '), report
        for kind in ('universal restriction (only)', 'cardinality', 'negation (not)', 'SWRL rule',
                     'InverseObjectProperties axiom'):
            assert f'1 {kind}' in report, report
        assert 'answers may be incomplete; ' in report, report

        placed = call('coverage_elk', 'QUERY IND CLASS', 'Placed')
        assert placed.queried_objects == [f'<{NS}r1>']
        assert placed.error_description.startswith('may be incomplete: ELK does not use 5 axioms')
        for query in ('Visited', 'NotRoom'):
            answer = call('coverage_elk', 'QUERY IND CLASS', query)
            assert answer.success and answer.queried_objects == []
            assert 'may be incomplete' in answer.error_description

        complete = _load(call, 'coverage_pellet', coverage_file, 'PELLET')
        # Openllet uses every axiom; the rule makes it reason on the whole ontology, and LOAD says so.
        # The rules' schema is not Horn (a definition a model may satisfy in several ways): whole.
        assert re.fullmatch(r'profile: OWL 2 DL; \d+ classes, classified in [^;]+; '
                            r'reasoning on the whole ontology: SWRL rules with an axiom that lets '
                            r'a model choose \(not Horn\): EquivalentClasses\(.+',
                            complete.error_description), complete.error_description
        visited = call('coverage_pellet', 'QUERY IND CLASS', 'Visited')
        assert visited.queried_objects == [f'<{NS}kitchen>'] and visited.error_description == ''
        assert call('coverage_pellet', 'QUERY IND CLASS', 'NotRoom').queried_objects == [
            f'<{NS}hall>']
    finally:
        call('coverage_elk', 'DROP')
        call('coverage_pellet', 'DROP')


def test_jfact_says_it_does_not_use_swrl(call, coverage_file):
    try:
        loaded = _load(call, 'coverage_jfact', coverage_file, 'JFACT')
        assert re.fullmatch(r'profile: OWL 2 DL; JFACT does not use 1 axiom: 1 SWRL rule; '
                            r'answers may be incomplete; \d+ classes, classified in [^;]+; '
                            r'reasoning on the whole ontology: SWRL rules \(JFact does not '
                            r'evaluate them; PELLET and HERMIT references do\)',
                            loaded.error_description), loaded.error_description
        visited = call('coverage_jfact', 'QUERY IND CLASS', 'Visited')
        assert visited.queried_objects == []
        assert visited.error_description == ('may be incomplete: JFACT does not use 1 axiom: '
                                             '1 SWRL rule')
    finally:
        call('coverage_jfact', 'DROP')


def test_a_change_outside_el_is_said_from_then_on(call):
    try:
        created = call('coverage_created', 'CREATE', 'http://www.example.org/created', 'false',
                       'ELK', 'false')
        assert created.success and created.error_description == ''
        assert call('coverage_created', 'ADD IND CLASS', 'r1', 'Robot').success
        assert call('coverage_created', 'QUERY IND CLASS', 'Robot').error_description == ''
        rule = 'Robot(?r) -> Agent(?r)'
        assert call('coverage_created', 'ADD SWRL', 'agents', rule).success
        note = call('coverage_created', 'QUERY IND CLASS', 'Robot').error_description
        assert note == 'may be incomplete: ELK does not use 1 axiom outside OWL 2 EL: 1 SWRL rule'
        assert call('coverage_created', 'REMOVE SWRL', 'agents', rule).success
        assert call('coverage_created', 'QUERY IND CLASS', 'Robot').error_description == ''
    finally:
        call('coverage_created', 'DROP')
