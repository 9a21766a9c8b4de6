"""RF302: a message sent with a field set on some paths only, where the field's ROS
default breaks its refinement. Fields set on every path, or whose default is fine,
are not reported."""
import rospy

from drive_pkg.msg import DriveMode


def send_mode(pub: rospy.Publisher, command: str) -> None:
    msg = DriveMode()
    if command == "slow":
        msg.mode = 1
    elif command == "fast":
        msg.mode = 3
    pub.publish(msg)  # error: RF302


def send_mode_all_paths(pub: rospy.Publisher, command: str) -> None:
    msg = DriveMode()
    if command == "slow":
        msg.mode = 1
    else:
        msg.mode = 2
    pub.publish(msg)


def send_speed(pub: rospy.Publisher, fast: bool) -> None:
    msg = DriveMode(mode=2)
    if fast:
        msg.speed = 1.0
    pub.publish(msg)  # speed's default 0.0 is within 0..1


def send_guarded(pub: rospy.Publisher, command: str) -> None:
    msg = DriveMode()
    if command == "slow":
        msg.mode = 1
    if command == "slow":
        pub.publish(msg)


def send_dead(pub: rospy.Publisher, fast: bool) -> None:
    msg = DriveMode()
    if fast:
        if not fast:
            pub.publish(msg)  # no execution gets here
