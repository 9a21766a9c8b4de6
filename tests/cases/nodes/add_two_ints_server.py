"""A ROS 2 service server: requests arrive refined, responses leave checked."""
from rclpy.node import Node

from example_pkg.srv import AddTwoInts


class Adder(Node):
    def __init__(self) -> None:
        super().__init__("adder")
        self.create_service(AddTwoInts, "add", self.add)
        self.create_service(AddTwoInts, "subtract", self.subtract)
        self.create_service(AddTwoInts, "broken", self.broken)

    def add(self, request, response):
        response.sum = request.a + request.b
        return response

    def subtract(self, request, response):
        response.sum = request.a - request.b  # warning: RF102
        return response

    def broken(self, request, response):
        response.sum = -1  # error: RF101
        return response


def call(node: Node) -> None:
    client = node.create_client(AddTwoInts, "add")
    good = AddTwoInts.Request(a=1, b=2)
    client.call_async(good)
    bad = AddTwoInts.Request()
    bad.a = -5  # error: RF101
