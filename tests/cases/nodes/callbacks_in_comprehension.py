"""Subscriptions made in a comprehension register their lambdas as callbacks too;
the comprehension's variable stays its own (Python 3 scoping)."""
from rclpy.node import Node
from sensor_msgs.msg import Range

from example_pkg.msg import Distance


class Sonars(Node):
    def __init__(self, topics: list[str]) -> None:
        super().__init__("sonars")
        self.pub = self.create_publisher(Distance, "distance", 1)
        self.subs = [
            self.create_subscription(
                Range, t, lambda msg: self.pub.publish(Distance(data=msg.range)), 1  # error: RF201
            )
            for t in topics
        ]
