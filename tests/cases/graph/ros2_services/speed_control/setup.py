from setuptools import setup

setup(
    name='speed_control',
    packages=['speed_control'],
    entry_points={
        'console_scripts': [
            'limit_server = speed_control.limit_server:main',
            'cruise = speed_control.cruise:main',
            'docking = speed_control.docking:main',
            'joy_limit = speed_control.joy_limit:main',
            'fleet = speed_control.fleet:main',
        ],
    },
)
