import rclpy
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node


class GymBridge(Node):
    def __init__(self):
        super().__init__("gym_bridge")
        self.declare_parameter("ego_namespace", "ego_racecar")
        self.declare_parameter("scan_beams", 1080)
        fov = ParameterDescriptor(
            floating_point_range=[FloatingPointRange(from_value=0.0, to_value=6.3)]
        )
        self.declare_parameter("scan_fov", 4.7, fov)
        self.declare_parameter("num_agent", 1)
        self.declare_parameter("kb_teleop", True)


def main():
    rclpy.init()
    rclpy.spin(GymBridge())
