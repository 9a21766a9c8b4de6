#!/usr/bin/env python
"""A ROS 1 voice-navigation node: the command message lives in an attribute set in
__init__ and is filled in by callbacks."""

import rospy
from geometry_msgs.msg import Twist, TwistStamped
from std_msgs.msg import String


class VoiceNav:
    def __init__(self):
        rospy.init_node("voice_nav")
        self.speed = rospy.get_param("~speed", 0.3)  # suggest: speed m/s
        self.turn = rospy.get_param("~turn", 0.5)  # suggest: turn rad/s
        self.rate = rospy.get_param("~rate", 5)  # suggest: rate Hz
        self.cmd_vel = Twist()
        self.stamped = TwistStamped()
        self.echo = None  # near miss: holds whatever message arrived
        self.last = 0.0  # near miss: written into a message of unknown type
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        rospy.Subscriber("recognizer/output", String, self.on_speech)
        rospy.Subscriber("cmd_vel_in", Twist, self.on_twist)

    def on_twist(self, msg):
        self.echo = msg

    def replay(self):
        if self.echo is not None:
            self.echo.linear.x = self.last
            self.pub.publish(self.echo)

    def on_speech(self, msg):
        if msg.data == "forward":
            self.cmd_vel.linear.x = self.speed
            self.cmd_vel.angular.z = 0.0
        elif msg.data == "left":
            self.cmd_vel.angular.z = self.turn
        self.stamped.twist.linear.x = self.cmd_vel.linear.x

    def run(self):
        rate = rospy.Rate(self.rate)
        while not rospy.is_shutdown():
            self.pub.publish(self.cmd_vel)
            rate.sleep()


if __name__ == "__main__":
    VoiceNav().run()
