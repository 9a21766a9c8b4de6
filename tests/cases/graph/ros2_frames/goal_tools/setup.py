from setuptools import setup

setup(
    name='goal_tools',
    packages=['goal_tools'],
    entry_points={
        'console_scripts': [
            'goal_checker = goal_tools.goal_checker:main',
            'ahead = goal_tools.ahead:main',
            'inspection = goal_tools.inspection:main',
            'clicked = goal_tools.clicked:main',
            'patrol_goals = goal_tools.patrol_goals:main',
        ],
    },
)
