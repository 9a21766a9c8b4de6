"""A script-style node: its refined helper names an imported constant, and its
module code calls it (the constant's value is the binding on that path)."""
from typing import Annotated

from alias_pkg.limits import MAX_SPEED


def send(speed: Annotated[float, "Unit('m/s') and 0 <= _ <= MAX_SPEED"]) -> None:
    print(speed)


if __name__ == "__main__":
    send(0.4)
    send(MAX_SPEED)
    send(0.6)  # error: RF101
