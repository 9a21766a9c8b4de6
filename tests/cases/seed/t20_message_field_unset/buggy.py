"""T20 (thesis A.18): linear.x is read while it still holds its default 0."""
from typing_extensions import Annotated
import rospy
from geometry_msgs.msg import Twist

pub = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
move = Twist()
x : Annotated[float, "Unit('m/s')"]
x = move.linear.x  # error: RF302
pub.publish(move)

rospy.spin()
