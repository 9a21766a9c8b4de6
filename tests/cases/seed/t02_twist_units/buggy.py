"""T2 (thesis A.2): angular.z is in rad/s; z is annotated degree/s."""
from typing_extensions import Annotated
import rospy
from geometry_msgs.msg import Twist
pub = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
x : Annotated[float, "Unit('m/s')"]
z : Annotated[float, "Unit('degree/s')"]
x = 5
z = 6
move = Twist()
move.linear.x = x
move.angular.z = z  # error: RF201
pub.publish(move)

rospy.spin()
