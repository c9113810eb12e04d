# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
from setuptools import find_packages, setup

package_name = 'armor_client'

setup(
    name=package_name,
    version='0.4.0',
    packages=find_packages(exclude=['test']),
    package_data={package_name: ['py.typed']},
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ARMOR for ROS 2 maintainers',
    maintainer_email='armor-ros2@example.com',
    description='ARMOR for ROS 2: Python client library and the armor command-line tool',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'armor = armor_client.cli:main',
        ],
        # The verbs of the armor command; other packages add theirs to the same group.
        'armor.verbs': [f'{verb} = armor_client.cli.{verb}' for verb in (
            'call', 'explain', 'load', 'query', 'refs', 'save', 'scene', 'shell', 'sparql',
            'watch')],
    },
)
