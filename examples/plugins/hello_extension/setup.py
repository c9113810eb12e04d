# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""A tiny ROS-side extension of the ARMOR node (docs/extending.md).

Install it and name it in the node's parameter:
pip install examples/plugins/hello_extension, then
armor serve --ros-args -p extensions:=hello.
"""
from setuptools import setup

setup(
    name='armor-hello-extension',
    version='0.4.0',
    packages=['armor_hello_extension'],
    description='Example extension of the ARMOR node: a service and a directive topic',
    license='Apache-2.0',
    # The node loads the entry points of this group that its `extensions` parameter names.
    entry_points={'armor_service.extensions': ['hello = armor_hello_extension:HelloExtension']},
)
