"""An rclpy arm driver: a timer publishes the JointState of a six-joint arm, whose
interface overlay (msg/JointState.msg) puts units and limits on the position and
velocity arrays (issue 8, item 5)."""
import math
from typing import Annotated

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import JointState

NAMES = ("shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3")
HOME: Annotated[tuple[float, ...], "Unit('rad') and abs(_) <= 3.1416"] = (
    0.0,
    -1.57,
    1.57,
    0.0,
    0.0,
    0.0,
)
MAX_JOINT_SPEED = 1.5  # rad/s


class ArmStatePublisher(Node):
    positions: Annotated[list[float], "Unit('rad') and abs(_) <= 3.1416"]

    def __init__(self) -> None:
        super().__init__("arm_state_publisher")
        self.declare_parameter("rate", 50.0)
        self.positions = list(HOME)
        self.pub = self.create_publisher(JointState, "joint_states", 10)
        self.timer = self.create_timer(0.02, self.on_timer)

    def on_timer(self) -> None:
        state = JointState()
        state.name = list(NAMES)
        state.position = [0.0, -1.57, 1.57, 0.0, 0.0, 0.0]
        # error: RF101 "`-90.0` violates"
        # error: RF101 "`90.0` violates"
        state.position = [0.0, -90.0, 90.0, 0.0, 0.0, 0.0]
        state.position = [0.0, -1.57, 1.57, 0.0, 0.0]  # error: RF101 "len(state.position) == 6"
        state.velocity = [MAX_JOINT_SPEED] * 6
        state.velocity = [0.0, 0.0, 2.5, 0.0, 0.0, 0.0]  # error: RF101 "abs(state.velocity[2]) <= 2.0"
        self.pub.publish(state)

    def publish_names_only(self) -> None:
        state = JointState()
        state.name = list(NAMES)
        self.pub.publish(state)  # error: RF302 "len(position) == 6"

    def move_joint(
        self,
        index: int,
        angle: Annotated[float, "Unit('rad') and abs(_) <= 3.0"],
        angle_deg: Annotated[float, "Unit('degree')"],
    ) -> None:
        self.positions[index] = angle
        self.positions[index] = angle_deg  # error: RF201
        self.positions[index] = math.radians(angle_deg)  # warning: RF102
        self.positions.append(angle)

    def publish_current(self) -> None:
        state = JointState()
        state.name = list(NAMES)
        state.position = self.positions  # warning: RF102 "len(state.position) == 6"
        first: Annotated[float, "Unit('rad') and abs(_) <= 3.1416"] = state.position[0]
        state.velocity = [0.0 for _ in NAMES]
        self.pub.publish(state)


def main() -> None:
    rclpy.init()
    rclpy.spin(ArmStatePublisher())
