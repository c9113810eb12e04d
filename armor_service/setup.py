# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
from setuptools import find_packages, setup

package_name = 'armor_service'

setup(
    name=package_name,
    version='0.4.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', ['launch/armor.launch.py']),
        ('share/' + package_name + '/config', ['config/armor.params.yaml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ARMOR for ROS 2 maintainers',
    maintainer_email='armor-ros2@example.com',
    description='ARMOR for ROS 2: the node serving armor_msgs in front of the OWL knowledge core',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'armor_service = armor_service.node:main',
        ],
        # The armor command (armor_client) finds its verbs here: serve starts this node.
        'armor.verbs': [
            'serve = armor_service.serve_verb',
        ],
    },
)
