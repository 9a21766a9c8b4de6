"""RF301: an annotated variable read before any assignment."""
from typing import Annotated

limit: Annotated[float, "_ > 0"]
speed: Annotated[float, "_ < 10"] = limit  # error: RF301
limit = 3
ok: Annotated[float, "_ < 10"] = limit


def later(flag: bool) -> None:
    x: Annotated[int, ""]
    if flag:
        x = 1
    # unset on one path only: not an error, but nothing bounds x there
    y: Annotated[int, "_ < 5"] = x  # warning: RF102
