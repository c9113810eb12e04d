# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The web view's HTTP and WebSocket server (aiohttp), on a thread and event loop of its own.

Routes (all read-only; none changes an ontology):

  GET  /                                     the page (static/index.html), its files under /static/
  GET  /api/overview                         every reference's summary
  GET  /api/references/{ref}                 one summary with the reference's properties
  GET  /api/references/{ref}/classes         the class hierarchy
  GET  /api/references/{ref}/class?iri=      one class in detail
  GET  /api/references/{ref}/individuals?search=&offset=&limit=
  GET  /api/references/{ref}/individual?iri=
  GET  /api/references/{ref}/graph?property=&property=&class=&focus=&limit= (no property: all)
  GET  /api/references/{ref}/consistency     QUERY CONSISTENCY: the explanation when inconsistent
  GET  /api/recent?reference=&limit=&all=    the last directives (all=1: the page's own too)
  POST /api/references/{ref}/dl              {"expression"}: QUERY IND DL and QUERY CLASS DL
  POST /api/references/{ref}/sparql          {"query"}: QUERY SPARQL FORMATTED
  GET  /api/references/{ref}/scenes[/recent] the SIT plugin's learned scenes, last scenes
  GET  /api/references/{ref}/explain?kind=&arg= EXPLAIN: why an inferred fact holds ("why?")
  GET  /api/live                             WebSocket: the table of revisions after each change

Bound to the loopback interface (the default), it answers only requests addressed to a loopback
name, which keeps other web sites a browser visits from reading it through DNS rebinding; its
WebSocket takes only pages of its own origin.
"""

import asyncio
import ipaddress
import json
import pathlib
import threading
from typing import Any, Awaitable, Callable, Dict, List, Optional

from aiohttp import web, WSMsgType
from armor_service.core_process import CoreUnavailable
from armor_service.web.live import LiveUpdates
from armor_service.web.reads import CoreReads, SharedAnswers, ViewFailed, WEB_CLIENT
from armor_service.web.explanations import ExplanationRoutes
from armor_service.web.scenes import SceneRoutes

STATIC = pathlib.Path(__file__).resolve().parent / 'static'
MAX_PAGES = 32
MAX_BODY_BYTES = 1 << 20
# How long an answer is reused while its reference has no new revision (a lease counts down,
# a reasoner is rebuilt, a reference gets busy without one).
OVERVIEW_MAX_AGE_S = 2.0
REFERENCE_MAX_AGE_S = 30.0
RECENT_MAX_AGE_S = 1.0
EXPLANATION_MAX_AGE_S = 5.0
# Exit codes of the core, as HTTP statuses.
_STATUS = {205: 400, 206: 404, 207: 400, 208: 400, 211: 504, 215: 400, 216: 503, 217: 409,
           224: 404}
_SECURITY_HEADERS = {
    'Content-Security-Policy': "default-src 'self'; style-src 'self' 'unsafe-inline'; "
                               "img-src 'self' data:; connect-src 'self'; frame-ancestors 'none'",
    'X-Content-Type-Options': 'nosniff',
    'Referrer-Policy': 'no-referrer',
    'Cache-Control': 'no-store',
}


class WebViewError(RuntimeError):
    """The web view could not start (its port is taken, its host cannot be bound)."""


class WebView:
    """Serves the page for a node's core on host:port until stop()."""

    def __init__(self, core, host: str, port: int, *,
                 request_timeout_s: Callable[[], Optional[float]], logger):
        """Configure; nothing listens before start().

        request_timeout_s() is the node's current wait per request (None: no limit), read at
        each request as the node reads it for ROS clients.
        """
        self._core = core
        self._host = host
        self._port = port
        self._log = logger
        self._timeout_s = request_timeout_s
        self._loop = asyncio.new_event_loop()
        self._live = LiveUpdates(self._loop)
        # One bound method, added and later removed: the core tells listeners apart by identity.
        self._on_event = self._live.on_event
        self._reads: Optional[CoreReads] = None
        self._runner: Optional[web.AppRunner] = None
        self._thread: Optional[threading.Thread] = None
        self._tasks: list = []

    @property
    def url(self) -> str:
        host = self._host
        if host in ('0.0.0.0', '::', ''):
            host = '127.0.0.1'
        elif ':' in host:
            host = f'[{host}]'
        return f'http://{host}:{self._port}/'

    def start(self) -> str:
        """Bind and serve on a thread of its own; answers the page's URL."""
        outcome: list = []
        started = threading.Event()
        self._thread = threading.Thread(target=self._serve, args=(outcome, started),
                                        daemon=True, name='armor-web')
        self._thread.start()
        started.wait()
        if outcome:
            self._thread.join()
            raise WebViewError(f'the web view cannot listen on {self._host}:{self._port}: '
                               f'{outcome[0]}') from outcome[0]
        self._core.add_event_listener(self._on_event)
        return self.url

    def directives_answered(self, references: List[str]) -> None:
        """The node answered directives on these references (a name per directive)."""
        self._live.on_directives(references)

    def stop(self) -> None:
        if self._thread is None or not self._thread.is_alive():
            return
        self._core.remove_event_listener(self._on_event)
        closing = asyncio.run_coroutine_threadsafe(self._close(), self._loop)
        try:
            closing.result(timeout=5)
        except Exception as error:  # whatever stopped it, the node is going down: say so only
            self._log.warning(f'web view: closing: {error}')
        self._loop.call_soon_threadsafe(self._loop.stop)
        self._thread.join(timeout=5)

    def _serve(self, outcome: list, started: threading.Event) -> None:
        asyncio.set_event_loop(self._loop)
        try:
            self._loop.run_until_complete(self._open())
        except Exception as error:  # reported by start()
            outcome.append(error)
            self._loop.close()
            started.set()
            return
        started.set()
        self._loop.run_forever()
        self._loop.close()

    async def _open(self) -> None:
        self._reads = CoreReads(self._core, self._timeout_s)
        app = web.Application(middlewares=[self._guard], client_max_size=MAX_BODY_BYTES)
        _Routes(self._reads, self._live, self._log).add_to(app)
        self._runner = web.AppRunner(app, access_log=None, handle_signals=False)
        await self._runner.setup()
        site = web.TCPSite(self._runner, self._host, self._port, reuse_address=True)
        try:
            await site.start()
        except BaseException:
            await self._runner.cleanup()
            raise
        self._tasks.append(asyncio.create_task(self._live.broadcast()))

    async def _close(self) -> None:
        for task in self._tasks:
            task.cancel()
        if self._runner is not None:
            await self._runner.cleanup()
        if self._reads is not None:
            self._reads.close()

    @web.middleware
    async def _guard(self, request: web.Request, handler) -> web.StreamResponse:
        if not _host_allowed(self._host, request.host):
            return web.json_response(_error(421, f'this server answers for {self.url} only, '
                                                 f'not for host {request.host!r}'), status=421)
        response = await handler(request)
        if not response.prepared:
            response.headers.update(_SECURITY_HEADERS)
        return response


def _host_allowed(bound: str, requested: str) -> bool:
    """Whether a request's Host header may be answered: any, unless bound to loopback only."""
    if not _is_loopback(bound):
        return True
    name = requested.rsplit(':', 1)[0] if not requested.endswith(']') else requested
    name = name.strip('[]').lower()
    return name == 'localhost' or _is_loopback(name)


def _is_loopback(host: str) -> bool:
    if host == 'localhost':
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def _error(exit_code: int, description: str) -> Dict[str, Any]:
    return {'error': {'exit_code': exit_code, 'description': description}}


class _Routes:
    """The handlers: each turns a request into a view or QUERY directive of the core."""

    def __init__(self, reads: CoreReads, live: LiveUpdates, logger):
        self._reads = reads
        self._live = live
        self._log = logger
        self._answers = SharedAnswers()
        self._pages = 0

    def add_to(self, app: web.Application) -> None:
        app.router.add_get('/', self.index)
        app.router.add_static('/static/', STATIC, follow_symlinks=False)
        app.router.add_get('/api/overview', self.overview)
        app.router.add_get('/api/recent', self.recent)
        app.router.add_get('/api/live', self.live)
        prefix = '/api/references/{reference}'
        app.router.add_get(prefix, self.reference)
        app.router.add_get(prefix + '/classes', self.classes)
        app.router.add_get(prefix + '/class', self.owl_class)
        app.router.add_get(prefix + '/individuals', self.individuals)
        app.router.add_get(prefix + '/individual', self.individual)
        app.router.add_get(prefix + '/graph', self.graph)
        app.router.add_get(prefix + '/consistency', self.consistency)
        app.router.add_post(prefix + '/dl', self.dl_query)
        app.router.add_post(prefix + '/sparql', self.sparql)
        SceneRoutes(self._json_lines).add_to(app, prefix)
        ExplanationRoutes(self._reads.directive, lambda key, fetch, reference: self._shared(
            key, self._live.version(reference), REFERENCE_MAX_AGE_S, fetch, reference,
            on_demand=True)).add_to(app, prefix)

    async def index(self, request: web.Request) -> web.StreamResponse:
        return web.FileResponse(STATIC / 'index.html')

    async def overview(self, request: web.Request) -> web.Response:
        return await self._shared(('overview',), self._live.version(), OVERVIEW_MAX_AGE_S,
                                  self._overview_with_damage)

    async def _overview_with_damage(self) -> Dict[str, Any]:
        """Every reference's summary, and what the state directory lost or refuses (a banner)."""
        overview = await self._reads.view({'name': 'overview'})
        damage = await self._reads.directive('', 'GET', 'STATE', 'DAMAGE')
        overview['state_damage'] = [json.loads(line) for line in damage.get('queried_objects', [])]
        return overview

    async def recent(self, request: web.Request) -> web.Response:
        reference = request.query.get('reference', '')
        everyone = request.query.get('all', '') in ('1', 'true')
        limit = _integer(request, 'limit', 50)
        view = {'name': 'recent', 'reference': reference, 'limit': limit,
                'exclude_clients': [] if everyone else [WEB_CLIENT]}
        return await self._shared(('recent', reference, everyone, limit), self._live.answered(),
                                  RECENT_MAX_AGE_S, lambda: self._reads.view(view))

    async def reference(self, request: web.Request) -> web.Response:
        return await self._reference_view(request, {'name': 'reference'})

    async def classes(self, request: web.Request) -> web.Response:
        return await self._reference_view(request, {'name': 'classes'})

    async def owl_class(self, request: web.Request) -> web.Response:
        return await self._reference_view(request, {'name': 'class',
                                                    'class': _entity(request)})

    async def individuals(self, request: web.Request) -> web.Response:
        return await self._reference_view(request, {
            'name': 'individuals', 'search': request.query.get('search', ''),
            'offset': _integer(request, 'offset', 0), 'limit': _integer(request, 'limit', 50)})

    async def individual(self, request: web.Request) -> web.Response:
        return await self._reference_view(request, {'name': 'individual',
                                                    'individual': _entity(request)})

    async def graph(self, request: web.Request) -> web.Response:
        view = {'name': 'graph', 'class': _bracketed(request.query.get('class', '')),
                'focus': _bracketed(request.query.get('focus', '')),
                'limit': _integer(request, 'limit', 300)}
        if 'property' in request.query:
            # property= alone (none chosen) follows no property; no property parameter, all.
            view['properties'] = [_bracketed(p) for p in request.query.getall('property') if p]
        return await self._reference_view(request, view)

    async def consistency(self, request: web.Request) -> web.Response:
        reference = request.match_info['reference']

        async def explain() -> Dict[str, Any]:
            answer = await self._reads.directive(reference, 'QUERY', 'CONSISTENCY', '')
            return _directive_answer(answer, explanation=answer['queried_objects'])
        # Explaining can take the reasoner seconds, holding the reference: while changes keep
        # coming, one explanation serves EXPLANATION_MAX_AGE_S (a new one once consistency flips).
        return await self._shared(('consistency', reference), self._live.consistent(reference),
                                  EXPLANATION_MAX_AGE_S, explain, reference)

    async def dl_query(self, request: web.Request) -> web.Response:
        reference = request.match_info['reference']
        expression = (await _json_body(request)).get('expression', '')
        if not isinstance(expression, str) or not expression.strip():
            raise web.HTTPBadRequest(text=json.dumps(_error(207, 'no class expression given')),
                                     content_type='application/json')
        instances, subclasses = await self._guarded(lambda: asyncio.gather(
            self._reads.directive(reference, 'QUERY', 'IND', 'DL', expression),
            self._reads.directive(reference, 'QUERY', 'CLASS', 'DL', expression)))
        return web.json_response({
            'instances': _directive_answer(instances, items=instances['queried_objects']),
            'subclasses': _directive_answer(subclasses, items=subclasses['queried_objects'])})

    async def sparql(self, request: web.Request) -> web.Response:
        reference = request.match_info['reference']
        query = (await _json_body(request)).get('query', '')
        if not isinstance(query, str) or not query.strip():
            raise web.HTTPBadRequest(text=json.dumps(_error(207, 'no SPARQL query given')),
                                     content_type='application/json')
        answer = await self._guarded(lambda: self._reads.directive(
            reference, 'QUERY', 'SPARQL', 'FORMATTED', query))
        return web.json_response(_directive_answer(answer, cells=[
            [item['key'], item['value']] for item in answer['sparql_queried_objects']]))

    async def live(self, request: web.Request) -> web.StreamResponse:
        origin = request.headers.get('Origin')
        if origin is not None and origin != f'{request.scheme}://{request.host}':
            raise web.HTTPForbidden(text='the live updates are for this server\'s own page')
        if self._pages >= MAX_PAGES:
            raise web.HTTPServiceUnavailable(text=f'{MAX_PAGES} pages are open already')
        socket = web.WebSocketResponse(heartbeat=20.0, max_msg_size=4096)
        await socket.prepare(request)
        self._pages += 1
        page = self._live.join()
        sender = asyncio.create_task(self._send_updates(socket, page))
        try:
            async for message in socket:
                if message.type == WSMsgType.ERROR:
                    break
        finally:
            self._pages -= 1
            self._live.leave(page)
            sender.cancel()
        return socket

    async def _send_updates(self, socket: web.WebSocketResponse, page) -> None:
        try:
            while not socket.closed:
                await socket.send_str(await page.next_message())
        except (ConnectionError, RuntimeError):
            pass  # the page went away; the reading side ends the handler

    async def _reference_view(self, request: web.Request, view: Dict[str, Any]) -> web.Response:
        reference = request.match_info['reference']
        view['reference'] = reference
        key = tuple(sorted((k, json.dumps(v)) for k, v in view.items()))
        return await self._shared(key, self._live.version(reference), REFERENCE_MAX_AGE_S,
                                  lambda: self._reads.view(view), reference)

    async def _json_lines(self, reference: str, *words: str) -> web.Response:
        """A QUERY whose answer lines are JSON objects, as {"items": [...]}, kept per revision."""
        async def fetch() -> Dict[str, Any]:
            answer = await self._reads.directive(reference, *words)
            if not answer['success']:
                raise ViewFailed(answer['exit_code'], answer['error_description'])
            return {'items': [json.loads(line) for line in answer['queried_objects']]}
        return await self._shared(('lines', reference, *words), self._live.version(reference),
                                  REFERENCE_MAX_AGE_S, fetch, reference)

    async def _shared(self, key, version, max_age_s: float, fetch: Callable[[], Awaitable[Any]],
                      reference: Optional[str] = None, on_demand: bool = False) -> web.Response:
        body = await self._guarded(
            lambda: self._answers.get(key, version, max_age_s, fetch, reference, on_demand))
        return web.Response(body=body, content_type='application/json')

    async def _guarded(self, call: Callable[[], Awaitable[Any]]) -> Any:
        """The core's answer, or the HTTP error that tells the page why there is none."""
        try:
            return await call()
        except ViewFailed as failure:
            raise _http_error(_STATUS.get(failure.exit_code, 500),
                              _error(failure.exit_code, failure.description))
        except CoreUnavailable as error:
            raise _http_error(503, _error(216, str(error)))
        except TimeoutError:
            raise _http_error(504, _error(211, 'no answer from the core within '
                                               'request_timeout_s'))


def _http_error(status: int, body: Dict[str, Any]) -> web.HTTPException:
    error_class = _STATUS_ERRORS.get(status, web.HTTPInternalServerError)
    return error_class(text=json.dumps(body), content_type='application/json')


_STATUS_ERRORS = {400: web.HTTPBadRequest, 404: web.HTTPNotFound, 409: web.HTTPConflict,
                  503: web.HTTPServiceUnavailable, 504: web.HTTPGatewayTimeout}


def _directive_answer(answer: Dict[str, Any], **fields: Any) -> Dict[str, Any]:
    """A QUERY response as the page shows it: success, code, reason, consistency, its items."""
    return {'success': answer['success'], 'exit_code': answer['exit_code'],
            'description': answer['error_description'], 'timeout': answer['timeout'],
            'consistent': answer['is_consistent'], **fields}


def _integer(request: web.Request, name: str, absent: int) -> int:
    text = request.query.get(name, '')
    if not text:
        return absent
    try:
        return int(text)
    except ValueError:
        raise web.HTTPBadRequest(text=json.dumps(_error(207, f'{name} must be a whole number')),
                                 content_type='application/json')


def _entity(request: web.Request) -> str:
    iri = request.query.get('iri', '')
    if not iri:
        raise web.HTTPBadRequest(text=json.dumps(_error(207, 'no iri given')),
                                 content_type='application/json')
    return _bracketed(iri)


def _bracketed(iri: str) -> str:
    """An IRI as an ARMOR argument (<...>); a short name or prefix:name is passed as it is."""
    return f'<{iri}>' if '://' in iri and not iri.startswith('<') else iri


async def _json_body(request: web.Request) -> Dict[str, Any]:
    if request.content_type != 'application/json':
        raise web.HTTPUnsupportedMediaType(text='send application/json')
    try:
        body = await request.json()
    except ValueError:
        body = None
    if not isinstance(body, dict):
        raise web.HTTPBadRequest(text=json.dumps(_error(207, 'the body must be a JSON object')),
                                 content_type='application/json')
    return body
