"""RF401: int may flow into float, not the reverse; str is not a number."""
from typing import Annotated

count: Annotated[int, ""] = 3
ratio: Annotated[float, ""] = count
count = 2.5  # error: RF401
name: Annotated[str, "_ != ''"] = "base_link"
name = 3  # error: RF401
flag: Annotated[bool, ""] = True
total: Annotated[int, ""] = flag
