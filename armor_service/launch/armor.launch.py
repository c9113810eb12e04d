# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Start the ARMOR node with ros2 launch (needs a full ROS 2 install with launch_ros).

  ros2 launch armor_service armor.launch.py
  ros2 launch armor_service armor.launch.py params_file:=/path/my.params.yaml namespace:=robot1

Without launch (this checkout's venv has none), the same is
  armor serve --ros-args --params-file armor_service/config/armor.params.yaml -r __ns:=/robot1
"""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    sample = os.path.join(get_package_share_directory('armor_service'), 'config',
                          'armor.params.yaml')
    return LaunchDescription([
        DeclareLaunchArgument('params_file', default_value=sample,
                              description='parameters of the node (see the README table)'),
        DeclareLaunchArgument('namespace', default_value='',
                              description='namespace of the node and its two services'),
        Node(package='armor_service', executable='armor_service', name='armor_service',
             namespace=LaunchConfiguration('namespace'),
             parameters=[LaunchConfiguration('params_file')], output='screen', emulate_tty=True),
    ])
