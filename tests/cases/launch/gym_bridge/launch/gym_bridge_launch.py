import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(
        get_package_share_directory("gym_bridge"), "config", "sim.yaml"
    )
    agents = LaunchConfiguration("agents")
    bridge = Node(
        package="gym_bridge",
        executable="gym_bridge",
        name="bridge",
        parameters=[
            config,
            {
                "scan_fov": 7.0,  # error: RF101
                "num_agent": agents,
                "kb_teleop": "true",
                "scan_beams": "1080",
                "ego_namespce": "ego",  # warning: RF601
                "use_sim_time": True,
                "legacy_mode": True,  # robotfix: ignore[RF601]
            },
        ],
    )
    teleop = Node(
        package="gym_bridge",
        executable="teleop",
        parameters=[{"speed": 1, "anything": 2.0}],  # error: RF401
    )
    return LaunchDescription(
        [DeclareLaunchArgument("agents", default_value="1.5"), bridge, teleop]
    )
