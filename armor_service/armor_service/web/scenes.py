# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The web view's Scenes tab: what the SIT plugin knows of a reference (docs/scenes.md).

  GET /api/references/{ref}/scenes          QUERY SIT SCENES: the learned scene classes, each
                                            with its definition and the scenes it contains
  GET /api/references/{ref}/scenes/recent   QUERY SIT RECENT: the last scenes, recognitions
                                            explained

Both are read-only QUERY directives, shared and kept per revision as the page's other reads.
"""

from typing import Any, Awaitable, Callable

from aiohttp import web

# (reference, command words) -> the answer's lines read as JSON, as a web response.
JsonLines = Callable[..., Awaitable[web.Response]]


class SceneRoutes:
    """The two routes, answered through the server's shared QUERY path."""

    def __init__(self, json_lines: JsonLines):
        self._json_lines = json_lines

    def add_to(self, app: web.Application, prefix: str) -> None:
        app.router.add_get(prefix + '/scenes', self.classes)
        app.router.add_get(prefix + '/scenes/recent', self.recent)

    async def classes(self, request: web.Request) -> Any:
        return await self._json_lines(request.match_info['reference'], 'QUERY', 'SIT', 'SCENES')

    async def recent(self, request: web.Request) -> Any:
        return await self._json_lines(request.match_info['reference'], 'QUERY', 'SIT', 'RECENT')
