# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
from setuptools import find_packages, setup

package_name = 'armor_contract'

setup(
    name=package_name,
    version='0.4.0',
    packages=find_packages(exclude=['test']),
    package_data={package_name: ['catalogue.json', 'py.typed']},
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ARMOR for ROS 2 maintainers',
    maintainer_email='armor-ros2@example.com',
    description='ARMOR for ROS 2: the catalogue, exit codes and service QoS shared by node '
                'and clients',
    license='Apache-2.0',
)
