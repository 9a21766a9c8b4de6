"""RF301 after a retry loop: a name bound only in a `try` body inside a loop is
unbound after the loop when every attempt may raise and be handled (the loop then
ends without binding it). A loop left only by a `break` after the binding, a guard
flag set with the binding (tested after the loop or in the `while` test), a handler
that gives up (`raise`, `return`) or binds the name too are fine."""
import socket
import time

import rclpy
import rospy
from rclpy.node import Node
from std_msgs.msg import String


def connect_with_retries(host: str, port: int) -> None:
    for attempt in range(3):
        try:
            conn = socket.create_connection((host, port), timeout=1.0)
            break
        except OSError:
            time.sleep(0.5)
            continue
    conn.sendall(b"hello")  # error: RF301


def connect_until_shutdown(host: str, port: int) -> None:
    while not rospy.is_shutdown():
        try:
            conn = socket.create_connection((host, port), timeout=1.0)
            break
        except OSError:
            rospy.logwarn("driver not up yet")
            rospy.sleep(1.0)
    conn.sendall(b"hello")  # error: RF301


def connect_forever(host: str, port: int) -> None:
    while True:
        try:
            conn = socket.create_connection((host, port), timeout=1.0)
            break
        except OSError:
            time.sleep(0.5)
    conn.sendall(b"hello")


def connect_with_flag(host: str, port: int) -> None:
    ok = False
    for attempt in range(3):
        try:
            conn = socket.create_connection((host, port), timeout=1.0)
            ok = True
            break
        except OSError:
            continue
    if ok:
        conn.sendall(b"hello")


def connect_until_connected(host: str, port: int) -> None:
    connected = False
    while not connected:
        try:
            conn = socket.create_connection((host, port), timeout=1.0)
            connected = True
        except OSError:
            time.sleep(0.5)
    conn.sendall(b"hello")


def connect_or_give_up(host: str, port: int) -> None:
    for attempt in range(3):
        try:
            conn = socket.create_connection((host, port), timeout=1.0)
            break
        except OSError:
            if attempt == 2:
                raise
            time.sleep(0.5)
    conn.sendall(b"hello")


def connect_with_fallback(host: str, port: int) -> None:
    for attempt in range(3):
        try:
            conn = socket.create_connection((host, port), timeout=1.0)
            break
        except OSError:
            conn = None
    if conn is not None:
        conn.sendall(b"hello")


def connect_else_raises(host: str, port: int) -> None:
    for attempt in range(3):
        try:
            conn = socket.create_connection((host, port), timeout=1.0)
            break
        except OSError:
            continue
    else:
        raise RuntimeError("no driver")
    conn.sendall(b"hello")


class Bridge(Node):
    def __init__(self) -> None:
        super().__init__("bridge")
        self.pub = self.create_publisher(String, "status", 10)

    def open_port(self, path: str) -> None:
        attempts = 0
        while attempts < 5:
            try:
                port = open(path, "rb")
                break
            except OSError as err:
                self.get_logger().warn(f"{path}: {err}")
                attempts += 1
        self.pub.publish(String(data=port.name))  # error: RF301

    def open_port_checked(self, path: str) -> None:
        opened = False
        attempts = 0
        while attempts < 5 and not opened:
            try:
                port = open(path, "rb")
                opened = True
            except OSError:
                attempts += 1
        if opened:
            self.pub.publish(String(data=port.name))


def connect_then_check(host: str, port: int) -> None:
    for attempt in range(3):
        ok = False
        try:
            conn = socket.create_connection((host, port), timeout=1.0)
            ok = True
        except OSError:
            time.sleep(0.5)
        if not ok:
            return  # gives up after the first failure
        break
    conn.sendall(b"hello")


def read_until_value(values: list[int]) -> None:
    for i in range(3):
        if i == 2:
            last = values[i]
    rospy.loginfo(f"{last}")  # bound on the last pass: no error (only the `try` shape counts)


def wait_for_service_node(node: Node) -> None:
    client = node.create_client(String, "status")
    while rclpy.ok():
        try:
            future = client.call_async(String())
            rclpy.spin_until_future_complete(node, future)
            reply = future.result()
            break
        except RuntimeError:
            node.get_logger().warn("retrying")
    node.get_logger().info(f"{reply}")  # error: RF301
