# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Plugins reach the core through its API and SPI only (issue 30 item 2).

The core cannot say so with a Java module descriptor: its 124 libraries share 162 packages
between jars (owlapi-distribution and owlapi-tools, openllet-jena and openllet-query, ...),
which the module path refuses, so it runs from the class path, where a descriptor binds
nothing. This test binds the repository's plugins and the example instead: their sources and
the classes in their built jars name no core package but `api` and `spi`.
"""

import pathlib
import re
import zipfile

REPO = pathlib.Path(__file__).resolve().parents[1]
ALLOWED = {'api', 'spi'}
SOURCE_USE = re.compile(r'\bio\.github\.armor\.core\.(\w+)')
CLASS_USE = re.compile(rb'io/github/armor/core/(\w+)')


def _plugin_sources():
    yield from sorted(REPO.glob('plugins/*/src/main/java/**/*.java'))
    yield from sorted(REPO.glob('examples/plugins/*/src/**/*.java'))


def _outside(packages) -> set:
    return {package for package in packages if package not in ALLOWED}


def test_plugin_sources_name_only_the_api_and_the_spi():
    sources = list(_plugin_sources())
    assert len(sources) >= 5, sources  # the PDDL and scene plugins and the example
    named = {str(path.relative_to(REPO)): _outside(SOURCE_USE.findall(path.read_text()))
             for path in sources}
    assert {path: packages for path, packages in named.items() if packages} == {}


def test_built_plugin_classes_reference_only_the_api_and_the_spi():
    jars = sorted((REPO / 'install' / 'armor_plugins').glob('armor-*.jar'))
    assert len(jars) >= 2, 'make setup builds armor-pddl.jar and armor-sit.jar'
    found = {}
    for jar in jars:
        with zipfile.ZipFile(jar) as archive:
            for entry in archive.namelist():
                if entry.endswith('.class'):
                    outside = _outside(
                        name.decode() for name in CLASS_USE.findall(archive.read(entry)))
                    if outside:
                        found[f'{jar.name}!{entry}'] = outside
    assert found == {}
