from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='safe_drive', executable='limiter', name='limiter'),
        Node(package='safe_drive', executable='planner', name='planner'),
        Node(package='safe_drive', executable='teleop', name='teleop'),
        Node(package='safe_drive', executable='joystick', name='joystick'),
    ])
