# tf.transformations (ROS 1): the same functions as tf_transformations.
from tf_transformations import euler_from_matrix as euler_from_matrix
from tf_transformations import euler_from_quaternion as euler_from_quaternion
from tf_transformations import euler_matrix as euler_matrix
from tf_transformations import quaternion_from_euler as quaternion_from_euler
