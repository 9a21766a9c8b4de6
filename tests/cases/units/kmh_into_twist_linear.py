"""RF201 with REP 103 alone: Twist.linear.x is m/s, no .msg annotation needed."""
from typing import Annotated

from geometry_msgs.msg import Twist


def drive(pub, speed: Annotated[float, "Unit('km/h') and 0 <= _ < 30"]) -> None:
    msg = Twist()
    msg.linear.x = speed  # error: RF201 "divide by 3.6"
    pub.publish(msg)


def drive_converted(pub, speed: Annotated[float, "Unit('km/h') and 0 <= _ < 30"]) -> None:
    msg = Twist()
    msg.linear.x = speed / 3.6  # a conversion: clean
    msg.linear.y = speed * 1000 / 3600  # also a conversion
    pub.publish(msg)


def drive_halved(pub, speed: Annotated[float, "Unit('km/h') and 0 <= _ < 30"]) -> None:
    msg = Twist()
    msg.linear.x = speed * 2  # error: RF201
    # 0.5 is nearer 1/3.6 than 1: maybe / 3.6 and a gain of 1.8 in one number
    msg.linear.x = speed * 0.5  # warning: RF203
    pub.publish(msg)
