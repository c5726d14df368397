"""``python -m solver``: the same command line as ``teleop-ui``."""

import sys

from solver.cli import main

sys.exit(main())
