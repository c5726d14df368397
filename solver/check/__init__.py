"""``teleop-ui check``: a linter for rule sets and team files.

Like yamllint, it is a registry of checks (:mod:`solver.check.registry`), each with a stable
id, a level (error, warning, info), a one-paragraph description and a generator yielding
located findings. They cover what a rule author gets wrong and what feature-model tools
(FeatureIDE, flamapy) analyse on product lines:

=========================  =================================================================
``finding``                findings, levels, the :class:`Check` type
``load``                   loader faults as findings: unknown references, duplicates, schema
``coverage``               gaps, overlaps, inverted/empty/unbounded component ranges
``equivalence``            "can share a component" that is not transitive (witness triples)
``void``                   void rule sets and kinematic types, minimal conflicts
``dead``                   dead values and components (and per kinematic type)
``forced``                 values and components forced for every robot of a type (``core-*``)
``redundancy``             redundant (entailed) and tautological constraints
``bound``                  the bound T and a declared bound that differs
``teams``                  teams against their rules: forbidden selections, void teams
``context``                what checks read, and how they locate and name things
``registry``               every check, by id
``runner``                 files -> :class:`Report`
``render``                 text, parsable, JSON, SARIF 2.1.0
=========================  =================================================================

The constraint analysis the checks ask (live values, minimal conflicts, excluded regions) is
:mod:`solver.core.analysis` and :mod:`solver.core.regions`: solving uses it too.

Not here: the command line (:mod:`solver.cli.check`).
"""

from solver.check.finding import LEVELS, Check, Finding, Level, Related
from solver.check.registry import ALL_CHECKS, check_ids, get
from solver.check.render import FORMATS, render
from solver.check.runner import Report, check_files

__all__ = [
    "ALL_CHECKS",
    "FORMATS",
    "LEVELS",
    "Check",
    "Finding",
    "Level",
    "Related",
    "Report",
    "check_files",
    "check_ids",
    "get",
    "render",
]
