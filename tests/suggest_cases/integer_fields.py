"""A name that reaches an integer field with a unit (`Duration.sec`) gets
`Annotated[int, ...]`: `float` made the applied file fail with RF401 (nav2's
`spin(time_allowance=10)` into `Duration(sec=time_allowance)`)."""

from builtin_interfaces.msg import Duration

TIMEOUT = 30  # suggest: TIMEOUT s int


def allowance(time_allowance=10):  # suggest: time_allowance s int
    return Duration(sec=time_allowance)


def later(delay=2.5):  # near miss: a float default, into an int field
    return Duration(sec=delay)


def main():
    allowance(TIMEOUT)
    later()
