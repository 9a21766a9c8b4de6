"""Lists, dicts and tuples of messages and objects (a sonar ring turned into a
LaserScan, a fleet of robots each with its own command): their elements have the
declared or built type, in `for` loops, comprehensions and subscripts."""
from typing import Annotated, Dict, List

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan, Range


def to_cm(reading: Range) -> Annotated[float, "Unit('cm')"]:
    """For the display, which shows centimetres."""
    return reading.range * 100.0


class Wheel:
    def spin(self, rate: Annotated[float, "Unit('rad/s')"]) -> None:
        print(rate)


class SonarRing:
    def __init__(self) -> None:
        self.sonars: list[Range] = []
        self.wheels: Dict[str, Wheel] = {"left": Wheel(), "right": Wheel()}
        self.history: List[Odometry] = []
        self.pub = rospy.Publisher("scan", LaserScan, queue_size=1)
        rospy.Subscriber("odom", Odometry, self.on_odom)

    def publish_scan(self) -> None:
        scan = LaserScan()
        scan.ranges = [to_cm(r) for r in self.sonars]  # error: RF201
        scan.ranges = [r.range for r in self.sonars]
        for sonar in self.sonars:
            scan.range_max = to_cm(sonar)  # error: RF201
            scan.range_min = sonar.min_range
        scan.angle_increment = self.sonars[0].field_of_view
        scan.angle_increment = self.sonars[0].max_range  # error: RF201
        self.pub.publish(scan)

    def on_odom(self, odom: Odometry) -> None:
        self.history.append(odom)
        self.wheels["left"].spin(odom.twist.twist.linear.x)  # error: RF201
        self.wheels["right"].spin(odom.twist.twist.angular.z)
        speeds = [o.twist.twist.linear.x for o in self.history]
        scan = LaserScan()
        scan.ranges = speeds  # error: RF201


class Fleet:
    def __init__(self, names: list[str]) -> None:
        self.pubs = [rospy.Publisher(n + "/cmd_vel", Twist, queue_size=1) for n in names]

    def command(self, odom: Odometry) -> None:
        cmds = [Twist(), Twist()]
        cmds[0].linear.x = odom.twist.twist.angular.z  # error: RF201
        cmds[1].linear.x = odom.twist.twist.linear.x
        for cmd in cmds:
            cmd.angular.z = odom.twist.twist.linear.x  # error: RF201
            cmd.angular.z = odom.twist.twist.angular.z
        built = [Twist() for _ in self.pubs]
        built[0].linear.y = odom.twist.twist.angular.z  # error: RF201
        pair = (Twist(), 0)
        pair[0].angular.x = odom.twist.twist.linear.x  # error: RF201
        for pub, cmd in zip(self.pubs, cmds):
            pub.publish(cmd)


if __name__ == "__main__":
    rospy.init_node("sonar_ring")
    ring = SonarRing()
    rospy.spin()
