# After navigation2's nav2_bringup/launch/navigation_launch.py: the servers as
# nodes, or as components of one container.
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    bringup_dir = get_package_share_directory("nav2_bringup")
    params_file = LaunchConfiguration("params_file")
    configured_params = RewrittenYaml(
        source_file=params_file, param_rewrites={}, convert_types=True
    )
    declare_params_file_cmd = DeclareLaunchArgument(
        "params_file",
        default_value=os.path.join(bringup_dir, "params", "nav2_params.yaml"),
    )
    controller = Node(
        package="nav2_controller",
        executable="controller_server",
        output="screen",
        parameters=[configured_params, {"controller_frequency": 10}],  # error: RF401
        remappings=[("cmd_vel", "cmd_vel_nav")],
    )
    smoother = Node(
        package="nav2_velocity_smoother",
        executable="velocity_smoother",
        name="velocity_smoother",
        parameters=[configured_params, {"odom_duration": 0.2}],
        remappings=[("cmd_vel", "cmd_vel_nav")],
    )
    container = ComposableNodeContainer(
        name="nav2_container",
        namespace="",
        package="rclcpp_components",
        executable="component_container_isolated",
        composable_node_descriptions=[
            ComposableNode(
                package="nav2_velocity_smoother",
                plugin="nav2_velocity_smoother::VelocitySmoother",
                name="docking_smoother",
                parameters=[configured_params, {"velocity_timeout": 1}],  # error: RF401
            ),
        ],
    )
    return LaunchDescription([declare_params_file_cmd, controller, smoother, container])
