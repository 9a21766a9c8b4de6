from setuptools import setup

setup(
    name='speed_control',
    packages=['speed_control'],
    entry_points={
        'console_scripts': [
            'boost_server = speed_control.boost_server:main',
            'scale_server = speed_control.scale_server:main',
            'clamp_server = speed_control.clamp_server:main',
            'cruise = speed_control.cruise:main',
            'turbo_server = speed_control.turbo_server:main',
            'cruise_async = speed_control.cruise_async:main',
            'async_cruise = speed_control.async_cruise:main',
        ],
    },
)
