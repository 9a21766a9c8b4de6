# rclpy (ROS 2), checked against ros2/rclpy rclpy/__init__.py (rolling, 2024-12).
from typing import Annotated

from rclpy.node import Node
from rclpy.task import Future

def create_node(
    node_name: str,
    *,
    context: object = None,
    cli_args: object = None,
    namespace: object = None,
) -> Node: ...
def spin(node: Node, executor: object = None) -> None: ...
def spin_once(
    node: Node,
    *,
    executor: object = None,
    timeout_sec: Annotated[float, "Unit('s')"] = None,
) -> None: ...
def spin_until_future_complete(
    node: Node,
    future: Future,
    executor: object = None,
    timeout_sec: Annotated[float, "Unit('s')"] = None,
) -> None: ...
