from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='patrol', executable='patrol_server', name='patrol_server'),
        Node(package='patrol', executable='patrol_client', name='patrol_client'),
        Node(package='patrol', executable='square_patrol', name='square_patrol'),
        Node(package='patrol', executable='circle_patrol', name='circle_patrol'),
    ])
