"""T15 (thesis 5.2.1): the timeout must stay below 200."""
from typing_extensions import Annotated

timeout : Annotated[int, "timeout < 200"]
timeout = 200  # error: RF101
