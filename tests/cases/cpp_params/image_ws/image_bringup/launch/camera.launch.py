import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(
        get_package_share_directory("image_bringup"), "config", "camera.yaml"
    )
    camera = Node(
        package="image_tools",
        executable="cam2image",
        name="camera",
        parameters=[
            config,
            {
                "frequency": 15,  # error: RF401
                "width": 640.0,  # error: RF401
                "depth": 5,
                "exposure": -0.25,
                "burger_mode": True,
                "show_camra": False,  # warning: RF601
                "use_sim_time": True,
            },
        ],
    )
    still = Node(
        package="image_tools",
        executable="cam2image",
        name="still_camera",
        parameters=[{"frequency": 1.0, "height": 480}],
    )
    return LaunchDescription([camera, still])
