#!/usr/bin/env python3
"""Logs the turtle's pose and colour: written against geometry_msgs' Pose2D."""
import rospy
from geometry_msgs.msg import Pose2D
from std_srvs.srv import Empty
from turtlesim.msg import Color


def on_pose(msg: Pose2D) -> None:
    rospy.loginfo('at %f %f', msg.x, msg.y)


def on_color(msg: Color) -> None:
    rospy.loginfo('colour %d', msg.r)


def main() -> None:
    rospy.init_node('follower')
    rospy.Subscriber('turtle1/pose', Pose2D, on_pose)  # error: RF603
    # near miss: the simulator's private topic, under its launch name `sim`
    rospy.Subscriber('sim/color_sensor', Color, on_color)
    clear = rospy.ServiceProxy('clear', Empty)
    clear()
    rospy.spin()


if __name__ == '__main__':
    main()
