"""T8 (thesis A.11): both fields set before the message is published."""
from typing_extensions import Annotated
import rospy
from geometry_msgs.msg import Twist

pub = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
y : Annotated[float, "Unit('m/s')"]
y = 5
move = Twist()
move.linear.x = 1
move.linear.y = y
pub.publish(move)

rospy.spin()
