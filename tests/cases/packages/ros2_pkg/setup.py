from setuptools import setup

setup(
    name="my_pkg",
    version="0.1.0",
    packages=["my_pkg"],
    entry_points={"console_scripts": ["driver = my_pkg.driver:main"]},
)
