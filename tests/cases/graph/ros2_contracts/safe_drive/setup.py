from setuptools import setup

setup(
    name='safe_drive',
    packages=['safe_drive'],
    entry_points={
        'console_scripts': [
            'limiter = safe_drive.limiter:main',
            'planner = safe_drive.planner:main',
            'teleop = safe_drive.teleop:main',
            'joystick = safe_drive.joystick:main',
        ],
    },
)
