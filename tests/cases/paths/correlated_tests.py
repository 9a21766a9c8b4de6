"""RF301 only on a path whose branch decisions are independent: two tests that read
a common attribute or a local rebound between them may be tied by facts about the
data the analysis does not track (array shapes, a credential found only for some
URLs, a list filled in the branch that bound the name). A handler of a named
exception around a lone `for` loop catches what the body raised, after the loop
variable was bound. Each has a near miss that is a bug on a path a run surely
takes."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class ParseError(Exception):
    pass


def parse_waypoint(text: str) -> float:
    if not text:
        raise ParseError(text)
    return float(text)


class Mixer(Node):
    def __init__(self) -> None:
        super().__init__("mixer")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(LaserScan, "scan", self.on_scan, 10)

    def blend(self, left: object, right: object, out: object) -> object:
        # shapes of different arrays: the caller sized `out` from the other two
        if right.shape[-1] == 3:
            z_right = right[2]
        if out.shape[-1] == 3:
            z_out = out[2]
        if left.shape[-1] == 2:
            if right.shape[-1] == 2:
                return left[0] * right[1] - left[1] * right[0]
            z_out = left[1] * z_right
        return z_out

    def gain(self, fast: bool, boost: bool) -> float:
        if fast:
            gain = 2.0
        if boost:
            return gain  # error: RF301
        return 1.0

    def credential(self, scheme: str, host: str, lookup: dict) -> str:
        if scheme in ("http", "https"):
            user, address = host.split("@")
        else:
            user = None
        if not user:
            found = lookup.get(host)
            if found:
                user = str(found)
        if user:
            return user + "@" + address  # `found` only for http hosts
        return host

    def credential_plain(self, scheme: str, host: str, verbose: bool) -> str:
        if scheme in ("http", "https"):
            address = host.split("@")[1]
        if verbose:
            self.get_logger().info(f"proxy {address}")  # error: RF301
        return host

    def on_scan(self, scan: LaserScan) -> None:
        if scan.range_min > 0.5:
            speed = 0.2
        elif scan.range_min > 0.2:
            speed = 0.1
        if scan.range_max > 10.0:
            cmd = Twist()
            cmd.linear.x = speed  # error: RF301
            self.pub.publish(cmd)

    def waypoints(self, lines: list) -> list:
        points = []
        try:
            for line in lines:
                points.append(parse_waypoint(line))
        except ParseError:
            self.get_logger().error(f"bad waypoint {line!r}")
            return []
        return points

    def waypoints_then_check(self, lines: list) -> list:
        points = []
        try:
            for line in lines:
                points.append(parse_waypoint(line))
            parse_waypoint("0.0")
        except ParseError:
            self.get_logger().error(f"bad waypoint {line!r}")  # error: RF301
            return []
        return points


class Recorder(Node):
    def __init__(self) -> None:
        super().__init__("recorder")
        self.depth = 0

    def save(self, path: str, rows: list) -> None:
        try:
            self.depth += 1
            with open(path, "w") as out:
                for row in rows:
                    out.write(str(parse_waypoint(row)))
        except ParseError:
            out.write("truncated")
        finally:
            self.depth -= 1

    def save_checked(self, path: str, rows: list) -> None:
        try:
            parse_waypoint(path)
            with open(path, "w") as out:
                for row in rows:
                    out.write(str(parse_waypoint(row)))
        except ParseError:
            out.write("truncated")  # error: RF301


def pairs(readings):
    it = iter(readings)
    try:
        current = next(it)
    except StopIteration:
        return
    try:
        for index in range(1_000_000):
            previous = current
            current = next(it)
            yield index, previous, False
    except StopIteration:
        yield index, previous, True


def main() -> None:
    rclpy.init()
    rclpy.spin(Mixer())


if __name__ == "__main__":
    main()
