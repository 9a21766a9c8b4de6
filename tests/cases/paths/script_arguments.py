"""A rospy script: arguments checked twice with the same test agree, a branch that
ends in sys.exit() does not reach the read; a list that changed in between does
not keep its length."""
import sys

import rospy
from std_msgs.msg import String

if len(sys.argv) == 2:
    topic = sys.argv[1]
elif len(sys.argv) == 1:
    topic = "chatter"
else:
    print("usage: talker.py [topic]")
    sys.exit(1)

if len(sys.argv) > 2:
    rate_hz = float(sys.argv[2])
if len(sys.argv) > 2:
    rospy.loginfo(f"rate {rate_hz}")


def first_word(words: list) -> None:
    if len(words) > 0:
        first = words[0]
    words.append("hello")
    if len(words) > 0:
        rospy.loginfo(first)  # error: RF301


rospy.init_node("talker")
pub = rospy.Publisher(topic, String, queue_size=10)
