"""RF301: a name bound only in a `try` body and read after a handler that does not
leave: when the body raises before the binding, the read raises. Handlers that
return, raise, continue or bind the name too are fine."""
import rclpy
from rclpy.node import Node

from example_pkg.srv import AddTwoInts


class Client(Node):
    def __init__(self) -> None:
        super().__init__("client")
        self.cli = self.create_client(AddTwoInts, "add_two_ints")

    def call(self, a: int, b: int) -> int:
        future = self.cli.call_async(AddTwoInts.Request(a=a, b=b))
        try:
            rclpy.spin_until_future_complete(self, future)
            total = future.result().sum
        except Exception as err:  # noqa: BLE001
            self.get_logger().error(f"call failed: {err!r}")
        return total  # error: RF301

    def call_returns(self, a: int, b: int) -> int:
        future = self.cli.call_async(AddTwoInts.Request(a=a, b=b))
        try:
            rclpy.spin_until_future_complete(self, future)
            total = future.result().sum
        except Exception:  # noqa: BLE001
            return 0
        return total

    def call_reraises(self, a: int, b: int) -> int:
        future = self.cli.call_async(AddTwoInts.Request(a=a, b=b))
        try:
            rclpy.spin_until_future_complete(self, future)
            total = future.result().sum
        except Exception:
            self.get_logger().error("call failed")
            raise
        return total

    def call_default(self, a: int, b: int) -> int:
        future = self.cli.call_async(AddTwoInts.Request(a=a, b=b))
        try:
            rclpy.spin_until_future_complete(self, future)
            total = future.result().sum
        except Exception:  # noqa: BLE001
            total = 0
        return total

    def call_flag(self, a: int, b: int) -> None:
        ok = False
        try:
            total = self.cli.call(AddTwoInts.Request(a=a, b=b)).sum
            ok = True
        except Exception:  # noqa: BLE001
            pass
        if ok:
            self.get_logger().info(f"sum {total}")

    def retry(self, a: int, b: int) -> int:
        for _ in range(3):
            try:
                total = self.cli.call(AddTwoInts.Request(a=a, b=b)).sum
            except Exception:  # noqa: BLE001
                continue
            return total
        return -1

    def cleanup(self, path: str) -> None:
        try:
            stream = open(path)
            stream.read()
        except OSError:
            self.get_logger().warn("cannot read")
        finally:
            stream.close()  # error: RF301
