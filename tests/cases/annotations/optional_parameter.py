"""Optional refinements hold when the value is not None."""
from __future__ import annotations

from typing import Annotated, Optional, Union

from geometry_msgs.msg import Twist

Speed = Annotated[float, "Unit('m/s') and 0 <= _ <= 0.5"]


def drive(pub, speed: Optional[Speed] = None, timeout: Annotated[float, "Unit('s') and _ > 0"] | None = None) -> None:
    msg = Twist()
    if speed is not None:
        msg.linear.x = speed
    pub.publish(msg)


def stop(pub) -> None:
    drive(pub, None)
    drive(pub, speed=None, timeout=None)
    drive(pub, 0.2, 1.0)
    drive(pub, 0.9)  # error: RF101
    drive(pub, timeout=-1.0)  # error: RF101


def limits() -> None:
    a: Optional[Annotated[float, "_ > 0"]] = None
    a = 2.0
    a = -1.0  # error: RF101
    b: Union[Annotated[int, "_ < 10"], None] = 3
    b = None
    b = 12  # error: RF101
    c: Union[None, Annotated[int, "_ < 10"]] = 20  # error: RF101
    d: Speed | None = None
    d = 0.4
    d = 0.7  # error: RF101
    width: Annotated[float, "Unit('s')"] = 1.0  # a duration, not a speed
    e: Optional[Speed] = width  # error: RF201


def reads(speed: Optional[Speed]) -> None:
    # the value may be None: nothing of the refinement is assumed on a read
    copy: Annotated[float, "_ <= 0.5"] = speed  # warning: RF102
