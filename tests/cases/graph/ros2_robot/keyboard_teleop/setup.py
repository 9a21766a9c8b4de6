from setuptools import setup

package_name = 'keyboard_teleop'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    entry_points={
        'console_scripts': [
            'teleop = keyboard_teleop.teleop:main',
            'monitor = keyboard_teleop.monitor:main',
            'obstacle_stop = keyboard_teleop.obstacle_stop:main',
        ],
    },
)
