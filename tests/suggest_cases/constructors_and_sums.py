"""Keyword arguments of message constructors, sums, and conditional values."""

from geometry_msgs.msg import Point, Vector3

OFFSET_X = 0.05  # suggest: OFFSET_X m


class Marker:
    def __init__(self, base_x, base_y):  # suggest: base_x m, base_y m
        self.base_x = base_x  # suggest: base_x m
        self.base_y = base_y  # suggest: base_y m
        self.scale = 2.0  # near miss: multiplies a length, has no unit of its own

    def tip(self, up):
        height = 0.3 if up else -0.3  # suggest: height m
        return Point(x=self.base_x + OFFSET_X, y=self.base_y, z=abs(height))

    def grown(self, size):
        return Vector3(x=size * self.scale)

    def reused(self, n):
        value = 0.0  # near miss: bound twice, the second time by a loop
        for value in range(n):
            print(value)
        return Point(x=float(value))
