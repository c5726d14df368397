"""Tests of the command line (:mod:`solver.cli`) run end to end: hostile files, values and
outputs given to every command."""
