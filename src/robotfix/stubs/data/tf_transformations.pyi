# tf_transformations (ROS 2) and tf.transformations (ROS 1), after Gohlke's
# transformations.py: euler_from_quaternion(quaternion, axes='sxyz') -> (ai, aj, ak)
# in rad; quaternion_from_euler(ai, aj, ak, axes='sxyz') takes rad.
from typing import Annotated

def euler_from_quaternion(
    quaternion: object, axes: str = "sxyz"
) -> tuple[
    Annotated[float, "Unit('rad')"],
    Annotated[float, "Unit('rad')"],
    Annotated[float, "Unit('rad')"],
]: ...
def quaternion_from_euler(
    ai: Annotated[float, "Unit('rad')"],
    aj: Annotated[float, "Unit('rad')"],
    ak: Annotated[float, "Unit('rad')"],
    axes: str = "sxyz",
) -> object: ...
def euler_from_matrix(
    matrix: object, axes: str = "sxyz"
) -> tuple[
    Annotated[float, "Unit('rad')"],
    Annotated[float, "Unit('rad')"],
    Annotated[float, "Unit('rad')"],
]: ...
def euler_matrix(
    ai: Annotated[float, "Unit('rad')"],
    aj: Annotated[float, "Unit('rad')"],
    ak: Annotated[float, "Unit('rad')"],
    axes: str = "sxyz",
) -> object: ...
