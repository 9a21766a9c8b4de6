from setuptools import setup

setup(
    name='patrol',
    packages=['patrol'],
    entry_points={
        'console_scripts': [
            'patrol_server = patrol.patrol_server:main',
            'patrol_client = patrol.patrol_client:main',
            'square_patrol = patrol.square_patrol:main',
            'circle_patrol = patrol.circle_patrol:main',
        ],
    },
)
