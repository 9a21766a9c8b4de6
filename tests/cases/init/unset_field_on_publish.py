"""RF302: a field left at its default where the default breaks a refinement."""
import rospy
from std_msgs.msg import Int32

pub = rospy.Publisher("mode", Int32, queue_size=1)
unset = Int32()
pub.publish(unset)  # error: RF302
pub.publish(unset)
chosen = Int32()
chosen.data = 2
pub.publish(chosen)
built = Int32(data=3)
pub.publish(built)
wrong = Int32(data=7)  # error: RF101
