# Modelled on turtlebot3_bringup and nav2_bringup: one robot under a namespace.
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    driver_params = os.path.join(
        get_package_share_directory('teleop_bringup'), 'config', 'driver.yaml'
    )
    return LaunchDescription([
        Node(
            package='base_driver',
            executable='driver',
            name='driver',
            namespace='robot1',
            parameters=[driver_params],
        ),
        # near miss: the remapping makes the teleop's `cmd_vel` the driver's
        # `base/cmd_vel` (without it, two notes: published / subscribed nowhere)
        Node(
            package='keyboard_teleop',
            executable='teleop',
            name='teleop',
            namespace='robot1',
            parameters=[{'use_stamped': False}],
            remappings=[('cmd_vel', 'base/cmd_vel')],
        ),
        Node(
            package='keyboard_teleop',
            executable='monitor',
            name='monitor',
            namespace='robot1',
        ),
        Node(
            package='keyboard_teleop',
            executable='obstacle_stop',
            name='obstacle_stop',
            namespace='robot1',
        ),
    ])
