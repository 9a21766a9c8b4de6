"""`python -m robotfix` runs the command line."""

from robotfix.cli import run

run()
