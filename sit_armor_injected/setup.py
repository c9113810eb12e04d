# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The scene service of the ARMOR node (docs/scenes.md): an extension the node loads by default."""
from setuptools import setup

package_name = 'sit_armor_injected'

setup(
    name=package_name,
    version='0.4.0',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ARMOR for ROS 2 maintainers',
    maintainer_email='armor-ros2@example.com',
    description='ARMOR for ROS 2: the sit_armor_injected scene service, a node extension',
    license='Apache-2.0',
    # The node loads the extensions its `extensions` parameter names; its default names sit.
    entry_points={'armor_service.extensions': ['sit = sit_armor_injected:SceneService']},
)
