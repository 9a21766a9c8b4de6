from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='speed_control', executable='limit_server', name='limit_server'),
        Node(package='speed_control', executable='cruise', name='cruise'),
        Node(package='speed_control', executable='docking', name='docking'),
        Node(package='speed_control', executable='joy_limit', name='joy_limit'),
        # near miss: under a namespace its relative `set_max_speed` is another
        # robot's service, which this launch file does not start
        Node(package='speed_control', executable='fleet', name='fleet',
             namespace='robot2'),
    ])
