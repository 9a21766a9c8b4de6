"""A subscription callback's refined message is assumed inside the callback, as a
refined parameter is: its senders prove it (contracts across nodes, docs/graph.md).
Before, an arriving message was any message, so a callback relying on its own
contract got an RF102 (the second fresh-eyes round's c06: a server's request
refinement was ignored when its return was checked)."""
from typing import Annotated

from rclpy.node import Node
from std_msgs.msg import Float64

JointCmd = Annotated[Float64, "abs(data) <= 3.2"]


class Halver(Node):
    def __init__(self):
        super().__init__("halver")
        self.create_subscription(Float64, "command", self.on_command, 10)
        self.create_subscription(Float64, "boost", self.on_boost, 10)
        self.pub = self.create_publisher(Float64, "half", 10)

    def on_command(self, msg: JointCmd):
        out: JointCmd = Float64()
        out.data = msg.data / 2  # within the contract: no diagnostic
        self.pub.publish(out)

    def on_boost(self, msg: JointCmd):
        out: JointCmd = Float64()
        out.data = msg.data * 2  # warning: RF102
        self.pub.publish(out)
