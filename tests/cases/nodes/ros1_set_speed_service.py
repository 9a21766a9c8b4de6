"""A ROS 1 service server and client (rospy), with generated Request classes."""
from typing import Annotated

import rospy
from geometry_msgs.msg import Twist

from example_pkg.srv import SetSpeed, SetSpeedRequest, SetSpeedResponse

pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)


def handle(req):
    cmd = Twist()
    cmd.linear.x = req.speed
    limited: Annotated[float, "_ <= 2"] = req.speed
    pub.publish(cmd)
    return SetSpeedResponse(ok=True)


rospy.init_node("speed_server")
rospy.Service("set_speed", SetSpeed, handle)
proxy = rospy.ServiceProxy("set_speed", SetSpeed)
proxy(SetSpeedRequest(speed=1.5))
proxy(SetSpeedRequest(speed=3))  # error: RF101
