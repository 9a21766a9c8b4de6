"""T8 (thesis A.5b): `x` is never defined, and linear.x keeps its default 0."""
from typing_extensions import Annotated
import rospy
from geometry_msgs.msg import Twist

pub = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
y : Annotated[float, "Unit('m/s')"]
y = 5
move = Twist()
move.linear.y = x  # error: RF301
pub.publish(move)  # error: RF302

rospy.spin()
