"""RF102, not RF101, when the value comes from an unannotated source."""
from typing import Annotated


def set_speed(v):
    limited: Annotated[float, "_ < 2"] = v  # warning: RF102


def set_speed_checked(v):
    assert v < 2
    limited: Annotated[float, "_ < 2"] = v


def set_speed_refined(v: Annotated[float, "0 <= _ <= 1"]):
    limited: Annotated[float, "_ < 2"] = v
