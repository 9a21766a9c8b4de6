from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='goal_tools', executable='goal_checker', name='goal_checker'),
        Node(package='goal_tools', executable='ahead', name='ahead'),
        Node(package='goal_tools', executable='inspection', name='inspection'),
        Node(package='goal_tools', executable='clicked', name='clicked'),
        Node(package='goal_tools', executable='patrol_goals', name='patrol_goals',
             parameters=[{'frame_id': 'map'}]),
    ])
