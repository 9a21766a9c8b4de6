"""ROS 1 has no default values: a rospy node's `Quaternion()` has w = 0.0, which
breaks the team's `w > 0` overlay (issue 8, item 2)."""
import rospy
from geometry_msgs.msg import PoseStamped, Quaternion


def publish_identity(pub: rospy.Publisher) -> None:
    q = Quaternion()
    q.w = 1.0
    pub.publish(q)


def publish_unset(pub: rospy.Publisher) -> None:
    pub.publish(Quaternion())  # error: RF302


def publish_goal(pub: rospy.Publisher, x: float) -> None:
    goal = PoseStamped()
    goal.header.frame_id = "map"
    goal.pose.position.x = x
    pub.publish(goal)  # error: RF302


if __name__ == "__main__":
    rospy.init_node("goal_sender")
    publish_identity(rospy.Publisher("orientation", Quaternion, queue_size=1))
