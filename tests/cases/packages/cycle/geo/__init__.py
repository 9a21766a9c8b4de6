"""A package whose modules import each other; its __init__ re-exports."""
from .angles import wrap
from .speeds import LIMIT as SPEED_LIMIT

__all__ = ["wrap", "SPEED_LIMIT"]
