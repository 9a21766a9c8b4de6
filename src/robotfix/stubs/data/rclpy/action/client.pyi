# rclpy.action.client (ROS 2): ActionClient.wait_for_server(self, timeout_sec=None)
from typing import Annotated

class ActionClient:
    def wait_for_server(
        self, timeout_sec: Annotated[float, "Unit('s')"] = None
    ) -> bool: ...
