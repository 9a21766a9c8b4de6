"""T9 (thesis A.9): Quaternion.x must lie in [0, 3.14]."""
from geometry_msgs import Quaternion

qt = Quaternion()
qt.x = 1
