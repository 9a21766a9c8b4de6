"""Paths the analysis cannot tell a run takes are no RF301 error: a call it cannot
see that may never return (a helper that raises, `parser.error`), the end of an
`elif` case analysis its author may have made exhaustive, two tests of one object
with a call between that may or may not have changed it, a loop whose running
may imply an earlier test, a `try` whose first statement binds. Each has a near
miss that is a bug on a path a run surely can take."""
import argparse
from enum import Enum

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Mode(Enum):
    IDLE = 0
    DRIVE = 1


def require(ok: bool, why: str) -> None:
    if not ok:
        raise ValueError(why)


def log_only(why: str) -> None:
    print(why)


class Driver(Node):
    def __init__(self) -> None:
        super().__init__("driver")
        self.mode = Mode.IDLE
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_timer(0.1, self.on_timer)

    def speed_for(self, mode: Mode) -> float:
        if mode is Mode.IDLE:
            speed = 0.0
        elif mode is Mode.DRIVE:
            speed = 0.2
        return speed  # the enum has no other member

    def speed_ordered(self, level: float) -> float:
        if level > 0.5:
            speed = 0.2
        elif level > 0.2:
            speed = 0.1
        return speed  # error: RF301

    def checked_speed(self, fast: bool) -> float:
        if fast:
            speed = 0.2
        else:
            require(False, "slow mode is not supported")
        return speed  # require() raised on the other path

    def logged_speed(self, fast: bool) -> float:
        if fast:
            speed = 0.2
        else:
            log_only("slow mode is not supported")
        return speed  # error: RF301

    def forwarded_speed(self, fast: bool) -> float:
        if fast:
            speed = 0.2
        else:
            self.get_logger().error("slow mode is not supported")
        return speed  # error: RF301

    def on_timer(self) -> None:
        cmd = Twist()
        cmd.linear.x = self.speed_for(self.mode)
        self.pub.publish(cmd)


def parse(argv: list) -> float:
    parser = argparse.ArgumentParser()
    parser.add_argument("--speed", type=float)
    args = parser.parse_args(argv)
    if args.speed is not None:
        speed = args.speed
    else:
        parser.error("--speed is required")
    return speed  # parser.error() exits


def timed(args: argparse.Namespace, node: Node) -> None:
    if args.verbose:
        started = node.get_clock().now()
    rclpy.spin_once(node)
    report(args)
    if args.verbose:  # report() may have changed args, or may not
        node.get_logger().info(f"{started}")


def report(args: argparse.Namespace) -> None:
    print(args)


def first_hint(given: dict) -> None:
    if ... in given.values():
        hints = {name: float for name in given}
    for name in [n for n, v in given.items() if v is ...]:
        print(hints[name])  # an element here means the test above held


def import_rows(node: Node, rows: list) -> None:
    try:
        final = None
        node.get_logger().info("begin")
        final = "rollback"
        for row in rows:
            node.get_logger().info(str(row))
    except Exception:
        if final:  # bound before anything could raise
            node.get_logger().info(final)


def import_rows_late(node: Node, rows: list) -> None:
    try:
        node.get_logger().info("begin")
        final = "rollback"
        for row in rows:
            node.get_logger().info(str(row))
    except Exception:
        if final:  # error: RF301
            node.get_logger().info(final)


class Recorder(Node):
    def __init__(self) -> None:
        super().__init__("recorder")
        self.verbose = self.declare_parameter("verbose", False).value

    def dump(self, items: list) -> None:
        if self.verbose:
            shown = []
        for item in items:
            self.record(item)
        if self.verbose:  # record() may have changed it, or may not
            self.get_logger().info(str(shown))

    def dump_forced(self, items: list) -> None:
        if self.verbose:
            shown = []
        self.verbose = True
        for item in items:
            self.record(item)
        if self.verbose:
            # a bug, but a path whose two tests read one attribute the analysis
            # cannot tie (record() may set it) is not surely one a run takes
            self.get_logger().info(str(shown))

    def record(self, item: object) -> None:
        self.get_logger().info(str(item))


def platform_speed() -> float:
    import platform

    if platform.system() == "Linux":
        speed = 0.2
    print("checking")
    if platform.system() == "Linux":
        return speed  # the same call asked the same question
    return 0.0


if platform_speed() > 0.1:
    FAST = True
if platform_speed() > 0.1:  # module code: the platform or version, mostly
    print(FAST)


def describe(event: object) -> str:
    if isinstance(event, Twist):
        kind = "twist"
    elif callable(event):
        kind = "callback"
    return kind  # a case analysis its author may have made exhaustive
