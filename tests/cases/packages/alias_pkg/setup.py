from setuptools import setup

setup(
    name="alias_pkg",
    version="0.1.0",
    packages=["alias_pkg"],
    entry_points={"console_scripts": ["cruise = alias_pkg.cruise:main"]},
)
