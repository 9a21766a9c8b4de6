from setuptools import setup

setup(
    name='joined_drive',
    packages=['joined_drive'],
    entry_points={
        'console_scripts': [
            'guard = joined_drive.guard:main',
            'mover = joined_drive.mover:main',
        ],
    },
)
