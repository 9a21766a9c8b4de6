from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='speed_control', executable='boost_server', name='boost_server'),
        Node(package='speed_control', executable='scale_server', name='scale_server'),
        Node(package='speed_control', executable='clamp_server', name='clamp_server'),
        Node(package='speed_control', executable='cruise', name='cruise'),
        Node(package='speed_control', executable='turbo_server', name='turbo_server'),
        Node(package='speed_control', executable='cruise_async', name='turbo_cruise'),
        Node(package='speed_control', executable='async_cruise', name='async_cruise'),
    ])
