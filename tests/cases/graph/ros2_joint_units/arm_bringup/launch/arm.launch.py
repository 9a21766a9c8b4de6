from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='arm_control', executable='controller', name='controller'),
        Node(package='arm_control', executable='dial', name='dial'),
        Node(package='arm_control', executable='slider', name='slider'),
        Node(package='arm_control', executable='home', name='home'),
    ])
