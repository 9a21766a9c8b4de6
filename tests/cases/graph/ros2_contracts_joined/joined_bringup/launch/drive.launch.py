from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='joined_drive', executable='guard', name='guard'),
        Node(package='joined_drive', executable='mover', name='mover'),
    ])
