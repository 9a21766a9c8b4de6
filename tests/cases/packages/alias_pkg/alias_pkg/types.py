"""Re-exports, as a package's public module often does."""
from alias_pkg.limits import Speed, TurnRate

Cruise = Speed

__all__ = ["Cruise", "Speed", "TurnRate"]
