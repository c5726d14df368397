"""Tests of ``teleop-ui check`` (:mod:`solver.check`), one module per module of the package."""
