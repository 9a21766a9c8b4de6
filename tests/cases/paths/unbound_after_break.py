"""RF301 after a loop left by a `break` before the name is bound: the first
iteration can take the `break` (a port with nothing to read, a node shut down
before the first lookup), and the name is then unbound after the loop. A `break`
only after the binding, a `break` that a flag from before the loop rules out in the
first iteration, a guard flag tested after the loop, a `break` of an inner loop,
an `else` that binds the name, and a test after the loop that tells the early exit
apart (a negative `errno` code, known to be negative) are fine."""
import errno
import time

import rclpy
import rospy
import serial
from rclpy.node import Node
from std_msgs.msg import Float64


def last_reading(port: serial.Serial) -> float:
    while True:
        line = port.readline()
        if not line:
            break
        reading = float(line)
    return reading  # error: RF301


def wait_for_transform(buffer, target: str, source: str):
    for attempt in range(10):
        if rospy.is_shutdown():
            break
        trans = buffer.lookup_transform(target, source, rospy.Time(0))
    return trans  # error: RF301


def first_good_reading(port: serial.Serial) -> float:
    while True:
        line = port.readline()
        reading = float(line)
        if reading > 0.0:
            break
    return reading


def read_until_done(port: serial.Serial) -> float:
    done = False
    while True:
        if done:
            break  # never in the first iteration: `done` is still False
        reading = float(port.readline())
        done = True
    return reading


def read_if_ready(port: serial.Serial) -> None:
    got = False
    while not rospy.is_shutdown():
        if not port.in_waiting:
            break
        reading = float(port.readline())
        got = True
        break
    if got:
        rospy.loginfo("read %f", reading)


def inner_break(ports: list) -> float:
    for attempt in range(3):
        for port in ports:
            if port.busy:
                break  # leaves the inner loop only
        reading = float(ports[0].readline())
    return reading


def with_default(port: serial.Serial) -> float:
    for attempt in range(3):
        if port.busy:
            reading = 0.0
            break
    else:
        reading = float(port.readline())
    return reading


def else_misses_the_break(port: serial.Serial) -> float:
    for attempt in range(3):
        if port.busy:
            break
        reading = float(port.readline())
    else:
        reading = 0.0
    return reading  # error: RF301


def request_topic(api, topic: str):
    """rospy's masterslave: a refused connection leaves the retry loop with a
    negative code and no result; the code is tested before the result is read."""
    success = False
    while not success and not rospy.is_shutdown():
        try:
            code, msg, result = api.requestTopic(topic)
            success = True
        except OSError as e:
            if e.errno == errno.ECONNREFUSED:
                code = -errno.ECONNREFUSED
                msg = str(e)
                break
            time.sleep(1.0)
    if code <= 0:  # error: RF301
        return code, msg, 0
    return result[0]


def request_or_refuse(api, refused: bool):
    if refused:
        code = -errno.ECONNREFUSED
    else:
        code, result = api.request()
    if code <= 0:
        return None
    return result


def request_or_give_up(api, topic: str):
    for attempt in range(3):
        try:
            code, result = api.requestTopic(topic)
        except OSError:
            code = errno.ECONNREFUSED  # positive: not told apart below
            break
    if code <= 0:
        return None
    return result  # error: RF301


class Gauge(Node):
    def __init__(self) -> None:
        super().__init__("gauge")
        self.pub = self.create_publisher(Float64, "level", 10)
        self.port = serial.Serial("/dev/ttyUSB0")

    def poll(self) -> None:
        while rclpy.ok():
            raw = self.port.readline()
            if raw == b"":
                break
            level = float(raw) / 100.0
        self.pub.publish(Float64(data=level))  # error: RF301
