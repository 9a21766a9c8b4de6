"""A service whose interface files are not found (example_interfaces is not shipped):
a refinement naming its request's fields cannot be checked, which the RF508 note says;
it is no RF503 "not a variable in scope" error (the fresh-eyes round's c04 and c06)."""
from typing import Annotated

from example_interfaces.srv import AddTwoInts  # note: RF508
from rclpy.node import Node
from my_robot_msgs.msg import Limits  # note: RF508

Small = Annotated[Limits, "max_speed <= 2"]


class Adder(Node):
    def __init__(self):
        super().__init__("adder")
        self.srv = self.create_service(AddTwoInts, "add", self.on_add)

    def on_add(
        self, request: Annotated[AddTwoInts.Request, "0 <= a <= 10 and b >= 0"], response
    ):
        response.sum = request.a + request.b
        return response

    def limit(self, limits: Small) -> None:
        self.limits = limits


speed: Annotated[float, "_ <= top"] = 1.0  # error: RF503
