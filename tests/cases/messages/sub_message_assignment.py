"""Sub-messages assigned whole (`cmd.linear = Vector3(...)`, `odom.header =
msg.header`) and nested constructors are checked against the outer message's units
and refinements, exactly as the same values written field by field."""
import math
from typing import Annotated

from geometry_msgs.msg import Point, Pose, Twist, Vector3
from nav_msgs.msg import Odometry
from rclpy.action import ActionClient
from rclpy.node import Node
from sensor_msgs.msg import Imu

from robot_pkg.action import BackUp
from robot_pkg.msg import Drive


class Base(Node):
    def __init__(self) -> None:
        super().__init__("base")
        self.cmd_pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.odom_pub = self.create_publisher(Odometry, "odom", 10)
        self.drive_pub = self.create_publisher(Drive, "drive", 10)
        self.backup = ActionClient(self, BackUp, "backup")
        self.create_subscription(Imu, "imu", self.on_imu, 10)

    def steer(self, yaw_rate_deg: Annotated[float, "Unit('degree/s')"]) -> None:
        cmd = Twist()
        cmd.linear = Vector3(0.5, 0.2, 0.0)
        cmd.angular = Vector3(z=yaw_rate_deg)  # error: RF201
        self.cmd_pub.publish(cmd)

    def steer_converted(self, yaw_rate_deg: Annotated[float, "Unit('degree/s')"]) -> None:
        cmd = Twist(angular=Vector3(z=math.radians(yaw_rate_deg)))
        self.cmd_pub.publish(cmd)

    def steer_nested(self, yaw_rate_deg: Annotated[float, "Unit('degree/s')"]) -> None:
        cmd = Twist(Vector3(x=0.1), Vector3(0.0, 0.0, yaw_rate_deg))  # error: RF201
        self.cmd_pub.publish(cmd)

    def on_imu(self, msg: Imu) -> None:
        odom = Odometry()
        odom.header = msg.header
        odom.twist.twist.angular = msg.angular_velocity
        odom.twist.twist.linear = msg.linear_acceleration  # error: RF201
        self.odom_pub.publish(odom)

    def report_pose(self, x: Annotated[float, "Unit('m')"]) -> None:
        p = Pose()
        p.position = Point(x=x)
        odom = Odometry()
        odom.pose.pose = p
        self.odom_pub.publish(odom)

    def drive(self, speed: Annotated[float, "Unit('m/s') and 0 <= _ <= 0.4"]) -> None:
        self.drive_pub.publish(Drive(velocity=Vector3(x=speed)))
        self.drive_pub.publish(Drive(velocity=Vector3(x=speed + 0.6)))  # error: RF101
        fast = Vector3(x=0.8)
        msg = Drive()
        msg.velocity = fast  # error: RF101
        msg.accel = Vector3(1.5, 1.0, 0.0)  # error: RF101
        msg.accel = Vector3(1.0, 1.0, 0.0)
        self.drive_pub.publish(msg)

    def back_up(self, d: Annotated[float, "Unit('m') and _ > 0"]) -> None:
        self.backup.send_goal_async(BackUp.Goal(target=Point(x=d), speed=0.2))
        self.backup.send_goal_async(BackUp.Goal(target=Point(x=-d), speed=0.2))  # error: RF101
