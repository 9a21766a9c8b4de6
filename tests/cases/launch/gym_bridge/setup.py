import os
from glob import glob

from setuptools import setup

package_name = "gym_bridge"

setup(
    name=package_name,
    packages=[package_name],
    data_files=[
        (os.path.join("share", package_name, "launch"), glob("launch/*.py")),
        (os.path.join("share", package_name, "config"), glob("config/*.yaml")),
    ],
    entry_points={
        "console_scripts": [
            "gym_bridge = " + package_name + ".bridge_node:main",
            f"teleop = {package_name}.teleop:main",
        ],
    },
)
