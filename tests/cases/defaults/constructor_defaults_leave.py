"""A message built by a constructor that leaves a field out gives that field its
default (issue 22, section 2): RF302 when the default breaks the field's refinement
and the message leaves the node: published, a service request (rclpy's
`call_async`, rospy's `proxy(request)` and `proxy.call`), a service response, an
action goal. Each has its correct form beside it."""
import rclpy
import rospy
from rclpy.action import ActionClient
from rclpy.node import Node
from robot_msgs.action import Dock
from robot_msgs.srv import SetMode, SetModeRequest, SetModeResponse
from sensor_msgs.msg import Range

MODE_DOCKING = 2


class DockingSupervisor(Node):
    def __init__(self) -> None:
        super().__init__("docking_supervisor")
        self.mode_client = self.create_client(SetMode, "set_mode")
        self.create_service(SetMode, "supervisor_mode", self.on_set_mode)
        self.dock_client = ActionClient(self, Dock, "dock")
        self.range_pub = self.create_publisher(Range, "dock_range", 10)

    def start_docking(self) -> None:
        self.mode_client.call_async(SetMode.Request(timeout=2.0))  # error: RF302
        self.mode_client.call_async(SetMode.Request(mode=MODE_DOCKING, timeout=2.0))
        goal = Dock.Goal(dock_id="charger_1")
        self.dock_client.send_goal_async(goal)  # error: RF302
        self.dock_client.send_goal_async(
            Dock.Goal(dock_id="charger_1", approach_speed=0.1)
        )

    def report(self, distance: float) -> None:
        self.range_pub.publish(Range(range=distance, min_range=0.05))  # error: RF302
        self.range_pub.publish(Range(range=distance, min_range=0.05, max_range=4.0))

    def on_set_mode(
        self, request: SetMode.Request, response: SetMode.Response
    ) -> SetMode.Response:
        if request.mode == MODE_DOCKING:
            return SetMode.Response(ok=True)  # error: RF302
        return SetMode.Response(ok=True, code=1)


def handle_set_mode(request: SetModeRequest) -> SetModeResponse:
    if request.timeout > 10.0:
        return SetModeResponse(ok=False)  # error: RF302
    return SetModeResponse(ok=True, code=1)


def ros1_main() -> None:
    rospy.init_node("mode_switcher")
    rospy.Service("mode_switcher/set_mode", SetMode, handle_set_mode)
    set_mode = rospy.ServiceProxy("set_mode", SetMode)
    set_mode(SetModeRequest(timeout=2.0))  # error: RF302
    set_mode(SetModeRequest(mode=MODE_DOCKING, timeout=2.0))
    set_mode.call(SetModeRequest(timeout=2.0))  # error: RF302


def main() -> None:
    rclpy.init()
    rclpy.spin(DockingSupervisor())
