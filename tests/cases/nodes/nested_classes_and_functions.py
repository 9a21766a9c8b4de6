"""Classes and functions defined inside functions are analysed too."""
from typing import Annotated


def make_node():
    class Inner:
        def set(self) -> None:
            limit: Annotated[int, "_ < 10"] = 10  # error: RF101

    def helper() -> None:
        other: Annotated[int, "_ < 10"] = 11  # error: RF101

    return Inner, helper
