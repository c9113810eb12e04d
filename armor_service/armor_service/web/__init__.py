# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The live web view of every reference, served by the node (parameters web_port, web_host).

The node starts it from one place (``WebView`` in server.py). It reads the core through the
same socket as ROS clients' directives: read-only views the core answers as JSON (core/.../view/)
and ordinary QUERY directives. It changes nothing, and holds no ontology logic: the page's
contents are computed in the core; this package serves them and pushes change events.
"""

from armor_service.web.server import WebView

__all__ = ['WebView']
