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
    # unset when flag is false: UnboundLocalError on that path
    y: Annotated[int, "_ < 5"] = x  # error: RF301
