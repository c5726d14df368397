"""Teleoperation UI configurations for heterogeneous robot teams, as a constraint problem.

After Mortimer, Horan and Seyedmahmoudian, "Building a Relationship between Robot
Characteristics and Teleoperation User Interfaces", Sensors 17(3):587 (2017). Robots are
described by characteristics (kinematic type, motion control, sensor type, number of sensors,
or any of the user's own); relationship rules map every value to the UI component that serves
it; a team selection says which values each kinematic type may take. The solver enumerates the
valid robots and partitions them into the fewest UI configurations.

Modules, one concept each:

=====================  ==========================================================
``errors``             the exception root and located faults
``inputfile``          reading input files with a size limit, located failures
``yamlio``             safe YAML loading with line/column for every value
``reader``             typed, fault-collecting access to a loaded document
``filekind``           which kind of file a document is: team, rule set or profile
``rules``              rule sets: characteristics, components, :func:`load_rules`
``constraints``        constraints between values, as data
``team``               team selections, :func:`load_team`
``forbidden``          selected values a team's constraints leave no robot for
``model``              the python-constraint model; valid robots
``partition``          robots -> UI configurations, numbering
``engines``            counting and enumerating: ``structure``, ``fast``, ``csp``,
                       the exact minimum ``cover``; the limits
``solution``           :func:`solve` a team -> :class:`Solution`
``listing``            every valid robot with its configuration number (CSV, JSONL)
``symbolic``           counts as formulas of a type's maximum sensor count
``assignment``         :func:`assign` one combination -> :class:`Assignment`
``reproduce``          published figures beside computed ones
``render``             text / JSON / CSV / Markdown rendering of solutions
``markdown``           escaping names from user files in Markdown
``plot``               radar chart (the article's Figure 9) and bar chart, PNG/SVG/PDF
``report``             self-contained HTML and Markdown reports of a solved team
``atomic``             writing output files atomically
``batch``              many teams at once: parallel solving, summary, up-to-date skipping
``identify``           real robots from ROS metadata (URDF, xacro, SRDF, topics, bags)
``live``               live UI assignment on a ROS 2 graph or a ROS 1 master (``watch``)
``layouts``            UI configurations -> Foxglove/Lichtblick and RViz2 layouts
``uvl``                a team's design space as a UVL feature model
``check``              linting rule sets and teams: coverage, void, dead, conflicts
``extras``             optional dependencies and the error when one is missing
``cli``                the ``teleop-ui`` command line
=====================  ==========================================================

Every command from Python (docs/python-api.md has worked examples):

==============================  ========================================================
``teleop-ui solve TEAM``        ``solve(load_team("case3"))`` -> :class:`Solution`;
                                ``.to_dict()`` is the JSON output, ``.records()`` a table
``solve --plot``, ``report``    ``write_plot(solution, path)``, ``write_report(...)``
``assign``                      ``assign(solution, kinematic_type="UAV", ...)``
``count FILE``                  ``solve(team, count_only=True)``; a rule set's whole
                                design space: ``solver.team.full_team(load_rules(path))``
``count --symbolic``            ``solver.symbolic.formulas(team)``
``robots``                      ``solver.listing.numbered_robots(solution)``
``reproduce``                   ``compare()``
``check FILES``                 ``check_files(paths)``
``identify``, ``fleet``         ``identify_urdf(text, ...)``, ``identify_fleet(...)``
``watch``, ``assign --master``  ``Watcher``, ``assign_from_master(...)``
``batch``                       ``find_teams``, ``plan``, ``run_batch``, ``write_summary``
``layouts``                     ``solver.layouts.writer.write_layouts(solution, profile, dir)``
``export --format uvl``         ``solver.uvl.team_to_uvl(team)``
==============================  ========================================================

Example::

    >>> from solver import load_team, solve
    >>> solution = solve(load_team("rules/teams/case1.yaml"))
    >>> solution.totals.valid_robots, solution.totals.ui_configurations
    (30, 6)
"""

# The public API is loaded lazily (PEP 562): `import solver` and the command line stay fast,
# and each name is imported from its module on first use. Keep _EXPORTS and the TYPE_CHECKING
# imports and __all__ in step (tests/test_api.py checks they match).
from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

if TYPE_CHECKING:
    from solver.assignment import Assignment, assign, parse_combination
    from solver.batch import Outcome, find_teams, plan, run_batch, write_summary
    from solver.check import Finding, check_files
    from solver.constraints import Condition, RuleConstraint
    from solver.errors import Fault, InputError, Location, RulesError, SolverError, TeamError
    from solver.identify import Identification, IdentificationCache, identify_fleet, identify_urdf
    from solver.live import MasterError, Watcher, assign_from_master
    from solver.model import Robot, build_problem, robots
    from solver.partition import Configuration
    from solver.plot import bars_figure, radar_figure, write_plot
    from solver.report import render_html, render_markdown, write_report
    from solver.reproduce import Comparison, compare
    from solver.rules import Characteristic, Component, RuleSet, default_rules_path, load_rules
    from solver.solution import Solution, TypeSummary, solve
    from solver.team import Published, Team, TypeSelection, load_team

_EXPORTS = {
    "Assignment": "solver.assignment",
    "Characteristic": "solver.rules",
    "Comparison": "solver.reproduce",
    "Component": "solver.rules",
    "Condition": "solver.constraints",
    "Configuration": "solver.partition",
    "Fault": "solver.errors",
    "Finding": "solver.check",
    "Identification": "solver.identify",
    "IdentificationCache": "solver.identify",
    "InputError": "solver.errors",
    "Location": "solver.errors",
    "MasterError": "solver.live",
    "Outcome": "solver.batch",
    "Published": "solver.team",
    "Robot": "solver.model",
    "RuleConstraint": "solver.constraints",
    "RuleSet": "solver.rules",
    "RulesError": "solver.errors",
    "Solution": "solver.solution",
    "SolverError": "solver.errors",
    "Team": "solver.team",
    "TeamError": "solver.errors",
    "TypeSelection": "solver.team",
    "TypeSummary": "solver.solution",
    "Watcher": "solver.live",
    "assign": "solver.assignment",
    "assign_from_master": "solver.live",
    "bars_figure": "solver.plot",
    "build_problem": "solver.model",
    "check_files": "solver.check",
    "compare": "solver.reproduce",
    "default_rules_path": "solver.rules",
    "find_teams": "solver.batch",
    "identify_fleet": "solver.identify",
    "identify_urdf": "solver.identify",
    "load_rules": "solver.rules",
    "load_team": "solver.team",
    "parse_combination": "solver.assignment",
    "plan": "solver.batch",
    "radar_figure": "solver.plot",
    "render_html": "solver.report",
    "render_markdown": "solver.report",
    "robots": "solver.model",
    "run_batch": "solver.batch",
    "solve": "solver.solution",
    "write_plot": "solver.plot",
    "write_report": "solver.report",
    "write_summary": "solver.batch",
}

__all__ = [
    "Assignment",
    "Characteristic",
    "Comparison",
    "Component",
    "Condition",
    "Configuration",
    "Fault",
    "Finding",
    "Identification",
    "IdentificationCache",
    "InputError",
    "Location",
    "MasterError",
    "Outcome",
    "Published",
    "Robot",
    "RuleConstraint",
    "RuleSet",
    "RulesError",
    "Solution",
    "SolverError",
    "Team",
    "TeamError",
    "TypeSelection",
    "TypeSummary",
    "Watcher",
    "assign",
    "assign_from_master",
    "bars_figure",
    "build_problem",
    "check_files",
    "compare",
    "default_rules_path",
    "find_teams",
    "identify_fleet",
    "identify_urdf",
    "load_rules",
    "load_team",
    "parse_combination",
    "plan",
    "radar_figure",
    "render_html",
    "render_markdown",
    "robots",
    "run_batch",
    "solve",
    "write_plot",
    "write_report",
    "write_summary",
]


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'solver' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_EXPORTS})
