"""RF401 on message fields: a float into an int32 field fails in ROS 2 at runtime."""
from std_msgs.msg import Int32, Float64

i = Int32()
i.data = 1.5  # error: RF401
f = Float64()
f.data = 1
