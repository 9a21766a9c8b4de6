"""Plain Python (a pydantic model, no ROS import): annotated-types constraints and
unit-like strings stay silent, as other metadata does there."""
from typing import Annotated, Optional

from annotated_types import Ge, Gt, Le, MaxLen, MinLen
from pydantic import BaseModel, Field


class User(BaseModel):
    id: Annotated[int, Ge(1)]
    name: Annotated[str, MinLen(3), MaxLen(30)]
    age: Annotated[int, Ge(12), Le(120)] = 18
    score: Annotated[float, Gt(0)] = Field(default=1.0, description="score")
    nick: Optional[Annotated[str, MaxLen(10)]] = None
    height: Annotated[float, "m"] = 1.8


def older(u: User, years: int) -> int:
    age: Annotated[int, Ge(12), Le(120)] = u.age + years
    return age
