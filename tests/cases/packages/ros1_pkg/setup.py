from catkin_pkg.python_setup import generate_distutils_setup
from distutils.core import setup

setup(**generate_distutils_setup(packages=["my_robot"], package_dir={"": "src"}))
