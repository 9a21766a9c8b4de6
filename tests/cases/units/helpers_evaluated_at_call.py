"""An unannotated one-line helper (`return <expr>`) is evaluated at its call with its
parameters bound to the arguments: the result has the unit, factors and bounds the
expression written inline would have. A clamp helper keeps rad/s (RF201 into rpm)
and keeps the bound a clamped value in rpm meets (no RF102); a km/h helper converts."""
import math
from typing import Annotated

from geometry_msgs.msg import Twist

MAX_RPM = 200.0
WHEEL_RADIUS: Annotated[float, "Unit('m')"] = 0.033


def set_rpm(rpm: Annotated[float, "Unit('rpm') and abs(_) <= MAX_RPM"]) -> None: ...


def steer(heading: Annotated[float, "Unit('rad') and -math.pi <= _ <= math.pi"]) -> None: ...


def clamp(x, lo, hi):
    """Limit x to [lo, hi]."""
    return max(lo, min(hi, x))


def clamp_rpm(rpm, limit=MAX_RPM):
    return clamp(rpm, -limit, limit)


def to_rpm(omega):
    return omega * 60 / (2 * math.pi)


def wrap_angle(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


def kmh_to_ms(v):
    return v / 3.6


def scaled(v, gain):
    print(gain)  # a statement: not evaluated at the call, its result stays unknown
    return v * gain


class Wheels:
    def __init__(self, pub) -> None:
        self.pub = pub

    def on_omega(self, omega_l: Annotated[float, "Unit('rad/s')"], omega_r: Annotated[float, "Unit('rad/s')"]) -> None:
        set_rpm(clamp(to_rpm(omega_l), -MAX_RPM, MAX_RPM))  # converted and clamped: clean
        set_rpm(clamp(omega_r, -MAX_RPM, MAX_RPM))  # error: RF201 "9.5493"
        set_rpm(clamp_rpm(to_rpm(omega_r)))  # default limit: clean
        set_rpm(clamp_rpm(limit=150.0, rpm=to_rpm(omega_r)))  # keywords: clean
        set_rpm(clamp(x=omega_l, lo=-MAX_RPM, hi=MAX_RPM))  # error: RF201
        set_rpm(to_rpm(omega_l))  # warning: RF102
        set_rpm(scaled(omega_l, 9.5))  # warning: RF102

    def on_rpm(self, rpm: Annotated[float, "Unit('rpm')"]) -> None:
        set_rpm(clamp(rpm, -MAX_RPM, MAX_RPM))  # clamped into the bound: clean
        set_rpm(clamp(rpm, -2 * MAX_RPM, 2 * MAX_RPM))  # warning: RF102

    def on_heading(self, yaw: Annotated[float, "Unit('rad')"], yaw_deg: Annotated[float, "Unit('degree')"]) -> None:
        steer(wrap_angle(yaw))  # within [-pi, pi): clean
        steer(wrap_angle(yaw_deg))  # error: RF201

    def on_speed(self, speed: Annotated[float, "Unit('km/h') and 0 <= _ < 30"]) -> None:
        msg = Twist()
        msg.linear.x = kmh_to_ms(speed)  # km/h / 3.6: clean
        msg.linear.y = speed  # error: RF201 "divide by 3.6"
        msg.angular.z = kmh_to_ms(speed) / WHEEL_RADIUS  # m/s / m: clean (rad/s)
        msg.linear.z = kmh_to_ms(kmh_to_ms(speed))  # error: RF201
        self.pub.publish(msg)
