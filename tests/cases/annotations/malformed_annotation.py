"""RF5xx at the spot inside the string; the file's other annotations are still checked."""
from typing import Annotated
import typing as t

broken: Annotated[float, "_ < < 3"]  # error: RF501
unknown_function: Annotated[float, "clip(_) < 3"]  # error: RF501
typo: Annotated[float, "Unit('meterz')"]  # error: RF502 "meter"
tag_meant: Annotated[float, "Tag('meterz')"] = 1
misplaced: Annotated[float, "Unit('m') or _ > 0"]  # error: RF507
not_in_scope: Annotated[float, "_ < lmit"]  # error: RF503 "lmit"
limit = 4
in_scope: Annotated[float, "_ < limit"] = 3
still_checked: Annotated[int, "_ < 200"] = 200  # error: RF101
aliased: t.Annotated[int, "_ > 0"] = 0  # error: RF101
not_ours: Annotated[float, 3.5] = 2  # note: RF511
