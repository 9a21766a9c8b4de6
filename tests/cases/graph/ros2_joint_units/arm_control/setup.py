from setuptools import setup

setup(
    name='arm_control',
    packages=['arm_control'],
    entry_points={
        'console_scripts': [
            'controller = arm_control.controller:main',
            'dial = arm_control.dial:main',
            'slider = arm_control.slider:main',
            'home = arm_control.home:main',
        ],
    },
)
