"""``python -m solver``: the same command line as ``teleop-ui``."""

from solver.cli import console

console()
