"""T7 (thesis A.7): Float64.data holds seconds, never negative."""
from std_msgs import Float64

time = Float64()

time.data = -1  # error: RF101
