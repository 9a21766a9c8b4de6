# rclpy.client (ROS 2): Client.wait_for_service(self, timeout_sec=None)
from typing import Annotated

class Client:
    def wait_for_service(
        self, timeout_sec: Annotated[float, "Unit('s')"] = None
    ) -> bool: ...
