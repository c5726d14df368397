"""Tests of the command line (:mod:`solver.cli`): each command's ``test_<command>.py``, main()
itself (``test_cli.py``), the shared options, terminal and progress (``test_common.py``,
``test_terminal.py``, ``test_progress.py``), and hostile files, values and outputs given to
every command, end to end (``test_hostile_*.py``)."""
