# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The web view's "why?": the justifications of an inferred fact (docs/explanations.md).

  GET /api/references/{ref}/explain?kind=instance&arg=IND&arg=CLASS     EXPLAIN IND CLASS
  GET /api/references/{ref}/explain?kind=objectprop&arg=PROP&arg=S&arg=O EXPLAIN OBJECTPROP IND
  GET /api/references/{ref}/explain?kind=subclass&arg=SUB&arg=SUPER      EXPLAIN CLASS CLASS

Answers ``{"success", "exit_code", "description", "justifications": [[{"kind", "text",
"rule", "bindings"}]], "sentence"}``: the sentence is the read-aloud rendering, with the
entities' rdfs:labels. Read-only QUERY-kind directives, shared and kept per revision as the
page's other reads.
"""

import json
import re
from typing import Any, Awaitable, Callable, Dict, List

from aiohttp import web

from armor_contract.explanations import parse

# kind -> (the directive's words, its argument count)
_KINDS = {'instance': (('EXPLAIN', 'IND', 'CLASS'), 2),
          'objectprop': (('EXPLAIN', 'OBJECTPROP', 'IND'), 3),
          'subclass': (('EXPLAIN', 'CLASS', 'CLASS'), 2)}
_FACTS = {'instance': '{0} Type {1}', 'objectprop': '{1} {0} {2}',
          'subclass': '{0} SubClassOf {1}'}

_IRI = re.compile(r'<([^<>\s]+)>')

# (reference, words and arguments) -> the core's answer (armor_msgs fields), kept per revision.
Directive = Callable[..., Awaitable[Dict[str, Any]]]


class ExplanationRoutes:
    """The route, answered through the server's shared QUERY path."""

    def __init__(self, directive: Directive, shared: Callable[..., Awaitable[web.Response]]):
        self._directive = directive
        self._shared = shared

    def add_to(self, app: web.Application, prefix: str) -> None:
        app.router.add_get(prefix + '/explain', self.explain)

    async def explain(self, request: web.Request) -> web.Response:
        reference = request.match_info['reference']
        kind = request.query.get('kind', '')
        args = request.query.getall('arg', [])
        if kind not in _KINDS or len(args) != _KINDS[kind][1]:
            raise web.HTTPBadRequest(text=json.dumps({'success': False, 'exit_code': 207,
                                                      'description': 'kind must be one of '
                                                      + ', '.join(sorted(_KINDS))
                                                      + ' with its arguments'}),
                                     content_type='application/json')
        words = _KINDS[kind][0]
        bracketed = [f'<{a}>' if '://' in a and not a.startswith('<') else a for a in args]

        async def fetch() -> Dict[str, Any]:
            answer = await self._directive(reference, *words, *bracketed)
            body = {'success': answer['success'], 'exit_code': answer['exit_code'],
                    'description': answer['error_description'], 'timeout': answer['timeout'],
                    'justifications': [], 'sentence': ''}
            if not answer['queried_objects']:
                return body
            fact = _FACTS[kind].format(*(a.rsplit('#', 1)[-1].rsplit('/', 1)[-1] for a in args))
            explanation = parse(answer['queried_objects'], fact,
                                answer['error_description'].startswith('asserted'), iris=True)
            body['justifications'] = [[axiom.__dict__ for axiom in j] for j in explanation]
            short = parse(answer['queried_objects'], fact, explanation.asserted, iris=False)
            named = sorted(set(_IRI.findall(' '.join(answer['queried_objects']))))
            body['sentence'] = short.read_aloud(await self._labels(reference, named))
            return body
        return await self._shared(('explain', reference, kind, *args), fetch, reference)

    async def _labels(self, reference: str, iris: List[str]) -> Dict[str, str]:
        """Short name -> rdfs:label of the entities named (by full IRI) in the explanation."""
        entities = ' '.join(f'<{i}>' for i in iris if '://' in i)
        if not entities:
            return {}
        query = ('SELECT ?e ?l WHERE { VALUES ?e { ' + entities + ' } ?e rdfs:label ?l } '
                 'ORDER BY ?e ?l')
        answer = await self._directive(reference, 'QUERY', 'SPARQL', 'FORMATTED', query)
        rows: List[Dict[str, str]] = [{}]
        for item in answer.get('sparql_queried_objects', []) if answer['success'] else []:
            if item['key']:
                rows[-1][item['key']] = item['value']
            else:  # an item with an empty key ends a row (the last row may end without one)
                rows.append({})
        labels: Dict[str, str] = {}
        for row in rows:
            if 'e' in row and 'l' in row:
                name = row['e'].strip('<>').rsplit('#', 1)[-1].rsplit('/', 1)[-1]
                text = row['l']
                labels.setdefault(name, text.split('"')[1] if text.startswith('"') else text)
        return labels
