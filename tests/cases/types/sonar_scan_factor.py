"""A ring of sonars kept as a list of received `Range` messages and turned into a
LaserScan each tick: the elements' type comes from the list's annotation, their
unit from the message (m), so a factor of 100 converts a second time."""
from rclpy.node import Node
from sensor_msgs.msg import LaserScan, Range


class SonarFusion(Node):
    def __init__(self) -> None:
        super().__init__("sonar_fusion")
        self.sonars: list[Range] = []
        self.pub = self.create_publisher(LaserScan, "scan", 10)
        self.create_subscription(Range, "sonar", self.on_range, 10)
        self.create_timer(0.1, self.tick)

    def on_range(self, msg: Range) -> None:
        self.sonars.append(msg)

    def tick(self) -> None:
        scan = LaserScan()
        scan.ranges = [r.range * 100.0 for r in self.sonars]  # error: RF201 "the value was in m already"
        self.pub.publish(scan)

    def tick_fixed(self) -> None:
        scan = LaserScan()
        scan.ranges = [r.range for r in self.sonars]
        scan.range_max = max(r.max_range for r in self.sonars)
        self.pub.publish(scan)
