"""T5 (thesis A.5): Int32.data must be 1, 2 or 3 (imported from the bare package)."""
from std_msgs import Int32

v = Int32()

v.data = 10  # error: RF101
