"""Callbacks given as functools.partial and lambda are entry points too."""
from functools import partial

from rclpy.node import Node
from sensor_msgs.msg import Range

from example_pkg.msg import Distance


class Sonars(Node):
    def __init__(self) -> None:
        super().__init__("sonars")
        self.pub = self.create_publisher(Distance, "distance", 1)
        self.create_subscription(Range, "front", partial(self.on_range, "front"), 1)
        self.create_subscription(
            Range, "rear", lambda msg: self.pub.publish(Distance(data=msg.range)), 1  # error: RF201
        )
        self.create_subscription(
            Range, "left", lambda msg: self.pub.publish(Distance(data=msg.range * 100)), 1  # warning: RF102
        )

    def on_range(self, side: str, msg) -> None:
        out = Distance()
        out.data = msg.range  # error: RF201
        out.data = msg.range * 100  # warning: RF102 "data >= 0"
        if msg.range >= 0:
            out.data = msg.range * 100
        self.pub.publish(out)
